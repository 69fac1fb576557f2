// Ensemble runs (`isopound run --ensemble N`): N members of one model whose initial states differ
// by a 1 um offset of the base slab; statistics of every peak and the predictability horizon.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "solver/core/analysis.h"
#include "solver/structures/config.h"
#include "solver/structures/job.h"

namespace isopound {

struct EnsembleOptions {
  int members = 8;
  int jobs = 1;                    // worker threads; the results do not depend on it
  double offset = 1e-6;            // m, initial offset of the perturbed level
  double horizon_distance = 1e-3;  // m, two members "differ" once a tracked point is this far
  double spread_warning = 0.05;    // (max - min) / |mean| of a headline peak that warns
};

// Initial displacement (relative to the ground) of member `member` of `members`: zero for
// member 0; for k > 0 the lowest level of the model's first structure (the base slab of an
// isolated building, the first floor of a fixed-base one) is moved by `offset`:
//  - a 3D level (DOFs x, y, theta): along the direction phi_k = 2 pi (k - 1) / (N - 1) from +x,
//    counter-clockwise (theta unchanged);
//  - a 2D level (x only): by +1, -1, +2, -2, ... times `offset` for k = 1, 2, 3, 4, ... (only two
//    directions exist in 2D, so the members also differ in size; equal members would add
//    nothing).
// Every other DOF starts at 0 and every velocity at 0; the stepper starts from equilibrium at u0
// (M a0 = -M iota a_g(0) - K u0 - f(u0)).
Eigen::VectorXd ensemble_initial_displacement(const Model& model, int member, int members,
                                              double offset);

// Statistics over the members of one number: member 0's value, min, mean, max, and the sample
// standard deviation (N - 1 in the denominator; 0 for one member).
struct MemberStatistics {
  double member0 = 0.0, min = 0.0, mean = 0.0, max = 0.0, stddev = 0.0;
  // (max - min) / |mean|; 0 when max - min <= 1e-12 max(1, |mean|) (round-off, in SI units).
  double spread() const;
};
MemberStatistics member_statistics(const std::vector<double>& values);

// What a peak measures, for the console table and the warning.
enum class HeadlinePeak {
  kNone,
  kBaseDisplacement,  // of an isolated structure's base slab (3D: centre of mass and corners)
  kCornerDriftRatio,  // 3D: the corner columns of a storey; 2D: the storey drift ratio
  kContactForce,      // F_N of a contact (2D: an impact element's force)
  kRotation,          // 3D: theta of a level (shown in the table, does not warn)
};

// One peak of summary.json (an object of the shape {value, unit, time_s, positive, negative,
// ...}) over the members: statistics of its value, positive and negative.
struct PeakStatistics {
  std::string
      pointer;        // JSON pointer into summary.json, e.g. "/structures/0/levels/0/displacement"
  std::string label;  // readable path with the labels of list entries, '.'-separated
  std::string name;   // short, for the console: "building/base/corner 1 displacement resultant"
  std::string unit;
  HeadlinePeak headline = HeadlinePeak::kNone;
  MemberStatistics value, positive, negative;
};

// Walks the summaries of all members (same shape: the same model) and returns the statistics of
// every peak, in the order of member 0's summary.json. Throws std::logic_error if a member lacks
// a peak of member 0.
std::vector<PeakStatistics> peak_statistics(const std::vector<nlohmann::json>& summaries);

// What a member's run keeps for the horizon: per output sample its time and the (x, y)
// displacement of every tracked point (3D: every slab corner, the probes "<level>/corner k"; 2D:
// every level, y = 0).
struct EnsembleTrack {
  std::vector<double> times;
  std::vector<double> xy;           // row-major: 2 per point per sample
  std::vector<std::string> points;  // labels
};

// One member: its model (elements in their final state), its analysis (no histories kept: they
// went to `histories` if given and config.output.histories) and its track. Throws what
// run_analysis throws.
// `event_log`: where its contact_events.csv goes ("" = nowhere; the first-impact times are kept
// anyway).
struct EnsembleMember {
  Model model;
  AnalysisResult analysis;
  std::vector<double> first_impact_time;  // as JobResult::first_impact_time
  EnsembleTrack track;
};
EnsembleMember run_ensemble_member(const ModelConfig& config, const GroundMotion& motion,
                                   int member, const EnsembleOptions& options,
                                   HistorySink* histories = nullptr,
                                   std::function<void(double, double)> progress = {},
                                   const std::string& event_log = "");

// The first output time at which two tracks' same point is more than `distance` apart (compared
// sample by sample over the samples all tracks have), else `analysed` with reached = false.
struct Horizon {
  double time = 0.0;  // s
  bool reached = false;
  std::string point;            // the point that first separated
  double max_separation = 0.0;  // m, over all samples, points and pairs
  std::size_t points = 0, samples = 0;
};
Horizon predictability_horizon(const std::vector<const EnsembleTrack*>& tracks, double analysed,
                               double distance);

// A member k > 0 whose analysis diverged (AnalysisError): left out of statistics and horizon.
struct FailedMember {
  int member = 0;
  double time = 0.0;  // s
  std::string error;
};

struct EnsembleResult {
  int members = 0;
  double offset = 0.0;            // m
  double horizon_distance = 0.0;  // m
  // Predictability horizon: the first output time at which two members' tracked points (3D:
  // every slab corner of every structure; 2D: every level) are more than horizon_distance apart;
  // if never, the analysed length and horizon_reached = false.
  double horizon = 0.0;  // s
  bool horizon_reached = false;
  double analysed = 0.0;        // s, the analysed length of the record (incl. extra time)
  std::string horizon_point;    // the point that first separated ("" if none)
  double max_separation = 0.0;  // m, largest distance of two members' points over the run
  std::size_t tracked_points = 0;
  std::size_t samples = 0;            // output samples compared
  std::vector<PeakStatistics> peaks;  // over the members that did not fail
  std::vector<FailedMember> failed;
  JobResult member0;  // member 0 as a normal run (its histories went to the sink given)
};

// Runs the ensemble on `options.jobs` threads. Member 0's history rows go to `member0_histories`
// (if not null and config.output.histories) and its contact events to `member0_event_log` (if
// not ""), other members keep only what the horizon needs; `progress` is called for member 0
// only. Throws what run_job throws for member 0, and for a later member anything but an
// AnalysisError (lowest index first; a diverged member k > 0 goes to EnsembleResult::failed),
// and std::invalid_argument for members < 1 or jobs < 1.
EnsembleResult run_ensemble(const ModelConfig& config, const EnsembleOptions& options,
                            HistorySink* member0_histories = nullptr,
                            std::function<void(double, double)> progress = {},
                            const std::string& member0_event_log = "");

// The "ensemble" block of summary.json (no timing or thread count: identical for any -j).
nlohmann::json ensemble_json(const EnsembleResult& result, const EnsembleOptions& options);
// summary.json of member 0 (report.h) with the "ensemble" block.
void write_summary_with_ensemble(const std::string& path, const ModelConfig& config,
                                 const JobResult& member0, const UnobstructedResult* unobstructed,
                                 const EnsembleResult& result, const EnsembleOptions& options);
// ensemble.csv: one row per peak and field (value, positive, negative).
void write_ensemble_csv(const std::string& path, const EnsembleResult& result);
// The console table of the headline peaks, the horizon, and the warning line if any.
void print_ensemble(std::ostream& out, const EnsembleResult& result,
                    const EnsembleOptions& options);
// The one-line warning when a headline peak (not a rotation) spreads more than
// options.spread_warning; "" if none does.
std::string ensemble_warning(const EnsembleResult& result, const EnsembleOptions& options);

}  // namespace isopound
