// From a ModelConfig to a result: ground motion, model, run options, analysis.
// Keeps parsing out of the physics: it only reads the plain config structs.
#include "solver/structures/job.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "solver/elements/contact.h"
#include "solver/excitation/ground_motion_pair.h"
#include "solver/structures/building2d.h"
#include "solver/structures/building3d.h"
#include "solver/structures/config3d.h"
#include "solver/structures/contact_log.h"
#include "solver/structures/pounding2d.h"
#include "solver/structures/pounding3d.h"
#include "solver/structures/struck_columns3d.h"

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
    add_flexible_walls(model, config);
    add_pounding3d(model, config);
    add_struck_columns3d(model, config);
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

namespace {

// 3D: the same structures without contact elements; per moat wall, the critical gap from the
// slab vertices' closing towards it (pounding3d.h, wall_closings).
UnobstructedResult run_unobstructed3d(const ModelConfig& config, const JobResult& pounding) {
  ModelConfig free_config = config;
  free_config.contact3d.pounding = false;
  free_config.output.histories = false;
  UnobstructedResult out;
  out.job.motion = pounding.motion;
  out.job.motion_peaks = pounding.motion_peaks;
  out.job.model = build_model(free_config);
  const auto dof = [&](const std::string& label) {
    for (int i = 0; i < out.job.model.size(); ++i)
      if (out.job.model.dofs[i].label == label) return i;
    throw std::logic_error("unobstructed run: no DOF '" + label + "'");
  };
  RunOptions options = run_options(free_config);
  const std::vector<WallClosing> walls = wall_closings(config);
  for (const WallClosing& w : walls)
    for (const auto& c : w.coefficients)
      options.tracked.push_back(
          {dof(w.dof_labels[0]), c[0], dof(w.dof_labels[1]), c[1], dof(w.dof_labels[2]), c[2]});
  out.job.analysis = run_analysis(out.job.model, out.job.motion, options);
  out.job.first_impact_time.assign(out.job.model.elements.size(), -1.0);
  std::size_t k = 0;
  for (const WallClosing& w : walls) {
    double closing = 0.0;  // how far the slab's outline crosses the wall's face at rest
    for (const double offset : w.offset)
      closing = std::max(closing, offset + out.job.analysis.tracked[k++].positive);
    out.gaps.push_back({w.label, w.gap, closing});
  }
  return out;
}

}  // namespace

UnobstructedResult run_unobstructed(const ModelConfig& config, const JobResult& pounding) {
  if (!config.structures3d.empty()) return run_unobstructed3d(config, pounding);
  ModelConfig free_config = config;
  free_config.building.walls.clear();
  for (NeighbourConfig& n : free_config.neighbours) {
    n.building.walls.clear();
    n.pounding = false;
  }
  free_config.output.histories = false;
  UnobstructedResult out;
  out.job.motion = pounding.motion;
  out.job.motion_peaks = pounding.motion_peaks;
  out.job.model = build_model(free_config);
  // DOFs are matched by label: wall structures shift the numbering of later structures.
  const auto dof_in_free = [&](int dof) {
    if (dof < 0) return -1;
    const std::string& label = pounding.model.dofs[dof].label;
    for (int i = 0; i < out.job.model.size(); ++i)
      if (out.job.model.dofs[i].label == label) return i;
    return -1;  // a flexible wall: rigid here
  };
  RunOptions options = run_options(free_config);
  for (const auto& element : pounding.model.elements) {
    const auto* contact = dynamic_cast<const Contact1D*>(element.get());
    if (!contact) continue;
    const ContactBody a = contact->body_a(), b = contact->body_b();
    options.tracked.push_back(
        {dof_in_free(a.dof), a.coefficient, dof_in_free(b.dof), b.coefficient});
    out.gaps.push_back({contact->label(), contact->gap(), 0.0});
  }
  out.job.analysis = run_analysis(out.job.model, out.job.motion, options);
  for (std::size_t k = 0; k < out.gaps.size(); ++k)
    out.gaps[k].critical_gap = out.job.analysis.tracked[k].positive;
  return out;
}

void check_step_against_record(const AnalysisConfig& analysis, const GroundMotion& motion) {
  if (analysis.stepping != AnalysisConfig::Stepping::kFixed) return;
  const double ratio = motion.dt / analysis.dt;
  const double whole = std::round(ratio);
  if (whole >= 1.0 && std::abs(ratio - whole) <= 1e-9 * ratio) return;
  std::ostringstream msg;
  msg << "analysis.dt: a fixed step of " << analysis.dt << " s does not divide the record interval "
      << motion.dt << " s (" << motion.name
      << "); steps end on every record sample, so use dt = " << motion.dt << " s / k, e.g. "
      << motion.dt / std::max(1.0, std::ceil(ratio)) << " s";
  throw std::invalid_argument(msg.str());
}

JobResult run_job(const ModelConfig& config, HistorySink* history_sink,
                  std::function<void(double, double)> progress, const std::string& event_log,
                  HistorySink* step_sink, std::optional<GroundMotion> motion) {
  JobResult job;
  job.motion = motion ? std::move(*motion)
                      : load_ground_motion(config.ground_motion, !config.structures3d.empty());
  check_step_against_record(config.analysis, job.motion);
  job.motion_peaks = peaks_of(job.motion);
  job.model = build_model(config);
  RunOptions options = run_options(config);
  options.history_sink = history_sink;
  options.step_sink = step_sink;
  options.progress = std::move(progress);
  ContactEventLog log(job.model, event_log);
  if (!log.empty()) options.observer = &log;
  job.analysis = run_analysis(job.model, job.motion, options);
  log.close();
  job.first_impact_time = log.first_impact_times(job.model);
  return job;
}

}  // namespace isopound
