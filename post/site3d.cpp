// Plan geometry of a 3D model at rest (see site3d.h). Slabs, columns and bearings from the
// buildings (levels bottom to top as levels3d.h orders and raises them, outlines
// placed in W by the building's position and rotation); walls from the solver's site_bodies()
// (solver/structures/pounding3d.h), whose slabs must be these (checked: one geometry).
#include "post/site3d.h"

#include <cmath>
#include <map>
#include <span>
#include <stdexcept>
#include <utility>

#include "geometry/overlap.h"
#include "solver/structures/building3d.h"
#include "solver/structures/bumper_layer3d.h"
#include "solver/structures/config3d.h"
#include "solver/structures/levels3d.h"
#include "solver/structures/pounding3d.h"
#include "solver/structures/struck_columns3d.h"

namespace isopound::post {
namespace {

std::vector<Vec2> outline_in_plan(const Building3DConfig& b, const std::vector<Vec2>& plan_B) {
  std::vector<Vec2> w;
  for (Vec2 p : plan_B) w.push_back(to_plan(b, p));
  // Validated and counter-clockwise.
  if (!is_convex_list(w)) {
    const SimplePolygon outline{std::span<const Vec2>(w.data(), w.size())};
    return {outline.vertices().begin(), outline.vertices().end()};
  }
  const ConvexPolygon polygon{std::span<const Vec2>(w.data(), w.size())};
  return {polygon.vertices().begin(), polygon.vertices().end()};
}

// The two strips of a bumper (rubber, bottomed rubber) glued to body `owner`, keyed as the
// solver labels their contacts: "<face> bumper", "<face> bumper bottomed".
void add_strips(Site3D& site, int owner, const std::string& face, const Building3DConfig& b,
                const Bumper3DConfig& bumper, const BumperStrips& strips) {
  const PlanBody& glued_to = site.bodies.at(static_cast<std::size_t>(owner));
  const double elevation = glued_to.elevation;
  for (const auto& [outline, name] :
       {std::pair{&strips.rubber, std::string(" ") + kBumperLabel},
        std::pair{&strips.bottomed, std::string(" ") + kBottomedLabel}}) {
    PlanBody r;
    r.structure = face + name;
    r.level = "rubber";
    r.role = "rubber";
    r.elevation = elevation;
    r.height = bumper.height;
    r.plan_W = outline_in_plan(b, *outline);
    r.p_WCM = plan_area_properties(r.plan_W).p_WC;
    r.follows = owner;  // moves with it (no DOFs of its own: dof_label stays empty)
    site.bodies.push_back(std::move(r));
  }
}

Vec2 rotate(double angle, Vec2 v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

}  // namespace

int Site3D::find(const std::string& key) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].key() == key) return static_cast<int>(i);
  return -1;
}

const PlanColumn* Site3D::struck(const std::string& label) const {
  for (const PlanColumn& c : columns)
    if (!c.struck.label.empty() && c.struck.label == label) return &c;
  return nullptr;
}

namespace {

// PlanBody::gap_W: every wall and every other structure is moved as a whole by its separation at
// rest from the first structure's slabs (the nearest of them).
void set_rest_gaps(std::vector<PlanBody>& bodies) {
  std::string first;
  for (const PlanBody& b : bodies)
    if (b.role == "slab") {
      first = b.structure;
      break;
    }
  std::map<std::string, std::pair<double, Vec2>> separation;  // per structure: nearest, vector
  for (const PlanBody& a : bodies) {
    if (a.role != "slab" || a.structure != first) continue;
    for (const PlanBody& b : bodies) {
      if (b.structure == first || b.role == "rubber") continue;
      const Separation sep = plan_separation(a.plan_W, b.plan_W);
      auto [it, fresh] = separation.try_emplace(b.structure, sep.distance, sep.n_AB);
      if (!fresh && sep.distance < it->second.first) it->second = {sep.distance, sep.n_AB};
    }
  }
  for (PlanBody& b : bodies)
    if (const auto it = separation.find(b.structure);
        it != separation.end() && it->second.first > 0.0)
      b.gap_W = it->second.first * it->second.second;
}

}  // namespace

Site3D site_geometry(const ModelConfig& config) {
  Site3D site;
  for (const Building3DConfig& b : config.structures3d) {
    const auto add_level = [&](const Diaphragm3DConfig& d, const std::string& level, double z) {
      PlanBody body;
      body.structure = b.name;
      body.level = level;
      body.role = "slab";
      body.elevation = z;
      body.plan_W = outline_in_plan(b, d.plan);
      body.p_WCM = plan_area_properties(body.plan_W).p_WC + rotate(b.rotation, d.eccentricity);
      body.dof_label = b.name + "/" + level;
      site.bodies.push_back(std::move(body));
      return static_cast<int>(site.bodies.size()) - 1;
    };
    // Levels in elevation order (levels3d.h); storey s stands on the level under it.
    const std::vector<Level3D> levels = levels3d(b);
    std::vector<int> body_of;
    for (const Level3D& level : levels)
      body_of.push_back(add_level(*level.diaphragm, level.name, level.elevation));
    if (b.isolated) {
      const int base = body_of[static_cast<std::size_t>(base_level3d(b))];
      const int on = bearing_lower_level3d(b);
      const int lower = on >= 0 ? body_of[static_cast<std::size_t>(on)] : -1;
      const auto add_bearing = [&](const std::string& label, Vec2 p_B) {
        site.bearings.push_back({b.name + "/bearing " + label, to_plan(b, p_B), base, lower});
      };
      if (b.bearings.empty() && !b.storeys.empty())
        for (const Column3DConfig& c :
             b.storeys.at(static_cast<std::size_t>(b.isolation_level)).columns)
          add_bearing(c.label, c.position);
      for (const Bearing3DConfig& c : b.bearings) add_bearing(c.label, c.position);
    }
    for (std::size_t s = 0; s < b.storeys.size(); ++s) {
      const Storey3DConfig& storey = b.storeys[s];
      const int floor = static_cast<int>(s) + 1;
      const int upper = body_of[static_cast<std::size_t>(floor_level3d(b, floor))];
      const int under = storey_lower_level3d(b, floor);
      const int below = under >= 0 ? body_of[static_cast<std::size_t>(under)] : -1;
      for (const Column3DConfig& c : storey.columns)
        site.columns.push_back({b.name + "/story " + std::to_string(floor) + "/" + c.label,
                                to_plan(b, c.position),
                                below,
                                upper,
                                storey.height,
                                {}});
    }
  }
  for (const SiteBody& b : site_bodies(config)) {
    if (b.role != "wall") {
      // The solver's slab: the same outline and level as the one drawn.
      const int i = site.find(b.label());
      if (i < 0 || std::abs(site.bodies[i].elevation - b.elevation) > 1e-9 ||
          site.bodies[i].plan_W.size() !=
              static_cast<std::size_t>(b.convex() ? b.plan_W.size() : b.outline_W.size()))
        throw std::invalid_argument("post: slab '" + b.label() +
                                    "' of the solver's site differs from the drawn one");
      continue;
    }
    const int wall_body = static_cast<int>(site.bodies.size());
    PlanBody w;
    w.structure = b.structure;
    w.level = b.level;
    w.role = "wall";
    w.elevation = b.elevation;
    w.height = b.height;
    w.plan_W.assign(b.plan_W.vertices().begin(), b.plan_W.vertices().end());
    w.p_WCM = area_properties(b.plan_W).p_WC;
    site.bodies.push_back(std::move(w));
    const Building3DConfig& building = config.structures3d.at(static_cast<std::size_t>(b.building));
    if (const auto strips = wall_bumper_strips(building, b.wall_side, b.wall_face))
      add_strips(site, wall_body, b.label(), building, building.walls.bumper, *strips);
  }
  // Rubber on slab faces: on every slab of the building, on each bumpered face.
  for (const Building3DConfig& b : config.structures3d) {
    if (!b.bumper.any() || !(b.bumper.thickness > 0)) continue;
    for (const Level3D& level : levels3d(b)) {
      const std::string label = b.name + "/" + level.name;
      for (const FaceStrips& face : slab_face_strips(level.diaphragm->plan, b.bumper))
        add_strips(site, site.find(label), slab_face_label(label, face.face), b, b.bumper,
                   face.strips);
    }
  }
  // Struck columns: the solver's elements (add_struck_columns3d), one per site of a structure
  // that describes them, none without pounding.
  if (config.contact3d.pounding)
    for (const StruckColumnSite& s : struck_column_sites(config)) {
      const Building3DConfig& b = config.structures3d.at(static_cast<std::size_t>(s.struck));
      if (!b.struck_columns.given) continue;
      const std::string column =
          b.name + "/story " + std::to_string(s.storey) + "/" + s.column_label;
      for (PlanColumn& c : site.columns)
        if (c.label == column)
          c.struck = {s.label(), s.slab_elevation - s.z_lower,
                      site.find(s.striker_name + "/" + s.slab_level), s.section_W};
    }
  set_rest_gaps(site.bodies);
  return site;
}

}  // namespace isopound::post
