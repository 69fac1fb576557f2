// From a ModelConfig to a result: ground motion, model, run options, analysis.
// Keeps parsing out of the physics: it only reads the plain config structs.
#include "solver/structures/job.h"

#include "solver/excitation/ground_motion_pair.h"
#include "solver/structures/building2d.h"
#include "solver/structures/building3d.h"
#include "solver/structures/config3d.h"
#include "solver/structures/pounding2d.h"

namespace isopound {

GroundMotion load_ground_motion(const GroundMotionConfig& config, bool two_components) {
  if (config.components.size() == 2)
    return combine_pair(load_ground_motion(config.components[0]),
                        load_ground_motion(config.components[1]), config.angle);
  if (two_components && config.use_pulse) {
    const GroundMotion l = load_ground_motion(config);
    GroundMotion t = l;
    for (double& a : t.acceleration) a *= config.pulse_transverse_ratio;
    return combine_pair(l, t, config.angle);
  }
  return load_ground_motion(config);
}

GroundMotion load_ground_motion(const GroundMotionConfig& config) {
  if (config.use_pulse) {
    GroundMotion pulse = make_pulse(config.pulse);
    for (double& a : pulse.acceleration) a *= config.read.scale;
    return pulse;
  }
  return read_record(config.record_path, config.read);
}

Model build_model(const ModelConfig& config) {
  if (!config.structures3d.empty()) {
    Model model;
    for (const Building3DConfig& b : config.structures3d) add_building3d(model, b);
    return model;
  }
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
  job.motion = load_ground_motion(config.ground_motion, !config.structures3d.empty());
  job.motion_peaks = peaks_of(job.motion);
  job.model = build_model(config);
  job.analysis = run_analysis(job.model, job.motion, run_options(config));
  return job;
}

}  // namespace isopound
