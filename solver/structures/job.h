// From a ModelConfig to a result: load the ground motion (record or built-in pulse), assemble
// the model, run. The one place the CLI and the studies turn configuration into an analysis.
#pragma once

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
};

// Loads, assembles and runs. Throws RecordError, std::invalid_argument or AnalysisError.
JobResult run_job(const ModelConfig& config);

}  // namespace isopound
