// From a ModelConfig to a result: load the ground motion (record or built-in pulse), assemble
// the model, run. The one place the CLI and the studies turn configuration into an analysis.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solver/core/analysis.h"
#include "solver/core/model.h"
#include "solver/excitation/ground_motion.h"
#include "solver/structures/config.h"

namespace isopound {

// The record named in the config (scaled), or the built-in pulse when none is given.
// A pair (config.components) is rotated into x and y at config.angle.
GroundMotion load_ground_motion(const GroundMotionConfig& config);
// As above; with two_components (a 3D model) and no record, the built-in pulse pair.
GroundMotion load_ground_motion(const GroundMotionConfig& config, bool two_components);

Model build_model(const ModelConfig& config);

RunOptions run_options(const ModelConfig& config);

struct JobResult {
  Model model;  // as assembled (labels, structures), elements in their final state
  GroundMotion motion;
  GroundMotionPeaks motion_peaks;
  AnalysisResult analysis;
  // Per model element: the time of its first counted impact (s), −1 if none or not a polygon
  // contact (3D pounding; the 2D contacts report theirs in their outputs).
  std::vector<double> first_impact_time;
};

// Loads, assembles and runs. Throws RecordError, std::invalid_argument or AnalysisError.
// `history_sink` receives the history rows (else they stay in the result); `progress` see
// RunOptions.
// `event_log`: where contact_events.csv goes for a model with polygon contacts ("" = nowhere).
// `step_sink` receives the row of every accepted step (RunOptions::step_sink).
// `motion`: the config's ground motion when the caller has loaded it already (isopound run reads
// it first to check it), so that the record is not read twice.
JobResult run_job(const ModelConfig& config, HistorySink* history_sink = nullptr,
                  std::function<void(double, double)> progress = {},
                  const std::string& event_log = "", HistorySink* step_sink = nullptr,
                  std::optional<GroundMotion> motion = std::nullopt);

// A contact of the pounding model and how far its gap closes in the unobstructed run.
struct ContactGap {
  std::string label;
  double gap = 0.0;           // m, as modelled
  double critical_gap = 0.0;  // m: the largest closing without contact; a smaller gap pounds
};

struct UnobstructedResult {
  JobResult job;  // the same model without walls, neighbours kept but without contacts
  std::vector<ContactGap> gaps;  // per contact of the pounding model, in its element order
};

// The unobstructed comparison of `pounding` (a run of `config`). A contact's critical gap is the
// peak of its closing coordinate c_a u_a + c_b u_b without any contact: for a wall at level L
// the displacement of level L towards it, for a neighbour the relative displacement of the two
// floors that meet. A flexible wall counts as rigid here (its own motion is not computed).
UnobstructedResult run_unobstructed(const ModelConfig& config, const JobResult& pounding);

// Checks the analysis settings against the record: a fixed step must divide the record interval
// (the stepper never skips samples). Throws std::invalid_argument naming analysis.dt.
void check_step_against_record(const AnalysisConfig& analysis, const GroundMotion& motion);

}  // namespace isopound
