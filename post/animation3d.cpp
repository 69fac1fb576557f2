// Animation frames of 3D runs (see animation3d.h).
#include "post/animation3d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <tuple>

#include "geometry/overlap.h"
#include "geometry/plan_overlap.h"

namespace isopound::post {
namespace {

using P3 = std::array<double, 3>;

// What one cell carries (the cell arrays of a 3D frame).
struct CellValues {
  Block block = Block::kSlab;
  double structure = -1.0;
  double drift_ratio = 0.0;
  double bearing_force = 0.0;
  P3 contact_force{};
  double normal_force = 0.0, tangential_force = 0.0, area = 0.0, penetration = 0.0;
};

class Builder3D {
 public:
  explicit Builder3D(double t) { mesh_.time = t; }

  int point(P3 x, P3 displacement, P3 acceleration, P3 depth_offset = {}, Vec2 gap = {}) {
    mesh_.points.push_back(x);
    displacement_.insert(displacement_.end(), displacement.begin(), displacement.end());
    gap_offset_.insert(gap_offset_.end(), {gap.x, gap.y, 0.0});
    acceleration_.insert(acceleration_.end(), acceleration.begin(), acceleration.end());
    depth_offset_.insert(depth_offset_.end(), depth_offset.begin(), depth_offset.end());
    return static_cast<int>(mesh_.points.size()) - 1;
  }
  void cell(int type, std::vector<int> points, const CellValues& v) {
    mesh_.cells.push_back({type, std::move(points)});
    block_.push_back(static_cast<double>(v.block));
    structure_.push_back(v.structure);
    drift_.push_back(v.drift_ratio);
    bearing_.push_back(v.bearing_force);
    contact_.insert(contact_.end(), v.contact_force.begin(), v.contact_force.end());
    normal_.push_back(v.normal_force);
    tangential_.push_back(v.tangential_force);
    area_.push_back(v.area);
    penetration_.push_back(v.penetration);
  }
  FrameMesh finish() {
    mesh_.point_data = {{"displacement", 3, std::move(displacement_)},
                        {"absolute_acceleration", 3, std::move(acceleration_)},
                        {"contact_depth_offset", 3, std::move(depth_offset_)},
                        {"gap_offset", 3, std::move(gap_offset_)}};
    mesh_.cell_data = {{"block", 1, std::move(block_)},
                       {"structure", 1, std::move(structure_)},
                       {"drift_ratio", 1, std::move(drift_)},
                       {"bearing_force", 1, std::move(bearing_)},
                       {"contact_force", 3, std::move(contact_)},
                       {"normal_force", 1, std::move(normal_)},
                       {"tangential_force", 1, std::move(tangential_)},
                       {"area", 1, std::move(area_)},
                       {"penetration", 1, std::move(penetration_)}};
    return std::move(mesh_);
  }

 private:
  FrameMesh mesh_;
  std::vector<double> displacement_, acceleration_, depth_offset_, gap_offset_, block_, structure_,
      drift_, bearing_, contact_, normal_, tangential_, area_, penetration_;
};

// A body's DOFs at time t (zero for walls and other fixed bodies).
struct BodyState {
  double u = 0, v = 0, theta = 0;        // m, m, rad
  double a_x = 0, a_y = 0, a_theta = 0;  // absolute accelerations, m/s2 and rad/s2
  int structure = -1;
  // The gap offset of the body's points (animation.h): PlanBody::gap_W.
  Vec2 gap;
  // Displacement and absolute acceleration of the plan point p (DOFs at the plan origin).
  Vec2 displacement(Vec2 p) const { return {u - p.y * theta, v + p.x * theta}; }
  Vec2 acceleration(Vec2 p) const { return {a_x - p.y * a_theta, a_y + p.x * a_theta}; }
};

std::vector<BodyState> body_states(const RunData& run, double t) {
  std::vector<BodyState> states(run.site.bodies.size());
  const auto at = [&](int column) { return column >= 0 ? value_at(run, column, t) : 0.0; };
  for (std::size_t s = 0; s < run.structures.size(); ++s)
    for (const Level& l : run.structures[s].levels) {
      if (l.body < 0) continue;
      BodyState& b = states[l.body];
      b = {at(l.u),       at(l.u_y),         at(l.theta),         at(l.a_abs),
           at(l.a_abs_y), at(l.a_abs_theta), static_cast<int>(s), Vec2{}};
    }
  const std::vector<PlanBody>& bodies = run.site.bodies;
  for (std::size_t i = 0; i < bodies.size(); ++i) states[i].gap = bodies[i].gap_W;
  // Rubber strips move with the wall or slab they are glued to (listed after it).
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (const int owner = bodies[i].follows; owner >= 0) states[i] = states[owner];
  return states;
}

// A struck column's node at time t: displacement (the floors' at the column, interpolated at the
// node's height, plus the element's local drift), its twist (the floors', interpolated alike: the
// solver's StruckColumn3D), and an acceleration interpolated between the floors'.
struct NodeState {
  Vec2 d, a;
  double theta = 0.0;
};

NodeState node_state(const RunData& run, const PlanColumn& c, const std::vector<BodyState>& states,
                     double t) {
  const BodyState ground;
  const BodyState& lo = c.lower >= 0 ? states[c.lower] : ground;
  const BodyState& hi = states[c.upper];
  const double r = c.struck.node_height / c.height;
  const auto at = [&](int column) { return column >= 0 ? value_at(run, column, t) : 0.0; };
  NodeState n;
  n.d = (1.0 - r) * lo.displacement(c.p_W) + r * hi.displacement(c.p_W) +
        Vec2{at(c.struck.drift_x), at(c.struck.drift_y)};
  n.a = (1.0 - r) * lo.acceleration(c.p_W) + r * hi.acceleration(c.p_W);
  n.theta = (1.0 - r) * lo.theta + r * hi.theta;
  return n;
}

}  // namespace

FrameMesh animation_frame3d(const RunData& run, double t, const AnimationOptions& o) {
  Builder3D f(t);
  const double S = o.scale, H = o.slab_thickness;
  const std::vector<BodyState> states = body_states(run, t);
  const auto drawn = [&](const BodyState& b, Vec2 p, double z) {
    const Vec2 d = b.displacement(p);
    return P3{p.x + S * d.x, p.y + S * d.y, z};
  };
  const auto point_of = [&](const BodyState& b, Vec2 p, double z) {
    const Vec2 d = b.displacement(p), a = b.acceleration(p);
    return f.point(drawn(b, p, z), {d.x, d.y, 0.0}, {a.x, a.y, 0.0}, {}, b.gap);
  };

  // Slabs and walls: extruded outlines (bottom and top polygons and a quad per side).
  for (std::size_t i = 0; i < run.site.bodies.size(); ++i) {
    const PlanBody& body = run.site.bodies[i];
    const BodyState& st = states[i];
    const bool wall = body.role == "wall", rubber = body.role == "rubber";
    // A slab hangs below its level; a wall's top is flush with the ground, the base slab's level
    // (the moat wall retains the soil around the isolation level): [-height, 0]; a rubber strip
    // hangs its rubber height below the level of what it is glued to.
    const double z1 = body.elevation, z0 = z1 - (wall || rubber ? body.height : H);
    CellValues v;
    v.block = wall ? Block::kWall : rubber ? Block::kRubber : Block::kSlab;
    v.structure = st.structure;
    std::vector<int> bottom, top;
    for (Vec2 p : body.plan_W) bottom.push_back(point_of(st, p, z0));
    for (Vec2 p : body.plan_W) top.push_back(point_of(st, p, z1));
    const std::size_t n = body.plan_W.size();
    f.cell(7, std::vector<int>(bottom.rbegin(), bottom.rend()), v);  // facing down
    f.cell(7, top, v);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t k1 = (k + 1) % n;
      f.cell(9, {bottom[k], bottom[k1], top[k1], top[k]}, v);
    }
  }

  // Columns: from the top of the level below (or the ground) to the underside of the floor; a
  // struck column bent at its node, which the chord between the floors plus the element's local
  // drift places.
  const BodyState ground;
  for (const PlanColumn& c : run.site.columns) {
    const BodyState& lo = c.lower >= 0 ? states[c.lower] : ground;
    const BodyState& hi = states[c.upper];
    const double z_lo = c.lower >= 0 ? run.site.bodies[c.lower].elevation : 0.0;
    const double z_hi = run.site.bodies[c.upper].elevation - H;
    const Vec2 d_lo = lo.displacement(c.p_W), d_hi = hi.displacement(c.p_W);
    CellValues v;
    v.block = Block::kColumn;
    v.structure = hi.structure;
    v.drift_ratio = std::hypot(d_hi.x - d_lo.x, d_hi.y - d_lo.y) / c.height;
    BodyState lo_moved = lo;  // a neighbour's ground end moves with its gap
    lo_moved.gap = hi.gap;
    const int bottom = point_of(lo_moved, c.p_W, z_lo), top = point_of(hi, c.p_W, z_hi);
    if (c.struck.label.empty()) {
      f.cell(3, {bottom, top}, v);
      continue;
    }
    const NodeState n = node_state(run, c, states, t);
    const int node =
        f.point({c.p_W.x + S * n.d.x, c.p_W.y + S * n.d.y, z_lo + c.struck.node_height},
                {n.d.x, n.d.y, 0.0}, {n.a.x, n.a.y, 0.0}, {}, hi.gap);
    f.cell(3, {bottom, node}, v);
    f.cell(3, {node, top}, v);
  }

  // Bearings: from the ground (fixed; drawn 0.6 m tall) or the top of the floor they stand on
  // (isolated above a storey) to the underside of the base slab.
  for (const PlanBearing& b : run.site.bearings) {
    const BodyState& base = states[b.base];
    BodyState lower = b.lower >= 0 ? states[b.lower] : ground;
    lower.gap = base.gap;
    CellValues v;
    v.block = Block::kBearing;
    v.structure = base.structure;
    for (const ElementColumns& e : run.isolators)
      if (e.label == b.label && e.force >= 0) v.bearing_force = value_at(run, e.force, t);
    const double z_top = run.site.bodies[b.base].elevation - H;
    const double z_bottom = b.lower >= 0 ? run.site.bodies[b.lower].elevation : z_top - 0.6;
    f.cell(3, {point_of(lower, b.p_W, z_bottom), point_of(base, b.p_W, z_top)}, v);
  }

  // Contacts in contact at t (by the event log): overlap, and the forces at the centroid.
  double force_ref = 0.0;  // the run's largest logged force: drawn force_length long
  for (const auto& [pair, rows] : run.contact_log.pairs)
    for (const ContactEvent& e : rows)
      force_ref = std::max({force_ref, std::abs(e.normal_force), std::abs(e.tangential_force)});
  for (const auto& [pair, rows] : run.contact_log.pairs) {
    const ContactEvent* e = run.contact_log.state_at(pair, t);
    if (!e || !e->in_contact) continue;
    // A: the slab; B: the other slab or wall, or a struck column's section at its node.
    int ia = -1;
    std::optional<ConvexPolygon> pb;
    std::optional<SimplePolygon> pb_outline;  // B's outline when it is not convex
    if (const PlanColumn* c = run.site.struck(pair)) {
      ia = c->struck.striker;
      const NodeState n = node_state(run, *c, states, t);
      const std::vector<Vec2>& section = c->struck.section_W;
      pb = ConvexPolygon(std::span<const Vec2>(section.data(), section.size()))
               .placed({n.d.x, n.d.y, n.theta}, c->p_W);
    } else {
      std::string a_key, b_key;
      if (!split_pair(pair, a_key, b_key)) continue;
      ia = run.site.find(a_key);
      const int ib = run.site.find(b_key);
      if (ib < 0) continue;
      const BodyState& B = states[ib];
      pb = run.site.bodies[ib].polygon().placed({B.u, B.v, B.theta});
      if (!run.site.bodies[ib].convex())
        pb_outline = run.site.bodies[ib].outline().placed({B.u, B.v, B.theta});
    }
    if (ia < 0) continue;
    const BodyState& A = states[ia];
    const Vec2 n{e->n_x, e->n_y}, tangent{-e->n_y, e->n_x};
    CellValues v;
    v.block = Block::kContact;
    v.structure = A.structure;
    v.normal_force = e->normal_force;
    v.tangential_force = e->tangential_force;
    // The force on B (THEORY-notes, polygon contact): F_N n_AB − F_T t_AB.
    const Vec2 force = e->normal_force * n - e->tangential_force * tangent;
    v.contact_force = {force.x, force.y, 0.0};
    v.area = e->area;
    v.penetration = e->indentation;
    // A point q of the overlap (true coordinates) is drawn where A's drawing puts it.
    const double z = run.site.bodies[ia].elevation + 0.02;  // just above A's top
    const auto on_a = [&](Vec2 q, bool overlap = false) {
      const Vec2 d = A.displacement(q), acc = A.acceleration(q);
      // An overlap vertex's offset from the centroid along n (see animation.h).
      const double along_n = overlap ? (q.x - e->x_C) * n.x + (q.y - e->y_C) * n.y : 0.0;
      return f.point({q.x + (S - 1.0) * d.x, q.y + (S - 1.0) * d.y, z}, {d.x, d.y, 0.0},
                     {acc.x, acc.y, 0.0}, {along_n * n.x, along_n * n.y, 0.0}, A.gap);
    };
    const PlanBody& body_a = run.site.bodies[ia];
    Overlap ov;
    if (body_a.convex() && !pb_outline) {
      ov = overlap_of(body_a.polygon().placed({A.u, A.v, A.theta}), *pb);
    } else {
      // A non-convex plan (plan_overlap.h): the part of the overlap this contact is, the one
      // nearest its logged centroid.
      const PlanOverlap parts =
          plan_overlap(body_a.outline().placed({A.u, A.v, A.theta}),
                       pb_outline ? *pb_outline : SimplePolygon(pb->vertices()));
      double nearest = std::numeric_limits<double>::infinity();
      for (int k = 0; k < parts.count; ++k) {
        const Vec2 d = parts.components[k].p_WC - Vec2{e->x_C, e->y_C};
        if (dot(d, d) < nearest) nearest = dot(d, d), ov = parts.components[k];
      }
    }
    if (ov.area > 0.0 && ov.vertex_count >= 3) {
      std::vector<int> ids;
      for (int k = 0; k < ov.vertex_count; ++k) ids.push_back(on_a(ov.vertices[k], true));
      f.cell(7, ids, v);
    } else {
      f.cell(1, {on_a({e->x_C, e->y_C})}, v);
    }
    // Force vectors on B from the logged centroid, length ∝ force (force_ref: force_length).
    const double per_newton = force_ref > 0.0 ? o.force_length / force_ref : 0.0;
    const Vec2 c{e->x_C, e->y_C};
    for (const auto& [block, dir, size] :
         {std::tuple{Block::kNormalForce, n, e->normal_force},
          std::tuple{Block::kTangentialForce, tangent, -e->tangential_force}}) {
      CellValues fv = v;
      fv.block = block;
      const Vec2 tip = c + (per_newton * size) * dir;
      const int p0 = on_a(c), p1 = on_a(tip);
      f.cell(3, {p0, p1}, fv);
    }
  }
  return f.finish();
}

Figure frame_figure3d(const FrameMesh& mesh, double scale, int width, int height) {
  Figure fig;
  fig.width = width;
  fig.height = height;
  if (mesh.points.empty()) return fig;
  // Eye towards azimuth phi (from +x, counter-clockwise) and elevation el: screen right
  // r = (-sin phi, cos phi, 0), up u = e x r, depth = -p.e (larger: farther). Right-handed, so
  // a face whose outward normal points at the eye is counter-clockwise on screen.
  constexpr double kDeg = std::numbers::pi / 180.0;
  const double phi = -125.0 * kDeg, el = 30.0 * kDeg;
  const P3 e{std::cos(phi) * std::cos(el), std::sin(phi) * std::cos(el), std::sin(el)};
  const P3 r{-std::sin(phi), std::cos(phi), 0.0};
  const P3 u{-std::cos(phi) * std::sin(el), -std::sin(phi) * std::sin(el), std::cos(el)};
  const auto project = [&](const P3& p, double& depth) {
    depth = -(p[0] * e[0] + p[1] * e[1] + p[2] * e[2]);
    return Point2{p[0] * r[0] + p[1] * r[1], p[0] * u[0] + p[1] * u[1] + p[2] * u[2]};
  };
  std::vector<Point2> screen(mesh.points.size());
  std::vector<double> depth(mesh.points.size());
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    screen[i] = project(mesh.points[i], depth[i]);
    x0 = std::min(x0, screen[i].x), x1 = std::max(x1, screen[i].x);
    y0 = std::min(y0, screen[i].y), y1 = std::max(y1, screen[i].y);
  }
  const double margin = 30, top = 70;
  const double s = std::min((width - 2 * margin) / std::max(x1 - x0, 1e-9),
                            (height - margin - top) / std::max(y1 - y0, 1e-9));
  const double ox = (width - s * (x1 - x0)) / 2;
  const auto px = [&](int i) {
    return Point2{ox + (screen[i].x - x0) * s, margin + (screen[i].y - y0) * s};
  };
  const MeshArray* block = nullptr;
  const MeshArray* structure = nullptr;
  for (const MeshArray& a : mesh.cell_data) {
    if (a.name == "block") block = &a;
    if (a.name == "structure") structure = &a;
  }
  static constexpr Rgb kColours[] = {{31, 119, 180}, {90, 90, 90},  {44, 160, 44}, {150, 60, 40},
                                     {214, 39, 40},  {230, 0, 200}, {255, 140, 0}};
  // A layered scene seen from above: what is higher hides what is lower within its outline, so
  // items are drawn by mean height, then back to front. Lines are cut in pieces, each sorted on
  // its own (a column runs the height of its storey).
  struct Item {
    double z, depth;
    std::size_t cell;
    double s0 = 0.0, s1 = 1.0;  // the piece of a line
  };
  constexpr int kPieces = 8;
  std::vector<Item> items;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const std::vector<int>& p = mesh.cells[c].points;
    if (p.size() == 2) {
      for (int k = 0; k < kPieces; ++k) {
        const double s0 = static_cast<double>(k) / kPieces, s1 = (k + 1.0) / kPieces;
        const double mid = 0.5 * (s0 + s1);
        const auto& a = mesh.points[p[0]];
        const auto& b = mesh.points[p[1]];
        items.push_back({a[2] + mid * (b[2] - a[2]),
                         depth[p[0]] + mid * (depth[p[1]] - depth[p[0]]), c, s0, s1});
      }
      continue;
    }
    if (p.size() < 3) continue;
    double d = 0.0, z = 0.0;
    for (int i : p) d += depth[i], z += mesh.points[i][2];
    items.push_back({z / p.size(), d / p.size(), c});
  }
  std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
    return a.z != b.z ? a.z < b.z : a.depth > b.depth;
  });
  for (const Item& item : items) {
    const MeshCell& cell = mesh.cells[item.cell];
    const int b = block ? std::clamp(static_cast<int>(block->values[item.cell]), 0, 6) : 0;
    std::vector<Point2> pts;
    for (int i : cell.points) pts.push_back(px(i));
    if (pts.size() == 2) {
      const Point2 a = pts[0], d{pts[1].x - pts[0].x, pts[1].y - pts[0].y};
      pts = {{a.x + item.s0 * d.x, a.y + item.s0 * d.y},
             {a.x + item.s1 * d.x, a.y + item.s1 * d.y}};
      const double w = (b >= 5 ? 3.0 : 1.6) / 2;
      const double dx = pts[1].x - pts[0].x, dy = pts[1].y - pts[0].y;
      const double len = std::max(std::hypot(dx, dy), 1e-9);
      const Point2 n{-dy / len * w, dx / len * w};
      fig.polygons.push_back({{{pts[0].x - n.x, pts[0].y - n.y},
                               {pts[1].x - n.x, pts[1].y - n.y},
                               {pts[1].x + n.x, pts[1].y + n.y},
                               {pts[0].x + n.x, pts[0].y + n.y}},
                              kColours[b]});
      continue;
    }
    double area2 = 0.0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const Point2& p = pts[k];
      const Point2& q = pts[(k + 1) % pts.size()];
      area2 += p.x * q.y - q.x * p.y;
    }
    if (area2 <= 0.0 && b != 4) continue;  // facing away (closed slabs and walls): hidden
    // Tops and bottoms in the block colour, sides darker (a light from above).
    const double light = cell.vtk_type == 7 ? 1.0 : 0.6;
    // Slabs of the other structures (neighbours) in a paler blue.
    const bool other = b == 0 && structure && structure->values[item.cell] > 0.0;
    const Rgb base = other ? Rgb{130, 160, 200} : kColours[b];
    fig.polygons.push_back(
        {pts,
         {static_cast<unsigned char>(base.r * light), static_cast<unsigned char>(base.g * light),
          static_cast<unsigned char>(base.b * light)}});
  }
  static constexpr const char* kNames[] = {"slab",    "column", "bearing", "wall",
                                           "contact", "F_N",    "F_T"};
  add_frame_caption(fig, mesh.time, scale, kNames, kColours, 105, 44);
  return fig;
}

}  // namespace isopound::post
