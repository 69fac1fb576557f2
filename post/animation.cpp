// Animation frames of 2D runs (see animation.h).
#include "post/animation.h"
#include "post/animation3d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace isopound::post {
namespace {

// Builds one frame: adds points and cells with their array values, in step.
class FrameBuilder {
 public:
  explicit FrameBuilder(double t) { mesh_.time = t; }

  int point(double x, double z, double u, double a) {
    mesh_.points.push_back({x, 0.0, z});
    displacement_.insert(displacement_.end(), {u, 0.0, 0.0});
    acceleration_.insert(acceleration_.end(), {a, 0.0, 0.0});
    depth_offset_.insert(depth_offset_.end(), {0.0, 0.0, 0.0});
    gap_offset_.insert(gap_offset_.end(), {gap_, 0.0, 0.0});
    return static_cast<int>(mesh_.points.size()) - 1;
  }
  // The gap offset (animation.h) of the points added from now on.
  void set_gap_offset(double x) { gap_ = x; }
  void cell(int type, std::vector<int> pts, Block block, double drift = 0.0, double bearing = 0.0,
            double contact_fx = 0.0, double penetration = 0.0) {
    mesh_.cells.push_back({type, std::move(pts)});
    block_.push_back(static_cast<double>(block));
    drift_.push_back(drift);
    bearing_.push_back(bearing);
    contact_.insert(contact_.end(), {contact_fx, 0.0, 0.0});
    penetration_.push_back(penetration);
    normal_.push_back(std::abs(contact_fx));  // 2D contacts are normal only
  }
  // An axis-aligned rectangle in x-z as a quad.
  void rect(double x0, double x1, double z0, double z1, double u, double a, Block block,
            double contact_fx = 0.0, double penetration = 0.0) {
    const int p0 = point(x0, z0, u, a), p1 = point(x1, z0, u, a), p2 = point(x1, z1, u, a),
              p3 = point(x0, z1, u, a);
    cell(9, {p0, p1, p2, p3}, block, 0.0, 0.0, contact_fx, penetration);
    if (block == Block::kContact)  // the overlap's depth runs along x, about its middle
      for (const int p : {p0, p1, p2, p3})
        depth_offset_[3 * p] = mesh_.points[p][0] - 0.5 * (x0 + x1);
  }
  FrameMesh finish() {
    mesh_.point_data = {{"displacement", 3, std::move(displacement_)},
                        {"absolute_acceleration", 3, std::move(acceleration_)},
                        {"contact_depth_offset", 3, std::move(depth_offset_)},
                        {"gap_offset", 3, std::move(gap_offset_)}};
    mesh_.cell_data = {{"block", 1, std::move(block_)},
                       {"drift_ratio", 1, std::move(drift_)},
                       {"bearing_force", 1, std::move(bearing_)},
                       {"contact_force", 3, std::move(contact_)},
                       {"penetration", 1, std::move(penetration_)},
                       {"normal_force", 1, std::move(normal_)}};
    return std::move(mesh_);
  }

 private:
  FrameMesh mesh_;
  double gap_ = 0.0;
  std::vector<double> displacement_, acceleration_, depth_offset_, gap_offset_, block_, drift_,
      bearing_, contact_, penetration_, normal_;
};

// Drawn x of a structure's centre line at rest.
double centre_of(const Structure& s, const AnimationOptions& o) {
  return s.neighbour ? s.side * (o.slab_width + o.scale * s.gap) : 0.0;
}

const Structure* structure_named(const RunData& run, const std::string& name) {
  for (const Structure& s : run.structures)
    if (s.name == name) return &s;
  return nullptr;
}

const Level* level_named(const Structure& s, const std::string& level) {
  for (const Level& l : s.levels)
    if (l.label == s.name + "/" + level) return &l;
  return nullptr;
}

// A struck column line (issue 26, 2D), from summary.json's struck_columns[] and the element's
// label "<A>~<B>/<level> on <B> story <f>": A's level strikes B's storey f at the fraction r of
// its height; the line facing A is drawn bent at its node.
struct StruckLine {
  std::string label;
  const Structure* striker = nullptr;
  const Level* slab = nullptr;
  const Structure* struck = nullptr;
  int upper = -1;  // index of floor f in struck->levels; the storey's lower level is upper - 1
  double r = 0.0;
  int drift = -1;  // history column of the node's drift from the chord
};

std::vector<StruckLine> struck_lines(const RunData& run) {
  std::vector<StruckLine> out;
  if (!run.summary.is_object() || !run.summary.contains("struck_columns")) return out;
  for (const auto& j : run.summary["struck_columns"]) {
    if (!j.contains("label") || !j.contains("struck_at_m") || !j.contains("height_m")) continue;
    StruckLine l;
    l.label = j["label"].get<std::string>();
    const auto tilde = l.label.find('~'), slash = l.label.find('/'), on = l.label.find(" on ");
    const auto story = l.label.rfind(" story ");
    if (tilde == std::string::npos || slash == std::string::npos || on == std::string::npos ||
        story == std::string::npos || !(tilde < slash && slash < on && on < story))
      continue;
    l.striker = structure_named(run, l.label.substr(0, tilde));
    l.struck = structure_named(run, l.label.substr(tilde + 1, slash - tilde - 1));
    if (!l.striker || !l.struck) continue;
    l.slab = level_named(*l.striker, l.label.substr(slash + 1, on - slash - 1));
    const std::string floor = l.struck->name + "/floor " + l.label.substr(story + 7);
    for (std::size_t k = 0; k < l.struck->levels.size(); ++k)
      if (l.struck->levels[k].label == floor) l.upper = static_cast<int>(k);
    const double height = j["height_m"].get<double>();
    l.r = height > 0 ? j["struck_at_m"].get<double>() / height : 0.0;
    l.drift = run.find(l.label, "local_drift");
    if (l.slab && l.upper >= 0) out.push_back(l);
  }
  return out;
}

}  // namespace

FrameMesh animation_frame(const RunData& run, double t, const AnimationOptions& o) {
  if (run.three_d) return animation_frame3d(run, t, o);
  FrameBuilder f(t);
  const double W = o.slab_width, H = o.slab_thickness, S = o.scale;
  const auto u_of = [&](const Level& l) { return value_at(run, l.u, t); };
  const auto a_of = [&](const Level& l) { return l.a_abs >= 0 ? value_at(run, l.a_abs, t) : 0.0; };

  const std::vector<StruckLine> struck = struck_lines(run);
  // The node of a struck line: displacement (the chord at r plus the local drift) and elevation.
  const auto node_of = [&](const StruckLine& l, double& z) {
    const Structure& s = *l.struck;
    const Level& hi = s.levels[static_cast<std::size_t>(l.upper)];
    const double z_lo =
        l.upper > 0 ? s.levels[static_cast<std::size_t>(l.upper) - 1].elevation : 0.0;
    const double u_lo = l.upper > 0 ? u_of(s.levels[static_cast<std::size_t>(l.upper) - 1]) : 0.0;
    z = z_lo + l.r * (hi.elevation - z_lo);
    return (1.0 - l.r) * u_lo + l.r * u_of(hi) + (l.drift >= 0 ? value_at(run, l.drift, t) : 0.0);
  };
  // A column line of storey `upper` of s between points a and b, bent at the struck node when the
  // line faces its striker.
  const auto column_line = [&](const Structure& s, std::size_t upper, double side, int a, int b,
                               double ratio) {
    for (const StruckLine& l : struck) {
      const double towards = centre_of(*l.striker, o) < centre_of(s, o) ? -1.0 : 1.0;
      if (l.struck != &s || l.upper != static_cast<int>(upper) || side * towards < 0) continue;
      double z = 0.0;
      const double u = node_of(l, z);
      const int n = f.point(centre_of(s, o) + S * u + side * o.slab_width, z, u, 0.0);
      f.cell(3, {a, n}, Block::kColumn, ratio);
      f.cell(3, {n, b}, Block::kColumn, ratio);
      return;
    }
    f.cell(3, {a, b}, Block::kColumn, ratio);
  };

  for (const Structure& s : run.structures) {
    const double xc = centre_of(s, o);
    f.set_gap_offset(s.neighbour ? s.side * s.gap : 0.0);  // d(centre_of)/d(scale)
    // Slabs.
    for (const Level& l : s.levels) {
      const double u = u_of(l), x = xc + S * u;
      f.rect(x - W / 2, x + W / 2, l.elevation - H / 2, l.elevation + H / 2, u, a_of(l),
             Block::kSlab);
    }
    // Bearings (base slab at elevation 0 on the ground, drawn 1 m below) or the ground columns.
    const Level& first = s.levels.front();
    const double u0 = u_of(first), x0 = xc + S * u0;
    if (first.elevation == 0.0) {
      double force = 0.0;
      for (const ElementColumns& e : run.isolators)
        if (e.label.rfind(s.name + "/", 0) == 0) force = value_at(run, e.force, t);
      for (double side : {-0.4, 0.4}) {
        const int g = f.point(xc + side * W, -1.0, 0.0, 0.0);
        const int b = f.point(x0 + side * W, -H / 2, u0, a_of(first));
        f.cell(3, {g, b}, Block::kBearing, 0.0, force);
      }
    } else {
      // A building on the ground (a neighbour): its first story's columns stand on the ground.
      for (double side : {-0.45, 0.45}) {
        const int g = f.point(xc + side * W, 0.0, 0.0, 0.0);
        const int b = f.point(x0 + side * W, first.elevation - H / 2, u0, a_of(first));
        column_line(s, 0, side, g, b, u0 / first.elevation);
      }
    }
    // Columns between consecutive levels, with the story drift ratio; bearings under a slab
    // isolated above a storey (docs/isolation-level.md), between it and the floor below.
    for (std::size_t k = 1; k < s.levels.size(); ++k) {
      const Level& lo = s.levels[k - 1];
      const Level& hi = s.levels[k];
      const double ulo = u_of(lo), uhi = u_of(hi);
      if (hi.label == s.name + "/base") {
        double force = 0.0;
        for (const ElementColumns& e : run.isolators)
          if (e.label.rfind(s.name + "/", 0) == 0) force = value_at(run, e.force, t);
        for (double side : {-0.4, 0.4}) {
          const int a = f.point(xc + S * ulo + side * W, lo.elevation + H / 2, ulo, a_of(lo));
          const int b = f.point(xc + S * uhi + side * W, hi.elevation - H / 2, uhi, a_of(hi));
          f.cell(3, {a, b}, Block::kBearing, 0.0, force);
        }
        continue;
      }
      const double ratio = (uhi - ulo) / (hi.elevation - lo.elevation);
      for (double side : {-0.45, 0.45}) {
        const int a = f.point(xc + S * ulo + side * W, lo.elevation + H / 2, ulo, a_of(lo));
        const int b = f.point(xc + S * uhi + side * W, hi.elevation - H / 2, uhi, a_of(hi));
        column_line(s, k, side, a, b, ratio);
      }
    }
  }

  // Moat walls (rigid): 1 m thick, from 1.5 m below to 1 m above the level they face.
  const Structure& main = run.structures.front();
  // A flexible wall (its own DOF) moves with its displacement.
  const auto wall_u = [&](const Wall& w) { return w.u >= 0 ? value_at(run, w.u, t) : 0.0; };
  for (const Wall& w : run.walls) {
    const double u = wall_u(w), face = w.side * (W / 2 + S * w.gap) + S * u;
    f.set_gap_offset(w.side * w.gap);
    f.rect(std::min(face, face + w.side * 1.0), std::max(face, face + w.side * 1.0),
           w.elevation - 1.5, w.elevation + 1.0, u, 0.0, Block::kWall);
  }
  f.set_gap_offset(0.0);  // contact cells move with the slab
  // Contacts in contact: the overlap between the slab edge and the face it hits, with the force
  // on the (first) building as a vector and the penetration.
  for (const ElementColumns& c : run.contacts) {
    const double force = value_at(run, c.force, t);
    const double pen = c.penetration >= 0 ? value_at(run, c.penetration, t) : 0.0;
    if (!(force > 0.0 || pen > 0.0)) continue;
    const auto wall = c.label.find("/wall ");
    if (wall != std::string::npos) {
      for (const Wall& w : run.walls) {
        if (w.label != c.label) continue;
        const Structure* s = structure_named(run, c.label.substr(0, wall));
        const Level* l = nullptr;
        for (const Level& lv : s ? s->levels : main.levels)
          if (lv.elevation == w.elevation) l = &lv;
        if (!l) break;
        const double u = u_of(*l), edge = S * u + w.side * W / 2;
        const double face = w.side * (W / 2 + S * w.gap) + S * wall_u(w);
        f.rect(std::min(edge, face), std::max(edge, face), l->elevation - H / 2,
               l->elevation + H / 2, u, a_of(*l), Block::kContact, -w.side * force, pen);
      }
      continue;
    }
    // A slab against a struck column line: from A's slab edge to the line's face at its node
    // (the face at rest where B's slab edge is: the gap is the same).
    if (const auto l = std::find_if(struck.begin(), struck.end(),
                                    [&](const StruckLine& x) { return x.label == c.label; });
        l != struck.end()) {
      const double side = centre_of(*l->struck, o) < centre_of(*l->striker, o) ? -1.0 : 1.0;
      const double ua = u_of(*l->slab);
      double z = 0.0;
      const double edge_a = centre_of(*l->striker, o) + S * ua + side * W / 2;
      const double face_b = centre_of(*l->struck, o) + S * node_of(*l, z) - side * W / 2;
      f.rect(std::min(edge_a, face_b), std::max(edge_a, face_b), l->slab->elevation - H / 2,
             l->slab->elevation + H / 2, ua, a_of(*l->slab), Block::kContact, -side * force, pen);
      continue;
    }
    // Neighbour contact "<A>~<B>/<level>": overlap of A's and B's facing slab edges.
    const auto tilde = c.label.find('~'), slash = c.label.find('/');
    if (tilde == std::string::npos || slash == std::string::npos || slash < tilde) continue;
    const Structure* a = structure_named(run, c.label.substr(0, tilde));
    const Structure* b = structure_named(run, c.label.substr(tilde + 1, slash - tilde - 1));
    if (!a || !b) continue;
    const std::string level = c.label.substr(slash + 1);
    const Level* la = level_named(*a, level);
    const Level* lb = level_named(*b, level);
    if (!la || !lb) continue;
    const double side = b->side != 0 ? b->side : 1.0;  // where B stands relative to A
    const double ua = u_of(*la), ub = u_of(*lb);
    const double edge_a = centre_of(*a, o) + S * ua + side * W / 2;
    const double edge_b = centre_of(*b, o) + S * ub - side * W / 2;
    f.rect(std::min(edge_a, edge_b), std::max(edge_a, edge_b), la->elevation - H / 2,
           la->elevation + H / 2, ua, a_of(*la), Block::kContact, -side * force, pen);
  }
  return f.finish();
}

Figure frame_figure(const FrameMesh& mesh, double scale, int width, int height) {
  Figure fig;
  fig.width = width;
  fig.height = height;
  double x0 = 1e300, x1 = -1e300, z0 = 1e300, z1 = -1e300;
  for (const auto& p : mesh.points) {
    x0 = std::min(x0, p[0]);
    x1 = std::max(x1, p[0]);
    z0 = std::min(z0, p[2]);
    z1 = std::max(z1, p[2]);
  }
  if (mesh.points.empty()) return fig;
  const double margin = 30, top = 64;
  const double s = std::min((width - 2 * margin) / std::max(x1 - x0, 1e-9),
                            (height - margin - top) / std::max(z1 - z0, 1e-9));
  const double ox = (width - s * (x1 - x0)) / 2;
  const auto at = [&](int i) {
    return Point2{ox + (mesh.points[i][0] - x0) * s, margin + (mesh.points[i][2] - z0) * s};
  };
  const MeshArray* block = nullptr;
  for (const MeshArray& a : mesh.cell_data)
    if (a.name == "block") block = &a;
  static constexpr Rgb kColours[] = {
      {31, 119, 180}, {120, 120, 120}, {44, 160, 44}, {150, 60, 40}, {214, 39, 40}};
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const int b = block ? static_cast<int>(block->values[c]) : 0;
    const Rgb colour = kColours[std::clamp(b, 0, 4)];
    const MeshCell& cell = mesh.cells[c];
    if (cell.vtk_type == 9 && cell.points.size() == 4) {
      FilledPolygon poly{{}, colour};
      for (int i : cell.points) poly.points.push_back(at(i));
      fig.polygons.push_back(poly);
    } else {
      Polyline line{{}, colour, 2.0};
      for (int i : cell.points) line.points.push_back(at(i));
      fig.lines.push_back(line);
    }
  }
  // Ground line.
  fig.lines.push_back(
      {{{margin / 2, margin + (-1.0 - z0) * s}, {width - margin / 2, margin + (-1.0 - z0) * s}},
       {0, 0, 0},
       1.0});
  static constexpr const char* kNames[] = {"slab", "column", "bearing", "wall", "contact"};
  add_frame_caption(fig, mesh.time, scale, kNames, kColours, 110, 40);
  return fig;
}

void add_frame_caption(Figure& fig, double time, double scale, std::span<const char* const> names,
                       std::span<const Rgb> colours, double spacing, double drop) {
  char title[96];
  std::snprintf(title, sizeof title, "t = %.3f s   (displacements × %g)", time, scale);
  fig.texts.push_back({{fig.width / 2.0, fig.height - 12.0},
                       title,
                       14,
                       {0, 0, 0},
                       HAlign::kCentre,
                       VAlign::kTop,
                       0.0,
                       true});
  for (std::size_t b = 0; b < names.size() && b < colours.size(); ++b) {
    const double x = 20 + spacing * static_cast<double>(b), y = fig.height - drop;
    fig.lines.push_back({{{x, y}, {x + 20, y}}, colours[b], 4.0});
    fig.texts.push_back({{x + 26, y}, names[b], 11, {0, 0, 0}, HAlign::kLeft, VAlign::kCentre});
  }
}

std::string pvd_text(const std::vector<double>& times, const std::vector<std::string>& files) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
  char buf[64];
  for (std::size_t i = 0; i < times.size() && i < files.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.17g", times[i]);
    out << "    <DataSet timestep=\"" << buf << "\" group=\"\" part=\"0\" file=\"" << files[i]
        << "\"/>\n";
  }
  out << "  </Collection>\n</VTKFile>\n";
  return out.str();
}

}  // namespace isopound::post
