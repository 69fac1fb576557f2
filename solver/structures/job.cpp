// From a ModelConfig to a result: ground motion, model, run options, analysis.
// Keeps parsing out of the physics: it only reads the plain config structs.
#include "solver/structures/job.h"

#include "solver/structures/building2d.h"
#include "solver/structures/pounding2d.h"

namespace isopound {

GroundMotion load_ground_motion(const GroundMotionConfig& config) {
  if (config.use_pulse) {
    GroundMotion pulse = make_pulse(config.pulse);
    for (double& a : pulse.acceleration) a *= config.read.scale;
    return pulse;
  }
  return read_record(config.record_path, config.read);
}

Model build_model(const ModelConfig& config) {
  Model model = make_model(config.building);
  const double per_contact = config.analysis.steps_per_contact;
  add_walls(model, 0, config.building, per_contact);
  for (const NeighbourConfig& n : config.neighbours)
    add_neighbour(model, 0, config.building, n, per_contact);
  return model;
}

RunOptions run_options(const ModelConfig& config) {
  RunOptions options;
  options.analysis = config.analysis;
  options.output = config.output;
  options.extra_time = config.ground_motion.extra_time;
  return options;
}

JobResult run_job(const ModelConfig& config) {
  JobResult job;
  job.motion = load_ground_motion(config.ground_motion);
  job.motion_peaks = peaks_of(job.motion);
  job.model = build_model(config);
  job.analysis = run_analysis(job.model, job.motion, run_options(config));
  return job;
}

}  // namespace isopound
