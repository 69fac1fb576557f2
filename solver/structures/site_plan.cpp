// The site in plan from a model's 3D structures: slabs, columns, bearings placed in frame W by
// each building's (position, rotation), as the solver's building3d.cpp places them.
#include "solver/structures/site_plan.h"

#include <cmath>
#include <span>

#include "geometry/plan_shape.h"
#include "solver/structures/building3d.h"
#include "solver/structures/config3d.h"
#include "solver/structures/levels3d.h"
#include "solver/structures/pounding3d.h"  // site_bodies(): walls as the solver builds them

namespace isopound {

void column_rectangle(double I11, double I22, double& b, double& h) {
  // (b h^3)(h b^3) = (bh)^4 = 144 I11 I22 and I11 / I22 = (h / b)^2.
  const double area = std::pow(144.0 * I11 * I22, 0.25);
  const double ratio = std::sqrt(I11 / I22);  // h / b
  b = std::sqrt(area / ratio);
  h = area / b;
}

std::vector<Vec2> PlanColumn::outline_W() const {
  const double c = std::cos(orientation), s = std::sin(orientation);
  const Vec2 a1{c, s}, a2{-s, c};
  return {p_W - 0.5 * b * a1 - 0.5 * h * a2, p_W + 0.5 * b * a1 - 0.5 * h * a2,
          p_W + 0.5 * b * a1 + 0.5 * h * a2, p_W - 0.5 * b * a1 + 0.5 * h * a2};
}

namespace {

PlanColumn plan_column(const Building3DConfig& b, const Column3DConfig& c) {
  PlanColumn p;
  p.label = c.label;
  p.p_W = to_plan(b, c.position);
  p.orientation = c.orientation + b.rotation;
  column_rectangle(c.I11, c.I22, p.b, p.h);
  return p;
}

PlanSlab plan_slab(int index, const Building3DConfig& b, const Diaphragm3DConfig& d,
                   std::string level, int level_index, double elevation) {
  PlanSlab s;
  s.structure = index;
  s.name = b.name;
  s.level = std::move(level);
  s.level_index = level_index;
  s.elevation = elevation;
  for (Vec2 p : d.plan) s.plan_W.push_back(to_plan(b, p));
  s.mass = d.mass;
  const AreaProperties a = plan_area_properties(d.plan);
  s.p_WM = to_plan(b, a.p_WC + d.eccentricity);
  return s;
}

}  // namespace

Site site_plan(const ModelConfig& config) {
  Site site;
  for (std::size_t i = 0; i < config.structures3d.size(); ++i) {
    const Building3DConfig& b = config.structures3d[i];
    const int index = static_cast<int>(i);
    const std::vector<Level3D> levels = levels3d(b);
    for (std::size_t l = 0; l < levels.size(); ++l) {
      const Level3D& level = levels[l];
      PlanSlab slab =
          plan_slab(index, b, *level.diaphragm, level.name, static_cast<int>(l), level.elevation);
      // The storey standing on this slab: floor f carries storey f + 1 (none on floor k, which
      // carries the bearings), the base slab storey k + 1.
      const int above = level.floor == 0 ? b.isolation_level + 1 : level.floor + 1;
      if (level.floor == 0) {
        if (b.bearings.empty()) {
          for (const Column3DConfig& c : b.storeys.at(static_cast<std::size_t>(above - 1)).columns)
            slab.bearings.push_back({c.label, to_plan(b, c.position)});
        } else {
          for (const Bearing3DConfig& br : b.bearings)
            slab.bearings.push_back({br.label, to_plan(b, br.position)});
        }
      }
      const bool carries_bearings =
          b.isolated && level.floor != 0 && level.floor == b.isolation_level;
      if (above <= static_cast<int>(b.storeys.size()) && !carries_bearings)
        for (const Column3DConfig& c : b.storeys[static_cast<std::size_t>(above - 1)].columns)
          slab.columns.push_back(plan_column(b, c));
      site.slabs.push_back(slab);
    }
    if (storey_on_ground3d(b, 0)) {
      for (const Column3DConfig& c : b.storeys.front().columns) {
        site.ground_columns.push_back(plan_column(b, c));
        site.ground_columns_structure.push_back(index);
      }
    }
  }
  for (const SiteBody& body : site_bodies(config)) {
    if (body.role != "wall") continue;
    PlanWall w;
    w.name = body.structure;  // "wall east"
    w.side = body.wall_face;
    w.height = body.height;
    w.elevation = body.elevation;
    w.building = body.building;
    for (Vec2 p : body.plan_W.vertices()) w.plan_W.push_back(p);
    const Building3DConfig& b = config.structures3d.at(static_cast<std::size_t>(w.building));
    w.structure = b.name;
    // A polyline's walls declare no gap: theirs is the clearance measured (pounding3d.h).
    w.declared_gap = b.walls.follow == MoatWalls3DConfig::Follow::kPolyline ? -1.0 : body.wall_gap;
    w.along_outline = body.wall_side < 0;
    w.normal_W = body.wall_normal_W;
    site.walls.push_back(w);
  }
  return site;
}

}  // namespace isopound
