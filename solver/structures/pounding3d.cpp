// Site bodies, pair search and contact assembly of 3D pounding (see pounding3d.h).
#include "solver/structures/pounding3d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

#include "geometry/moat.h"
#include "geometry/overlap.h"
#include "geometry/plan_shape.h"
#include "geometry/simple_polygon.h"
#include "solver/elements/plan_pair.h"
#include "solver/elements/polygon_contact.h"
#include "solver/structures/building3d.h"
#include "solver/structures/bumper_layer3d.h"
#include "solver/structures/levels3d.h"

namespace isopound {

namespace {

ConvexPolygon polygon_of(const std::vector<Vec2>& v) {
  return ConvexPolygon(std::span<const Vec2>(v.data(), v.size()));
}

// A non-convex plan as a simple polygon; empty for a convex one (it takes the convex path).
SimplePolygon outline_if_not_convex(const std::vector<Vec2>& plan_W) {
  if (is_convex_list(plan_W)) return {};
  return SimplePolygon(std::span<const Vec2>(plan_W.data(), plan_W.size()));
}

std::vector<Vec2> placed(const Building3DConfig& b, const std::vector<Vec2>& plan_B) {
  std::vector<Vec2> w;
  for (const Vec2& p : plan_B) w.push_back(to_plan(b, p));
  return w;
}

// A direction of the building frame in plan: turned by the building's rotation.
Vec2 direction_W(const Building3DConfig& b, Vec2 d_B) {
  const double c = std::cos(b.rotation), s = std::sin(b.rotation);
  return {c * d_B.x - s * d_B.y, s * d_B.x + c * d_B.y};
}

// The face a wall with outward normal n_B (building frame) faces, by the nearest of eight compass
// points (east = +x, north = +y).
std::string compass_face(Vec2 n_B) {
  static constexpr const char* kNames[8] = {"east", "north-east", "north", "north-west",
                                            "west", "south-west", "south", "south-east"};
  const long k = std::lround(std::atan2(n_B.y, n_B.x) / (std::numbers::pi / 4));
  return kNames[(k % 8 + 8) % 8];
}

// A face's name, numbered when another before it faces the same way ("east 2"; `seen` counts
// the faces named so far per compass point).
std::string numbered_face(const std::string& compass, std::map<std::string, int>& seen) {
  const int k = ++seen[compass];
  if (k == 1) return compass;
  char numbered[32];  // snprintf: GCC 12 misreads a string += as overlapping
  std::snprintf(numbered, sizeof numbered, "%s %d", compass.c_str(), k);
  return numbered;
}

// One moat wall of a building before its placement (building frame).
struct WallShape {
  std::vector<Vec2> outline_B;
  Vec2 n_B;             // unit normal from the slab's face into the wall
  double gap = 0.0;     // m, declared
  double length = 0.0;  // m, along the face (its mass is mass_per_length x length)
  std::string face;     // "east", ...; a second face of the same name "east 2", ...
  int side = -1;        // MoatWalls3DConfig::Side of a box wall, else -1
};

// Every wall of the building, before `sides` selects among the outline's or polyline's.
std::vector<WallShape> all_wall_shapes(const Building3DConfig& b) {
  using Follow = MoatWalls3DConfig::Follow;
  static constexpr Vec2 kAxis[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};  // box sides' normals
  std::vector<WallShape> out;
  const MoatWalls3DConfig& w = b.walls;
  if (w.follow == Follow::kBox) {
    for (int side = 0; side < 4; ++side) {
      if (!w.present[side]) continue;
      std::vector<Vec2> outline = moat_wall_outline(b, side);
      const double length = side <= MoatWalls3DConfig::kWest ? outline[2].y - outline[0].y
                                                             : outline[1].x - outline[0].x;
      out.push_back({std::move(outline), kAxis[side], w.gap[side], length,
                     MoatWalls3DConfig::kSideNames[side], side});
    }
    return out;
  }
  const std::vector<Level3D> levels = levels3d(b);
  const std::vector<Vec2>& plan =
      levels.at(static_cast<std::size_t>(walls_level3d(b))).diaphragm->plan;
  std::vector<std::string> names;
  std::vector<double> gaps;
  std::vector<MoatWall> walls;
  if (w.follow == Follow::kOutline) {
    const SimplePolygon slab{std::span<const Vec2>(plan)};
    // Each run's face name, then its gap (MoatWalls3DConfig::outline_gap) and thickness.
    std::vector<double> thicknesses;
    for (OutlineFace& face : outline_faces(slab)) {
      gaps.push_back(w.outline_gap(face.name));
      thicknesses.push_back(w.thickness_of(face.name));
      names.push_back(std::move(face.name));
    }
    walls = following_moat(slab, gaps, thicknesses, w.extension);
  } else {
    // The walls on the polyline's side away from the slab, listed and named in the order drawn
    // (by the compass point of the normal into each), each its face's thickness (gaps: below).
    const std::span<const Vec2> line(w.polyline);
    const bool walls_left = !lies_left_of(plan, line);
    std::map<std::string, int> faces;  // how many walls face each compass point so far
    std::vector<double> thicknesses;
    for (const auto& [start, end] : polyline_runs(line)) {
      const Vec2 run = end - start;
      const Vec2 n = walls_left ? Vec2{-run.y, run.x} : Vec2{run.y, -run.x};
      names.push_back(numbered_face(compass_face(n), faces));
      thicknesses.push_back(w.thickness_of(names.back()));
    }
    walls = polyline_walls(line, thicknesses, walls_left);
  }
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const MoatWall& m = walls[k];
    const Vec2 run = m.p_WE - m.p_WS;
    const Vec2 d = (1.0 / std::hypot(run.x, run.y)) * run, n{d.y, -d.x};
    const WallExtent along = wall_extent(m.outline.vertices(), n);  // t = d
    // A polyline's wall: its gap is its clearance at rest along n (nothing of the slab in front
    // of it: the distance between them).
    double gap = 0.0;
    if (w.follow == Follow::kPolyline) {
      const NormalClearance c = normal_clearance(plan, m.outline.vertices(), n);
      gap = std::isfinite(c.clearance)
                ? c.clearance
                : plan_separation(std::span<const Vec2>(plan), m.outline.vertices()).distance;
    } else {
      gap = gaps[k];
    }
    // From the vertex of least y (then x), as a box wall's outline starts.
    const std::span<const Vec2> v = m.outline.vertices();
    const auto first = std::min_element(v.begin(), v.end(), starts_face_before);
    std::vector<Vec2> outline(first, v.end());
    outline.insert(outline.end(), v.begin(), first);
    out.push_back({std::move(outline), n, gap, along.hi - along.lo, names[k], -1});
  }
  if (w.follow == Follow::kPolyline) return out;
  // In the order of box walls (east, west, north, south), then the other faces along the
  // outline: a rectangle's following moat is its box walls, element for element.
  const auto rank = [](const WallShape& s) {
    for (int side = 0; side < 4; ++side)
      if (s.face == MoatWalls3DConfig::kSideNames[side]) return side;
    return 4;
  };
  std::stable_sort(out.begin(), out.end(),
                   [&](const WallShape& p, const WallShape& q) { return rank(p) < rank(q); });
  return out;
}

std::vector<WallShape> wall_shapes(const Building3DConfig& b) {
  std::vector<WallShape> out = all_wall_shapes(b);
  if (!b.walls.by_face()) return out;
  std::erase_if(out, [&](const WallShape& s) { return !b.walls.has_outline_wall(s.face); });
  return out;
}

}  // namespace

std::optional<BumperStrips> wall_bumper_strips(const Building3DConfig& b, int side,
                                               const std::string& face) {
  const Bumper3DConfig& bumper = b.walls.bumper;
  if (!bumper.any() || !(bumper.thickness > 0)) return std::nullopt;
  if (side >= 0) {
    if (b.walls.by_face() || !bumper.on[side]) return std::nullopt;
    return bumper_strips(moat_wall_outline(b, side), side, bumper);
  }
  if (!b.walls.by_face() || !bumper.on_outline_face(face)) return std::nullopt;
  for (const WallShape& s : wall_shapes(b))
    if (s.face == face) return face_bumper_strips(s.outline_B, s.n_B, bumper);
  return std::nullopt;
}

std::vector<OutlineFace> outline_faces(const SimplePolygon& plan) {
  std::vector<OutlineFace> out;
  std::map<std::string, int> faces;  // how many runs face each compass point so far
  for (const auto& [start, end] : outline_runs(plan)) {
    const Vec2 run = end - start;
    const Vec2 d = (1.0 / std::hypot(run.x, run.y)) * run;
    out.push_back({numbered_face(compass_face({d.y, -d.x}), faces), start, end});
  }
  return out;
}

std::vector<FaceStrips> slab_face_strips(const std::vector<Vec2>& plan_B,
                                         const Bumper3DConfig& bumper) {
  std::vector<FaceStrips> out;
  if (!bumper.any() || !(bumper.thickness > 0)) return out;
  if (is_convex_list(plan_B)) {  // the box sides (bit for bit as before non-convex plans)
    for (int side = 0; side < 4; ++side) {
      const char* name = MoatWalls3DConfig::kSideNames[side];
      const bool on = bumper.faces.empty() ? bumper.on[side]
                                           : std::find(bumper.faces.begin(), bumper.faces.end(),
                                                       name) != bumper.faces.end();
      if (on) out.push_back({name, slab_bumper_strips(plan_B, side, bumper)});
    }
    return out;
  }
  const std::vector<OutlineFace> faces =
      outline_faces(SimplePolygon(std::span<const Vec2>(plan_B)));
  const int n = static_cast<int>(faces.size());
  const double t = bumper.thickness;
  for (int k = 0; k < n; ++k) {
    const OutlineFace& face = faces[k];
    if (!bumper.on_outline_face(face.name)) continue;
    const Vec2 run = face.end - face.start;
    const double length = std::hypot(run.x, run.y);
    const Vec2 d = (1.0 / length) * run, m{d.y, -d.x};  // m: outward (the slab to the left)
    // The slab as a wall standing behind the face (face_bumper_strips' inner face is the one of
    // least n·x, n = −m): its strips lie outside the slab, the rubber outermost.
    const std::vector<Vec2> wall = {face.start, face.end, face.end - length * m,
                                    face.start - length * m};
    Bumper3DConfig span = bumper;
    // A re-entrant corner at the run's start whose other face has rubber too: the two strips
    // would overlap in a t × t square there; this face's begins t from the corner instead, where
    // the other's ends (the rubber lines the corner once).
    const OutlineFace& before = faces[(k + n - 1) % n];
    const Vec2 in = face.start - before.start;
    if (cross(in, run) < 0 && bumper.on_outline_face(before.name)) {
      // from/to run from the face's end of least y (then x), as face_bumper_strips measures.
      if (starts_face_before(face.start, face.end))
        span.from = std::max(span.from, t);
      else
        span.to = std::min(span.to, length - t);
      if (!(span.from < std::min(span.to, length))) continue;  // nothing left beyond the corner
    }
    out.push_back({face.name, face_bumper_strips(wall, -1.0 * m, span)});
  }
  return out;
}

std::vector<MoatFace> moat_faces(const Building3DConfig& building) {
  Building3DConfig b = building;
  if (b.walls.follow == MoatWalls3DConfig::Follow::kBox)
    b.walls.follow = MoatWalls3DConfig::Follow::kOutline;
  std::vector<MoatFace> faces;
  for (const WallShape& s : all_wall_shapes(b)) faces.push_back({s.face, s.gap});
  return faces;
}

int find_dof(const Model& model, const std::string& label) {
  if (label.empty()) return -1;
  for (int i = 0; i < model.size(); ++i)
    if (model.dofs[i].label == label) return i;
  throw std::logic_error("3D pounding: no DOF labelled '" + label + "'");
}

PolygonContactConfig pair_law(const ModelConfig& config, double mass_a, double mass_b) {
  PolygonContactConfig law = config.contact3d.law;
  law.steps_per_contact = config.analysis.steps_per_contact;
  if (config.contact3d.use_impact_law) {
    ImpactLawConfig c = config.contact3d.impact_law;
    c.mass_1 = mass_a;
    c.mass_2 = mass_b;
    law.normal_law = make_impact_law(c);
  }
  return law;
}

void note_upper_contact(Model& model, int u, int element, bool with_wall) {
  for (StructureInfo& s : model.structures) {
    if (!s.has_base || u < 0 ||
        std::find(s.level_dofs.begin(), s.level_dofs.end(), u) == s.level_dofs.end())
      continue;
    const bool on_base = u == s.level_dofs[s.base_level];
    if (!on_base || (s.base_level > 0 && !with_wall)) s.upper_contact_elements.push_back(element);
  }
}

std::string slab_face_label(const std::string& slab_label, const std::string& face) {
  return slab_label + " " + face;
}

int walls_level3d(const Building3DConfig& b) {
  return b.walls_level >= 0 ? b.walls_level : base_level3d(b);
}

std::vector<Vec2> moat_wall_outline(const Building3DConfig& b, int side) {
  const MoatWalls3DConfig& w = b.walls;
  const std::vector<Level3D> levels = levels3d(b);
  const ConvexPolygon slab =
      convex_hull(levels.at(static_cast<std::size_t>(walls_level3d(b))).diaphragm->plan);
  const Vec2 lo = slab.box_min(), hi = slab.box_max();
  const double g = w.gap[side], t = w.thickness_of(MoatWalls3DConfig::kSideNames[side]),
               e = w.extension;
  double x0, x1, y0, y1;
  switch (side) {
    case MoatWalls3DConfig::kEast:
      x0 = hi.x + g, x1 = x0 + t, y0 = lo.y - e, y1 = hi.y + e;
      break;
    case MoatWalls3DConfig::kWest:
      x1 = lo.x - g, x0 = x1 - t, y0 = lo.y - e, y1 = hi.y + e;
      break;
    case MoatWalls3DConfig::kNorth:
      y0 = hi.y + g, y1 = y0 + t, x0 = lo.x - e, x1 = hi.x + e;
      break;
    default:
      y1 = lo.y - g, y0 = y1 - t, x0 = lo.x - e, x1 = hi.x + e;
      break;
  }
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::vector<SiteBody> site_bodies(const ModelConfig& config) {
  std::vector<SiteBody> out;
  for (std::size_t i = 0; i < config.structures3d.size(); ++i) {
    const Building3DConfig& b = config.structures3d[i];
    const auto add_slab = [&](const std::string& level, double z, const Diaphragm3DConfig& d) {
      const std::string prefix = b.name + "/" + level;
      out.push_back(SiteBody{.structure = b.name,
                             .level = level,
                             .role = "slab",
                             .elevation = z,
                             .height = 0.0,
                             .plan_W = convex_hull(placed(b, d.plan)),
                             .outline_W = outline_if_not_convex(placed(b, d.plan)),
                             .p_WO = {0.0, 0.0},
                             .dof_label_u = prefix + " (x)",
                             .dof_label_v = prefix + " (y)",
                             .dof_label_theta = prefix + " (theta)",
                             .mass = d.mass,
                             .building = static_cast<int>(i),
                             .wall_side = -1,
                             .wall_normal_W = {},
                             .wall_gap = 0.0,
                             .wall_face = "",
                             .wall_length = 0.0});
    };
    const std::vector<Level3D> levels = levels3d(b);
    for (const Level3D& level : levels) add_slab(level.name, level.elevation, *level.diaphragm);
    if (!b.isolated) continue;
    // The walls stand at the level they face (the base slab unless walls.level says otherwise).
    const double wall_elevation = levels.at(static_cast<std::size_t>(walls_level3d(b))).elevation;
    for (WallShape& shape : wall_shapes(b)) {
      SiteBody w{.structure = "wall " + shape.face,
                 .level = "wall",
                 .role = "wall",
                 .elevation = wall_elevation,
                 .height = b.walls.height,
                 .plan_W = polygon_of(placed(b, shape.outline_B)),
                 .outline_W = {},
                 .p_WO = {0.0, 0.0},
                 .dof_label_u = "",
                 .dof_label_v = "",
                 .dof_label_theta = "",
                 .mass = b.walls.mass_per_length * shape.length,
                 .building = static_cast<int>(i),
                 .wall_side = shape.side,
                 .wall_normal_W = direction_W(b, shape.n_B),
                 .wall_gap = shape.gap,
                 .wall_face = shape.face,
                 .wall_length = shape.length};
      // Named by side alone unless several buildings have walls.
      int walled = 0;
      for (const Building3DConfig& other : config.structures3d) walled += other.walls.any() ? 1 : 0;
      if (walled > 1) w.structure = b.name + " " + w.structure;
      if (b.walls.flexible_of(shape.face)) {
        w.dof_label_u = w.structure + " (x)";
        w.dof_label_v = w.structure + " (y)";
        w.dof_label_theta = w.structure + " (theta)";
      }
      out.push_back(std::move(w));
    }
  }
  return out;
}

std::vector<ContactPair3D> contact_pairs3d(const std::vector<SiteBody>& bodies,
                                           const ModelConfig::Contact3D& contact) {
  std::vector<ContactPair3D> pairs;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    for (std::size_t j = i + 1; j < bodies.size(); ++j) {
      const SiteBody& a = bodies[i];
      const SiteBody& b = bodies[j];
      const bool a_wall = a.role == "wall", b_wall = b.role == "wall";
      if (a_wall && b_wall) continue;
      if (a_wall || b_wall) {
        const SiteBody& wall = a_wall ? a : b;
        const SiteBody& slab = a_wall ? b : a;
        // A wall meets the base slab it surrounds (walls of other buildings: their slabs too,
        // when at the base level and near enough).
        if (std::abs(slab.elevation - wall.elevation) > contact.elevation_tolerance) continue;
      } else {
        if (a.structure == b.structure) continue;
        if (std::abs(a.elevation - b.elevation) > contact.elevation_tolerance) continue;
      }
      // Cheap rejection: bounding boxes farther apart than the search distance.
      const double d = contact.search_distance;
      const Vec2 amin = a.plan_W.box_min(), amax = a.plan_W.box_max();
      const Vec2 bmin = b.plan_W.box_min(), bmax = b.plan_W.box_max();
      if (amin.x - bmax.x > d || bmin.x - amax.x > d || amin.y - bmax.y > d || bmin.y - amax.y > d)
        continue;
      const Separation sep = a.convex() && b.convex() ? separation_of(a.plan_W, b.plan_W)
                                                      : plan_separation(a.outline(), b.outline());
      if (sep.distance > d) continue;
      // The slab is body A (walls always B), so n_AB points from the building into the wall.
      ContactPair3D p;
      p.a = static_cast<int>(b_wall || !a_wall ? i : j);
      p.b = static_cast<int>(p.a == static_cast<int>(i) ? j : i);
      p.label = bodies[p.a].label() + "|" + bodies[p.b].label();
      p.separation = sep.distance;
      pairs.push_back(std::move(p));
    }
  }
  return pairs;
}

void add_flexible_walls(Model& model, const ModelConfig& config) {
  for (const SiteBody& w : site_bodies(config)) {
    if (w.role != "wall" || w.dof_label_u.empty()) continue;
    const MoatWalls3DConfig& c = config.structures3d[w.building].walls;
    const double L = w.wall_length;  // along the face (a mitred wall: its longer face)
    const double t = c.thickness_of(w.wall_face), h = c.height, E = c.E,
                 G = E / (2.0 * (1.0 + c.nu));
    // Cantilever of height h: out of plane flexure (I = L t³/12); in plane flexure (I = t L³/12)
    // in series with shear (κ = 5/6); twist as the out-of-plane strips (k_n L²/12) plus
    // Saint-Venant G J/h with J = L t³/3 (THEORY-notes "Flexible moat walls").
    const double k_n = 3.0 * E * (L * t * t * t / 12.0) / (h * h * h);
    const double k_t =
        1.0 / (h * h * h / (3.0 * E * t * L * L * L / 12.0) + h / (5.0 / 6.0 * G * t * L));
    const double k_theta = k_n * L * L / 12.0 + G * (L * t * t * t / 3.0) / h;
    // Normal and tangent of the wall in plan (their signs do not enter n nᵀ and t tᵀ).
    const Vec2 n = w.wall_normal_W, tan{-n.y, n.x};
    const AreaProperties area = area_properties(w.plan_W);
    const Vec2 p = area.p_WC;
    Eigen::Matrix3d T = Eigen::Matrix3d::Identity();  // a point p moves by T q (DOFs at origin)
    T(0, 2) = -p.y;
    T(1, 2) = p.x;
    Eigen::Matrix3d k_c = Eigen::Matrix3d::Zero();
    k_c(0, 0) = k_n * n.x * n.x + k_t * tan.x * tan.x;
    k_c(0, 1) = k_c(1, 0) = k_n * n.x * n.y + k_t * tan.x * tan.y;
    k_c(1, 1) = k_n * n.y * n.y + k_t * tan.y * tan.y;
    k_c(2, 2) = k_theta;
    const Eigen::Matrix3d m_c =
        Eigen::Vector3d(w.mass, w.mass, w.mass * area.radius_of_gyration_sq()).asDiagonal();
    const Eigen::Matrix3d K = T.transpose() * k_c * T, M = T.transpose() * m_c * T;
    const Eigen::Matrix3d C = (2.0 * c.damping_ratio / std::sqrt(k_n / w.mass)) * K;
    const int o = model.size();
    model.grow(o + 3);
    model.mass.block<3, 3>(o, o) = M;
    model.stiffness.block<3, 3>(o, o) = K;
    model.damping.block<3, 3>(o, o) = C;
    model.influence[o] = 1.0;
    model.influence_y[o + 1] = 1.0;
    const double r = std::sqrt(M(2, 2) / w.mass);
    model.dofs.push_back({w.dof_label_u, -1, 0, DofKind::kTranslationX, 1.0});
    model.dofs.push_back({w.dof_label_v, -1, 0, DofKind::kTranslationY, 1.0});
    model.dofs.push_back({w.dof_label_theta, -1, 0, DofKind::kRotation, r});
  }
}

namespace {

// A bumper's two strips (issue 27, bumper_layer3d.h) as two more contacts right after the pair's
// own: between `other` and each strip, carried by `owner`'s DOFs and named after `face`, with laws
// per contact length and the rubber's friction. The concrete contact stays: the strips end at the
// owner's face, so the rubber's δ_N stops at max_strain t where the bottomed strip's overlap
// begins, and that one's at (1 − max_strain) t where the concrete's begins (docs/impact-laws.md,
// "Bumpers on moat walls (3D)").
template <class MakeBody>
void add_strip_contacts(Model& model, const ModelConfig& config, const SiteBody& other,
                        const SiteBody& owner, const std::string& face,
                        const std::vector<Vec2>& rubber_W, const std::vector<Vec2>& bottomed_W,
                        Vec2 compression_W, const Bumper3DConfig& bumper, const MakeBody& body,
                        const PolygonContactConfig& pair_law) {
  const double k_normal = config.contact3d.law.k_normal;
  PolygonContactConfig law = pair_law;
  law.normal_law = nullptr;
  law.mu_static = bumper.mu_static;
  law.mu_kinetic = bumper.mu_kinetic;
  law.strip_compression_W = compression_W;
  const std::shared_ptr<const ImpactLaw> rubber = bumper_rubber_law(bumper, k_normal);
  const std::shared_ptr<const ImpactLaw> bottomed = bumper_bottomed_law(k_normal);
  if (other.convex()) {
    const auto add = [&](const std::vector<Vec2>& outline_W, std::shared_ptr<const ImpactLaw> f,
                         const std::string& name) {
      PolygonBody strip = body(owner);
      strip.shape = polygon_of(outline_W);
      law.length_law = std::move(f);
      model.elements.push_back(std::make_unique<PolygonContact>(
          other.label() + "|" + face + " " + name, body(other), std::move(strip), law));
    };
    add(rubber_W, rubber, kBumperLabel);
    add(bottomed_W, bottomed, kBottomedLabel);
    return;
  }
  // A non-convex slab (L, T, U) against the strips: one contact per part of each strip's overlap
  // (plan_pair.h), slot k of the rubber followed by slot k of the bottomed strip ("... bumper #2",
  // "... bumper bottomed #2"), as report3d pairs them.
  const auto moves = [](const SiteBody& s) { return !s.dof_label_u.empty(); };
  const auto pair_with = [&](const std::vector<Vec2>& outline_W) {
    return std::make_shared<PlanPair>(
        PlanPairBody{other.outline(), other.p_WO, moves(other)},
        PlanPairBody{SimplePolygon(std::span<const Vec2>(outline_W)), owner.p_WO, moves(owner)},
        kPlanContactSlots, law.overlap);
  };
  const std::shared_ptr<PlanPair> rubber_pair = pair_with(rubber_W);
  const std::shared_ptr<PlanPair> bottomed_pair = pair_with(bottomed_W);
  for (int slot = 0; slot < kPlanContactSlots; ++slot) {
    const std::string suffix = slot == 0 ? "" : " #" + std::to_string(slot + 1);
    for (const bool is_rubber : {true, false}) {
      PolygonBody strip = body(owner);
      strip.shape = polygon_of(is_rubber ? rubber_W : bottomed_W);
      law.length_law = is_rubber ? rubber : bottomed;
      model.elements.push_back(std::make_unique<PolygonContact>(
          other.label() + "|" + face + " " + (is_rubber ? kBumperLabel : kBottomedLabel) + suffix,
          body(other), std::move(strip), law, is_rubber ? rubber_pair : bottomed_pair, slot));
    }
  }
}

// The rubber of a bumpered moat wall facing `slab`.
template <class MakeBody>
void add_wall_bumper(Model& model, const ModelConfig& config, const SiteBody& slab,
                     const SiteBody& wall, const MakeBody& body, const PolygonContactConfig& law) {
  if (wall.role != "wall") return;
  const Building3DConfig& b = config.structures3d[wall.building];
  const std::optional<BumperStrips> strips = wall_bumper_strips(b, wall.wall_side, wall.wall_face);
  if (!strips) return;
  add_strip_contacts(model, config, slab, wall, wall.label(), placed(b, strips->rubber),
                     placed(b, strips->bottomed), direction_W(b, strips->n), b.walls.bumper, body,
                     law);
}

// The rubber on the faces of `owner`, a slab of a building with a `bumper:`, towards `other`, a
// slab of another structure at its level: the sides whose strips lie within the search distance.
template <class MakeBody>
void add_slab_bumper(Model& model, const ModelConfig& config, const SiteBody& other,
                     const SiteBody& owner, const MakeBody& body, const PolygonContactConfig& law) {
  if (owner.role != "slab" || other.role != "slab") return;
  const Building3DConfig& b = config.structures3d[owner.building];
  const Bumper3DConfig& bumper = b.bumper;
  if (!bumper.any() || !(bumper.thickness > 0)) return;
  const std::vector<Level3D> levels = levels3d(b);
  const auto level = std::find_if(levels.begin(), levels.end(),
                                  [&](const Level3D& l) { return l.name == owner.level; });
  if (level == levels.end()) throw std::logic_error("3D pounding: no level " + owner.level);
  for (const FaceStrips& face : slab_face_strips(level->diaphragm->plan, bumper)) {
    const std::vector<Vec2> rubber_W = placed(b, face.strips.rubber);
    if (separation_of(polygon_of(rubber_W), other.plan_W).distance >
        config.contact3d.search_distance)
      continue;
    add_strip_contacts(model, config, other, owner, slab_face_label(owner.label(), face.face),
                       rubber_W, placed(b, face.strips.bottomed), direction_W(b, face.strips.n),
                       bumper, body, law);
  }
}

}  // namespace

void add_pounding3d(Model& model, const ModelConfig& config) {
  if (!config.contact3d.pounding) return;
  const std::vector<SiteBody> bodies = site_bodies(config);
  std::vector<std::shared_ptr<SharedPlacement>> placements(bodies.size());
  for (const ContactPair3D& pair : contact_pairs3d(bodies, config.contact3d)) {
    const auto body = [&](const SiteBody& s) {
      return PolygonBody{find_dof(model, s.dof_label_u),
                         find_dof(model, s.dof_label_v),
                         find_dof(model, s.dof_label_theta),
                         s.p_WO,
                         s.plan_W,
                         s.mass};
    };
    const SiteBody& a = bodies[pair.a];
    const SiteBody& b = bodies[pair.b];
    const PolygonContactConfig law = pair_law(config, a.mass, b.mass);
    const int first = static_cast<int>(model.elements.size());
    if (a.convex() && b.convex()) {
      auto contact = std::make_unique<PolygonContact>(pair.label, body(a), body(b), law);
      // A moving body's placement is shared by its convex pairs (the same DOFs, O and outline).
      for (const int side : {0, 1}) {
        const int index = side == 0 ? pair.a : pair.b;
        const PolygonBody p = body(bodies[index]);
        if (p.dof_u < 0 && p.dof_v < 0 && p.dof_theta < 0) continue;
        if (!placements[index]) placements[index] = std::make_shared<SharedPlacement>(p.shape);
        contact->share_placement(side, placements[index]);
      }
      model.elements.push_back(std::move(contact));
    } else {
      // One contact per part of the overlap (plan_pair.h): slots "A|B", "A|B #2", ...
      const auto moves = [](const SiteBody& s) { return !s.dof_label_u.empty(); };
      auto plans = std::make_shared<PlanPair>(PlanPairBody{a.outline(), a.p_WO, moves(a)},
                                              PlanPairBody{b.outline(), b.p_WO, moves(b)},
                                              kPlanContactSlots, law.overlap);
      for (int slot = 0; slot < kPlanContactSlots; ++slot)
        model.elements.push_back(std::make_unique<PolygonContact>(
            slot == 0 ? pair.label : pair.label + " #" + std::to_string(slot + 1), body(a), body(b),
            law, plans, slot));
    }
    add_wall_bumper(model, config, a, b, body, law);
    add_slab_bumper(model, config, a, b, body, law);
    add_slab_bumper(model, config, b, a, body, law);
    // A contact on a level other than an isolated structure's base slab is not part of its base
    // shear (StructureInfo::upper_contact_elements); nor is one on a base slab raised above a
    // storey by anything but its moat walls (a neighbour's floor is no foundation). The pair's
    // rubber strips go with it.
    const bool with_wall = a.role == "wall" || b.role == "wall";
    for (const SiteBody* side : {&a, &b})
      for (int e = first; e < static_cast<int>(model.elements.size()); ++e)
        note_upper_contact(model, find_dof(model, side->dof_label_u), e, with_wall);
  }
}

std::vector<WallClosing> wall_closings(const ModelConfig& config) {
  std::vector<WallClosing> out;
  const std::vector<SiteBody> bodies = site_bodies(config);
  for (const ContactPair3D& pair : contact_pairs3d(bodies, config.contact3d)) {
    const SiteBody& slab = bodies[pair.a];
    const SiteBody& wall = bodies[pair.b];
    if (wall.role != "wall") continue;
    const Vec2 n = wall.wall_normal_W;
    double face = -std::numeric_limits<double>::infinity();
    std::vector<Vec2> corners(slab.plan_W.vertices().begin(), slab.plan_W.vertices().end());
    if (!slab.convex()) {
      // A non-convex slab: the corners in front of the wall (within its length), the face its
      // gap before the wall.
      const Vec2 t{-n.y, n.x};
      const auto [lo, hi, wall_face] = wall_extent(wall.plan_W.vertices(), n);
      corners.clear();
      for (const Vec2& p : slab.outline_W.vertices())
        if (dot(t, p) >= lo && dot(t, p) <= hi && dot(n, p) <= wall_face) corners.push_back(p);
      face = wall_face - wall.wall_gap;
    } else {
      for (const Vec2& p : corners) face = std::max(face, dot(n, p));
    }
    WallClosing w;
    w.label = pair.label;
    w.gap = wall.wall_gap;
    w.dof_labels = {slab.dof_label_u, slab.dof_label_v, slab.dof_label_theta};
    for (const Vec2& p : corners) {
      w.offset.push_back(dot(n, p) - face);
      // n · (u − yθ, v + xθ) = n_x u + n_y v + (x n_y − y n_x) θ
      w.coefficients.push_back({n.x, n.y, p.x * n.y - p.y * n.x});
    }
    out.push_back(std::move(w));
  }
  return out;
}

}  // namespace isopound
