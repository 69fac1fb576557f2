// Pushover of a 2D building: assembly, pattern, control, and the capacity-curve table.
#include "solver/structures/pushover2d.h"

#include <cmath>
#include <stdexcept>

#include "solver/core/analysis.h"
#include "solver/core/pushover.h"
#include "solver/structures/building2d.h"
#include "solver/structures/story_hysteresis.h"

namespace isopound {

BuildingPushoverResult run_pushover2d(const ModelConfig& config,
                                      const BuildingPushoverOptions& options) {
  if (!config.structures3d.empty())
    throw std::invalid_argument("pushover: run_pushover2d is for 2D models (3D: pushover3d.h)");
  if (options.angle != 0.0)
    throw std::invalid_argument(
        "pushover: --angle is for 3D models (a 2D building is pushed in x)");
  BuildingConfig b = config.building;
  b.walls.clear();  // the building alone
  Model model = make_model(b);
  const StructureInfo& info = model.structures[0];
  const int n = model.size();
  const int roof = info.level_dofs.back();
  double height = 0.0;
  for (const FloorConfig& f : b.floors) height += f.height;
  if (b.isolated && b.isolation_level > 0) height += b.isolation_height;  // the isolation storey

  PushoverOptions o;
  o.control = Eigen::VectorXd::Zero(n);
  o.control[roof] = 1.0;
  o.pattern = options.pattern == BuildingPushoverOptions::Pattern::kUniform
                  ? Eigen::VectorXd(model.mass * model.influence)
                  : first_mode_pattern(model, o.control);
  o.target = options.target_drift_ratio * height;
  o.steps = options.steps;
  const std::vector<PushoverStep> curve = run_pushover(model, o);

  BuildingPushoverResult r;
  r.building = b.name;
  r.dimension = 2;
  r.height = height;
  r.columns = {"roof_displacement_m", "roof_drift_ratio", "base_shear_N"};
  const std::vector<Story> stories = stories_of(model);
  for (const Story& st : stories) {
    const std::string name = st.label.substr(st.label.find('/') + 1);  // "story k"
    const std::string key = "story" + name.substr(name.find(' ') + 1);
    r.columns.push_back(key + "_drift_m");
    r.columns.push_back(key + "_drift_ratio");
    r.columns.push_back(key + "_shear_N");
  }
  std::vector<double> yield_drift(stories.size(), 0.0);
  for (std::size_t k = 0; k < stories.size(); ++k)
    if (b.floors[k].hysteresis.yields()) yield_drift[k] = story_yield_drift(b, static_cast<int>(k));
  for (const PushoverStep& s : curve) {
    std::vector<double> row = {s.control, s.control / height, s.lambda * o.pattern.sum()};
    for (std::size_t k = 0; k < stories.size(); ++k) {
      const Story& st = stories[k];
      const double drift = s.u[st.upper] - (st.lower >= 0 ? s.u[st.lower] : 0.0);
      double shear = 0.0;
      for (std::size_t level = static_cast<std::size_t>(info.floor_level(static_cast<int>(k) + 1));
           level < info.level_dofs.size(); ++level)
        shear += s.lambda * o.pattern[info.level_dofs[level]];
      row.insert(row.end(), {drift, drift / st.height, shear});
      if (r.first_yield_row < 0 && yield_drift[k] > 0 &&
          std::abs(drift) >= yield_drift[k] * (1 - 1e-12))
        r.first_yield_row = static_cast<int>(r.rows.size());
    }
    r.rows.push_back(std::move(row));
  }
  mark_capping_point(r);
  return r;
}

}  // namespace isopound
