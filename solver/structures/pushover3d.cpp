// Pushover of a 3D building along an angle: assembly, pattern, control and the table.
#include "solver/structures/pushover3d.h"

#include <cmath>
#include <stdexcept>

#include "solver/core/pushover.h"
#include "solver/structures/building3d.h"
#include "solver/structures/column_element.h"
#include "solver/structures/levels3d.h"

namespace isopound {

namespace {

// Displacement (x, y) of plan point p of the diaphragm whose DOFs (u, v, theta) start at `dof`
// (-1: the ground).
Vec2 point_displacement(const Eigen::VectorXd& q, int dof, Vec2 p) {
  if (dof < 0) return {0.0, 0.0};
  return {q[dof] - p.y * q[dof + 2], q[dof + 1] + p.x * q[dof + 2]};
}

struct YieldingColumn {
  int upper = 0, lower = -1;  // diaphragm DOFs (lower -1: the ground)
  Vec2 position_W;
  double orientation = 0.0;  // rad, section axis 1 from x
  double yield_drift[2] = {0.0, 0.0};
};

}  // namespace

BuildingPushoverResult run_pushover3d(const ModelConfig& config,
                                      const BuildingPushoverOptions& options) {
  if (config.structures3d.empty())
    throw std::invalid_argument("pushover: run_pushover3d is for 3D models (2D: pushover2d.h)");
  const Building3DConfig& b = config.structures3d.front();
  Model model;
  add_building3d(model, b);
  const int n = model.size();
  const int storeys = static_cast<int>(b.storeys.size());
  const double ca = std::cos(options.angle), sa = std::sin(options.angle);
  // Levels in elevation order (levels3d.h); the roof is the last, at the building's height.
  const std::vector<Level3D> levels = levels3d(b);
  const double height = levels.back().elevation;
  // Building DOF of the level over storey s (0-based) and under it (-1: the ground).
  const auto upper_of = [&](int s) { return 3 * floor_level3d(b, s + 1); };
  const auto lower_of = [&](int s) {
    const int l = storey_lower_level3d(b, s + 1);
    return l < 0 ? -1 : 3 * l;
  };

  // Centre of mass of each level in plan.
  std::vector<Vec2> cm_W;
  for (const Level3D& level : levels)
    cm_W.push_back(centre_of_mass(diaphragm_in_plan(b, *level.diaphragm)));
  const int roof = 3 * (static_cast<int>(cm_W.size()) - 1);

  PushoverOptions o;
  o.control = Eigen::VectorXd::Zero(n);
  o.control[roof] = ca;
  o.control[roof + 1] = sa;
  o.control[roof + 2] = -ca * cm_W.back().y + sa * cm_W.back().x;
  const Eigen::VectorXd iota = ca * model.influence + sa * model.influence_y;
  o.pattern = options.pattern == BuildingPushoverOptions::Pattern::kUniform
                  ? Eigen::VectorXd(model.mass * iota)
                  : dominant_mode_pattern(model, iota, o.control);
  o.target = options.target_drift_ratio * height;
  o.steps = options.steps;
  const std::vector<PushoverStep> curve = run_pushover(model, o);

  std::vector<YieldingColumn> yielding;
  for (int s = 0; s < storeys; ++s) {
    const int upper = upper_of(s);
    const auto columns_W = columns_in_plan(b, b.storeys[s].columns);
    for (const Column3DConfig& c : columns_W) {
      if (!c.hysteresis.yields()) continue;
      const ColumnYield y = column_yield(c, b.storeys[s].height);
      yielding.push_back({upper, lower_of(s), c.position, c.orientation, {y.drift[0], y.drift[1]}});
    }
  }

  BuildingPushoverResult r;
  r.building = b.name;
  r.dimension = 3;
  r.height = height;
  r.columns = {"roof_displacement_m", "roof_drift_ratio", "base_shear_N", "base_shear_x_N",
               "base_shear_y_N"};
  for (int s = 1; s <= storeys; ++s)
    for (const char* part : {"_drift_m", "_drift_ratio", "_shear_N", "_shear_x_N", "_shear_y_N"})
      r.columns.push_back("story" + std::to_string(s) + part);
  for (const PushoverStep& step : curve) {
    // Loads per level in x and y: lambda P over the DOFs (u, v) of each level.
    const Eigen::VectorXd load = step.lambda * o.pattern;
    double base_x = 0.0, base_y = 0.0;
    for (int i = 0; i < n; i += 3) {
      base_x += load[i];
      base_y += load[i + 1];
    }
    std::vector<double> row = {step.control, step.control / height, ca * base_x + sa * base_y,
                               base_x, base_y};
    for (int s = 0; s < storeys; ++s) {
      const int upper = upper_of(s);
      const int lower = lower_of(s);
      const Vec2 p = cm_W[static_cast<std::size_t>(upper / 3)];
      const Vec2 du = point_displacement(step.u, upper, p);
      const Vec2 dl = point_displacement(step.u, lower, p);
      const double drift = ca * (du.x - dl.x) + sa * (du.y - dl.y);
      double vx = 0.0, vy = 0.0;
      for (int i = upper; i < n; i += 3) {
        vx += load[i];
        vy += load[i + 1];
      }
      row.insert(row.end(), {drift, drift / b.storeys[s].height, ca * vx + sa * vy, vx, vy});
    }
    if (r.first_yield_row < 0)
      for (const YieldingColumn& c : yielding) {
        const Vec2 du = point_displacement(step.u, c.upper, c.position_W);
        const Vec2 dl = point_displacement(step.u, c.lower, c.position_W);
        const double dx = du.x - dl.x, dy = du.y - dl.y;
        const double co = std::cos(c.orientation), so = std::sin(c.orientation);
        const double d1 = (co * dx + so * dy) / c.yield_drift[0];
        const double d2 = (-so * dx + co * dy) / c.yield_drift[1];
        if (std::hypot(d1, d2) >= 1 - 1e-12) {
          r.first_yield_row = static_cast<int>(r.rows.size());
          break;
        }
      }
    r.rows.push_back(std::move(row));
  }
  mark_capping_point(r);
  return r;
}

}  // namespace isopound
