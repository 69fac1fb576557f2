// The 3D model format (README "3D buildings"): buildings with a column grid or listed columns,
// storeys (short form or list), base slab, bearings, damping; record pairs at an angle.
#include "solver/io/model_input3d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <optional>

#include <limits>

#include "geometry/plan_shape.h"
#include "geometry/simple_polygon.h"
#include "solver/io/bumper_input.h"
#include "solver/io/hysteresis_input.h"
#include "solver/io/isolator_input.h"
#include "solver/io/model_input.h"
#include "solver/io/struck_columns_input.h"
#include "solver/structures/building3d.h"
#include "solver/structures/pounding3d.h"
#include "solver/structures/rayleigh_modes.h"

namespace isopound {
namespace {

// A side name: east, west, north or south (MoatWalls3DConfig::Side).
int read_side(const InputNode& n) {
  using W = MoatWalls3DConfig;
  return n.choice<int>(
      {{"east", W::kEast}, {"west", W::kWest}, {"north", W::kNorth}, {"south", W::kSouth}});
}

constexpr Dimension kAreaMoment{4, 0, 0};  // m^4
constexpr Dimension kMassMoment{2, 1, 0};  // kg m^2
constexpr int kMaxStoreys = 200;
constexpr int kMaxGridLines = 26;  // column lines named A..Z along x

Vec2 read_point(const InputNode& node, const Dimension& d = dim::kLength) {
  if (!node.is_sequence() || node.elements().size() != 2)
    node.fail("expected [x, y], e.g. [2.75 m, -2.75 m]; got " + node.kind());
  const std::vector<InputNode> e = node.elements();
  return {e[0].quantity(d), e[1].quantity(d)};
}

// plan: {rectangle: [Lx, Ly]} (centred on the building frame's origin) or {polygon: [[x, y], ..]}.
std::vector<Vec2> read_plan(const InputNode& node) {
  node.expect_keys({"rectangle", "polygon"});
  const auto rect = node.find("rectangle");
  const auto poly = node.find("polygon");
  if (rect && poly) poly->fail("give either rectangle or polygon, not both");
  if (rect) {
    const std::vector<InputNode> e = rect->elements();
    if (e.size() != 2) rect->fail("expected [Lx, Ly]");
    const double lx = e[0].quantity(dim::kLength, Bound::kPositive);
    const double ly = e[1].quantity(dim::kLength, Bound::kPositive);
    return {{-lx / 2, -ly / 2}, {lx / 2, -ly / 2}, {lx / 2, ly / 2}, {-lx / 2, ly / 2}};
  }
  if (!poly) node.fail("expected rectangle: [Lx, Ly] or polygon: [[x, y], ...]");
  if (!poly->is_sequence()) poly->fail("expected a list of vertices [[x, y], ...]");
  std::vector<Vec2> v;
  for (const InputNode& p : poly->elements()) v.push_back(read_point(p));
  const std::vector<InputNode> points = poly->elements();
  std::optional<SimplePolygon> outline;
  try {
    outline.emplace(std::span<const Vec2>(v.data(), v.size()));
  } catch (const InvalidPolygon& e) {
    if (e.vertex() >= 0 && e.vertex() < static_cast<int>(v.size()))
      points[e.vertex()].fail(std::string("not a simple polygon: ") + e.what());
    poly->fail(std::string("not a simple polygon: ") + e.what());
  }
  // Non-convex plans (L, T, U) are taken as written (collinear vertices kept: the outline's
  // pieces drop them).
  if (!outline->convex()) return v;
  // Collinear vertices, as drawings have them, are not corners: dropped, the others kept in the
  // list's order (a list without them is returned as given).
  const std::span<const Vec2> corners = outline->pieces()[0].vertices();
  if (corners.size() == v.size()) return v;
  std::vector<Vec2> kept;
  for (const Vec2& p : v)
    if (std::find_if(corners.begin(), corners.end(),
                     [&](const Vec2& c) { return c.x == p.x && c.y == p.y; }) != corners.end())
      kept.push_back(p);
  return kept;
}

// Column section and material: defaults from the building's `columns:` map, overridden per item.
struct ColumnProps {
  std::optional<double> b, h, I11, I22, J, E, G, nu;
  double orientation = 0.0;
  ColumnHysteresisConfig hysteresis;  // a `hysteresis:` map replaces the default's whole
};

const std::vector<std::string_view> kColumnPropKeys = {
    "section", "I11", "I22", "J", "orientation", "E", "G", "nu", "hysteresis"};

constexpr Dimension kMoment{2, 1, -2};  // N m

// hysteresis: {model: bilinear | bouc_wen | elastic, yield_drift_ratio | yield_moment,
// post_yield_ratio, the law's shape (hysteresis_input.h)}: column_element.h. Keys the model does
// not use are refused.
ColumnHysteresisConfig read_column_hysteresis(const InputNode& node) {
  using M = HysteresisModel;
  ColumnHysteresisConfig c;
  if (!node.is_map()) node.fail("expected a map {model: bilinear | bouc_wen | elastic, ...}");
  node.expect_keys(
      with_hysteresis_keys({"model", "yield_drift_ratio", "yield_moment", "post_yield_ratio"}));
  // No peak_oriented: it has no biaxial form.
  c.law.model = read_hysteresis_model(node, {M::kBilinear, M::kBoucWen, M::kElastic});
  if (!c.yields()) return c;
  const auto ratio = node.find("yield_drift_ratio");
  const auto moment = node.find("yield_moment");
  if (ratio && moment)
    node.fail_at_key("yield_moment", "give either yield_drift_ratio or yield_moment, not both");
  if (!ratio && !moment)
    node.fail_at_key("yield_drift_ratio",
                     "a yielding column needs yield_drift_ratio (d_y = ratio x storey height) or "
                     "yield_moment (V_y = 2 M_y / h)");
  if (ratio) c.yield_drift_ratio = ratio->number(Bound::kPositive);
  if (moment) c.yield_moment = moment->quantity(kMoment, Bound::kPositive);
  c.post_yield_ratio = read_post_yield_ratio(node);
  read_hysteresis_shape(node, c.law);
  return c;
}

void read_column_props(const InputNode& node, ColumnProps& p) {
  if (const auto s = node.find("section")) {
    const std::vector<InputNode> e = s->elements();
    if (!s->is_sequence() || e.size() != 2) s->fail("expected [b, h], e.g. [45 cm, 45 cm]");
    p.b = e[0].quantity(dim::kLength, Bound::kPositive);
    p.h = e[1].quantity(dim::kLength, Bound::kPositive);
  }
  for (auto [key, out] : {std::pair{"I11", &p.I11}, {"I22", &p.I22}, {"J", &p.J}})
    if (const auto n = node.find(key)) *out = n->quantity(kAreaMoment, Bound::kPositive);
  node.read_angle("orientation", p.orientation);
  if (const auto n = node.find("E")) p.E = n->quantity(dim::kPressure, Bound::kPositive);
  if (const auto n = node.find("G")) p.G = n->quantity(dim::kPressure, Bound::kPositive);
  if (const auto n = node.find("nu")) {
    p.nu = n->number(Bound::kNonNegative);
    if (*p.nu >= 0.5) n->fail("Poisson's ratio must be in [0, 0.5)");
  }
  if (p.G && p.nu) node.fail_at_key("nu", "give either G or nu, not both");
  if (const auto n = node.find("hysteresis")) p.hysteresis = read_column_hysteresis(*n);
}

// Rectangle b (along axis 1) x h (along axis 2): I11 = b h^3/12, I22 = h b^3/12 and Saint-Venant
// J = a c^3 (1/3 - 0.21 (c/a)(1 - c^4/(12 a^4))), a >= c the longer and shorter sides.
Column3DConfig make_column(const ColumnProps& p, const InputNode& where) {
  Column3DConfig c;
  c.orientation = p.orientation;
  c.hysteresis = p.hysteresis;
  if (p.b) {
    const double b = *p.b, h = *p.h, a = std::max(b, h), s = std::min(b, h);
    c.I11 = b * h * h * h / 12.0;
    c.I22 = h * b * b * b / 12.0;
    c.J = a * s * s * s * (1.0 / 3.0 - 0.21 * (s / a) * (1.0 - std::pow(s / a, 4) / 12.0));
  }
  if (p.I11) c.I11 = *p.I11;
  if (p.I22) c.I22 = *p.I22;
  if (p.J) c.J = *p.J;
  if (!(c.I11 > 0 && c.I22 > 0 && c.J > 0))
    where.fail("a column needs its section: section: [b, h] or I11, I22 and J");
  if (!p.E) where.fail("a column needs E (Young's modulus)");
  c.E = *p.E;
  if (p.G)
    c.G = *p.G;
  else if (p.nu)
    c.G = c.E / (2.0 * (1.0 + *p.nu));
  else
    where.fail("a column needs G or nu");
  return c;
}

// Built by append: GCC 12 warns (-Wrestrict, a false positive) on "x" + std::to_string(n).
std::string numbered(char prefix, std::size_t n) {
  std::string s(1, prefix);
  s.append(std::to_string(n));
  return s;
}

std::string grid_label(int ix, int iy) {
  return numbered(static_cast<char>('A' + ix), static_cast<std::size_t>(iy + 1));
}

// grid: {bays_x: [...], bays_y: [...], origin: [x, y]}: columns at every intersection, named
// A1.. (letter along x, number along y); origin = position of A1 (default: grid centred).
std::vector<std::pair<std::string, Vec2>> read_grid(const InputNode& node) {
  node.expect_keys({"bays_x", "bays_y", "origin"});
  std::vector<double> lines[2];
  const char* keys[2] = {"bays_x", "bays_y"};
  for (int d = 0; d < 2; ++d) {
    const InputNode bays = node.required(keys[d]);
    if (!bays.is_sequence() || bays.elements().empty())
      bays.fail("expected a list of bay widths, e.g. [5.5 m, 5.5 m, 5.5 m]");
    if (bays.elements().size() + 1 > kMaxGridLines) bays.fail("at most 25 bays");
    lines[d].push_back(0.0);
    for (const InputNode& b : bays.elements())
      lines[d].push_back(lines[d].back() + b.quantity(dim::kLength, Bound::kPositive));
  }
  Vec2 origin{-lines[0].back() / 2, -lines[1].back() / 2};
  if (const auto o = node.find("origin")) origin = read_point(*o);
  std::vector<std::pair<std::string, Vec2>> out;
  for (std::size_t iy = 0; iy < lines[1].size(); ++iy)
    for (std::size_t ix = 0; ix < lines[0].size(); ++ix)
      out.push_back({grid_label(static_cast<int>(ix), static_cast<int>(iy)),
                     {origin.x + lines[0][ix], origin.y + lines[1][iy]}});
  return out;
}

void read_diaphragm_extras(const InputNode& node, Diaphragm3DConfig& d) {
  if (const auto e = node.find("eccentricity")) d.eccentricity = read_point(*e);
  node.read_quantity("polar_moment", kMassMoment, Bound::kPositive, d.polar_moment);
  if (const auto p = node.find("plan")) d.plan = read_plan(*p);
}

BearingConfig read_bearing_law(const InputNode& node) {
  using M = BearingConfig::Model;
  node.expect_keys(isolator_keys());
  BearingConfig c;
  node.read_choice<M>("model",
                      {{"bouc_wen", M::kBoucWenCoupled},
                       {"bouc_wen_uncoupled", M::kBoucWenUncoupled},
                       {"bilinear", M::kBilinear},
                       {"linear", M::kLinear},
                       {"friction_pendulum", M::kFrictionPendulum}},
                      c.model);
  // Only the keys of the chosen law are read; any other is refused as unused (the key rule).
  node.read_quantity("carried_mass", dim::kMass, Bound::kPositive, c.carried_mass);
  read_isolator_keys(node, c.model == M::kFrictionPendulum, bearing_hysteresis_law(c).model, c,
                     [] {});
  return c;
}

void read_damping3d(const InputNode& node, bool isolated, Damping3DConfig& d) {
  using T = Damping3DConfig::Type;
  node.expect_keys({"type", "ratios", "modes", "bearing_stiffness", "isolation"});
  if (const auto t = node.find("type"))
    d.type = t->choice<T>(
        {{"rayleigh", T::kRayleigh}, {"non_classical", T::kNonClassical}, {"none", T::kNone}});
  if (d.type == T::kNone)
    for (const char* key : {"ratios", "modes", "bearing_stiffness", "isolation"})
      if (node.has(key)) node.find(key)->fail("has no effect with type: none");
  if (const auto r = node.find("ratios")) {
    const std::vector<InputNode> e = r->elements();
    if (!r->is_sequence() || e.size() != 2) r->fail("expected two ratios, e.g. [5 %, 2 %]");
    d.ratio_a = e[0].number(Bound::kFraction);
    d.ratio_b = e[1].number(Bound::kFraction);
  }
  if (const auto m = node.find("modes")) {
    const std::vector<InputNode> e = m->elements();
    if (!m->is_sequence() || e.size() != 2) m->fail("expected two mode numbers, e.g. [1, 4]");
    d.mode_a = e[0].integer(1, 10000);
    d.mode_b = e[1].integer(1, 10000);
    if (d.mode_a == d.mode_b) m->fail("the two Rayleigh modes must differ");
  }
  if (const auto k = node.find("bearing_stiffness")) {
    if (d.type != T::kRayleigh || !isolated)
      k->fail("only used with type: rayleigh on an isolated building");
    d.initial_bearing_stiffness = k->choice<bool>({{"post_yield", false}, {"initial", true}});
  }
  if (const auto i = node.find("isolation")) {
    if (d.type != T::kNonClassical || !isolated)
      i->fail("only used with type: non_classical on an isolated building");
    d.isolation_ratio = i->number(Bound::kFraction);
  }
}

// walls: {follow: box | outline | polyline, polyline: [[x, y], ...], sides: all | [east, ...],
// gap: 20 cm | {east: .., west: ..}, thickness, height, extension, mass_per_length, bumper}
MoatWalls3DConfig read_walls3d(const InputNode& node) {
  using W = MoatWalls3DConfig;
  node.expect_keys({"follow", "polyline", "sides", "gap", "thickness", "height", "extension",
                    "mass_per_length", "model", "E", "nu", "damping", "bumper", "level"});
  W w;
  if (node.has("polyline") && !node.has("follow")) {
    w.follow = W::Follow::kPolyline;  // the walls stand where they are drawn
    node.note_default("follow", "polyline (walls.polyline is given)");
  } else {
    node.read_choice<W::Follow>("follow",
                                {{"box", W::Follow::kBox},
                                 {"outline", W::Follow::kOutline},
                                 {"polyline", W::Follow::kPolyline}},
                                w.follow);
  }
  if (w.follow == W::Follow::kPolyline) {
    // Walls along a polyline of their own (building frame): each wall's gap is its clearance at
    // rest, measured (isopound-pre lists it); the polyline's ends are where it is drawn.
    const InputNode line = node.required("polyline");
    if (!line.is_sequence() || line.elements().size() < 2)
      line.fail("expected a list of at least two [x, y] points (the walls' faces)");
    for (const InputNode& p : line.elements()) w.polyline.push_back(read_point(p));
    for (const char* key : {"gap", "extension"})
      if (node.has(key))
        node.fail_at_key(key, std::string("not used by walls along a polyline: ") +
                                  (key == std::string("gap")
                                       ? "each wall's gap is its clearance from the slab at rest, "
                                         "measured (isopound-pre lists them)"
                                       : "its walls end where the polyline ends"));
    w.present = {true, true, true, true};
  } else if (node.has("polyline")) {
    node.fail_at_key("polyline", "only used with follow: polyline (walls along it)");
  }
  if (w.by_face()) {
    // sides: all, or the faces of a partial moat (checked against the outline's or polyline's
    // faces with the plan, check_moat_faces).
    if (const auto sides = node.find("sides")) {
      if (sides->is_sequence()) {
        w.outline_sides = read_face_names(*sides, "no sides: give all or e.g. [east, north-east]");
      } else {
        sides->choice<int>({{"all", 0}});
      }
    } else {
      node.note_default("sides", "all");
    }
  }
  if (w.follow == W::Follow::kOutline) {
    // One wall per straight run of the slab's outline (geometry/moat.h), at the one gap or a gap
    // per face, rigid or flexible (model), with bumpers by face (bumper.sides).
    // gap: one length for every wall, or a map by face (checked against the outline's faces
    // with the plan, check_moat_faces).
    const InputNode gap = node.required("gap");
    if (gap.is_map()) {
      for (const auto& entry : gap.yaml()) {
        const std::string face = entry.first.as<std::string>();
        w.outline_gaps[face] = gap.required(face).quantity(dim::kLength, Bound::kNonNegative);
      }
      if (w.outline_gaps.empty()) gap.fail("no gaps: give a length or e.g. {east: 20 cm, ...}");
    } else {
      const double g = gap.quantity(dim::kLength, Bound::kNonNegative);
      w.gap = {g, g, g, g};
    }
    w.present = {true, true, true, true};
  } else if (w.follow == W::Follow::kBox) {
    if (const auto sides = node.find("sides")) {
      if (sides->is_sequence()) {
        if (sides->elements().empty()) sides->fail("no sides: give all or e.g. [east, west]");
        for (const InputNode& s : sides->elements()) {
          const int k = read_side(s);
          if (w.present[k]) s.fail("side listed twice");
          w.present[k] = true;
        }
      } else {
        sides->choice<int>({{"all", 0}});
        w.present = {true, true, true, true};
      }
    } else {
      node.note_default("sides", "all");
      w.present = {true, true, true, true};
    }
    const InputNode gap = node.required("gap");
    if (gap.is_map()) {
      gap.expect_keys({"east", "west", "north", "south"});
      for (int k = 0; k < 4; ++k) {
        const auto g = gap.find(W::kSideNames[k]);
        if (w.present[k] && !g)
          gap.fail(std::string("no gap for the ") + W::kSideNames[k] + " wall");
        if (g && !w.present[k])
          g->fail(std::string("there is no ") + W::kSideNames[k] + " wall (see sides)");
        if (g) w.gap[k] = g->quantity(dim::kLength, Bound::kNonNegative);
      }
    } else {
      const double g = gap.quantity(dim::kLength, Bound::kNonNegative);
      w.gap = {g, g, g, g};
    }
  }
  // thickness and model: one for every wall, or a map by face (box walls by side; checked here
  // for box walls, with the plan for walls by face: check_moat_faces).
  if (const auto th = node.find("thickness"); th && th->is_map()) {
    for (const auto& entry : th->yaml()) {
      const std::string face = entry.first.as<std::string>();
      w.thicknesses[face] = th->required(face).quantity(dim::kLength, Bound::kPositive);
    }
    if (w.thicknesses.empty()) th->fail("no thicknesses: give a length or e.g. {east: 1 m, ...}");
  } else {
    node.read_quantity("thickness", dim::kLength, Bound::kPositive, w.thickness);
  }
  node.read_quantity("height", dim::kLength, Bound::kPositive, w.height);
  if (w.follow != W::Follow::kPolyline)
    node.read_quantity("extension", dim::kLength, Bound::kNonNegative, w.extension);
  node.read_quantity("mass_per_length", Dimension{-1, 1, 0}, Bound::kPositive, w.mass_per_length);
  if (const auto model = node.find("model"); model && model->is_map()) {
    for (const auto& entry : model->yaml()) {
      const std::string face = entry.first.as<std::string>();
      w.flexible_faces[face] =
          model->required(face).choice<bool>({{"rigid", false}, {"flexible", true}});
    }
    if (w.flexible_faces.empty()) model->fail("no models: give rigid, flexible or {east: ..}");
  } else {
    node.read_choice<bool>("model", {{"rigid", false}, {"flexible", true}}, w.flexible);
  }
  if (w.follow == W::Follow::kBox)
    for (const char* key : {"thickness", "model"}) {
      const auto map = node.find(key);
      if (!map || !map->is_map()) continue;
      map->expect_keys({"east", "west", "north", "south"});
      for (int k = 0; k < 4; ++k) {
        const auto entry = map->find(W::kSideNames[k]);
        if (w.present[k] && !entry)
          map->fail(std::string("no ") + key + " for the " + W::kSideNames[k] + " wall");
        if (entry && !w.present[k])
          entry->fail(std::string("there is no ") + W::kSideNames[k] + " wall (see sides)");
      }
    }
  if (w.any_flexible()) {
    node.read_quantity("E", dim::kPressure, Bound::kPositive, w.E);
    node.read_number("nu", Bound::kNonNegative, w.nu);
    if (w.nu >= 0.5) node.fail_at_key("nu", "Poisson's ratio must be in [0, 0.5)");
    node.read_number("damping", Bound::kFraction, w.damping_ratio);
  }
  if (const auto bumper = node.find("bumper")) w.bumper = read_bumper3d(*bumper, w, read_side);
  return w;
}

// Walls by face (follow: outline or polyline): walls the outline or polyline can have at these
// gaps and thickness (a run too short for its mitres is refused at the walls' thickness, or at
// the polyline's vertex); a polyline's walls clear of the slab at rest; with sides: [...], each a
// face of the walls (moat_faces); with a gap per face, one for every wall and none for a face
// without one.
std::vector<MoatFace> check_moat_faces(const InputNode& walls, const Building3DConfig& b) {
  using Follow = MoatWalls3DConfig::Follow;
  const MoatWalls3DConfig& w = b.walls;
  if (!w.by_face()) return {};
  std::vector<MoatFace> faces;
  try {
    faces = moat_faces(b);
  } catch (const InvalidPolygon& e) {
    if (w.follow == Follow::kPolyline) {
      const InputNode line = walls.required("polyline");
      const auto points = line.elements();
      const InputNode at = e.vertex() >= 0 && e.vertex() < static_cast<int>(points.size())
                               ? points[static_cast<std::size_t>(e.vertex())]
                               : line;
      at.fail(std::string("no walls can follow this polyline: ") + e.what());
    }
    const auto t = walls.find("thickness");
    (t ? *t : walls).fail(std::string("no moat can follow this outline: ") + e.what());
  }
  std::string all;
  for (const MoatFace& f : faces) all += (all.empty() ? "" : ", ") + f.name;
  const auto has_face = [&](const std::string& face) {
    return std::any_of(faces.begin(), faces.end(),
                       [&](const MoatFace& f) { return f.name == face; });
  };
  if (w.follow == Follow::kPolyline)
    for (const MoatFace& f : faces)
      if (!(f.gap > 0.0)) {
        char what[200];
        std::snprintf(what, sizeof what,
                      "the %s wall along this polyline %s the slab it faces at rest (clearance "
                      "%.4g m): draw the walls' faces outside the slab",
                      f.name.c_str(), f.gap < 0 ? "crosses" : "touches", f.gap);
        walls.required("polyline").fail(what);
      }
  const char* of = w.follow == Follow::kPolyline ? "polyline" : "outline";
  if (!w.outline_sides.empty())
    for (const InputNode& side : walls.find("sides")->elements())
      if (!has_face(side.string()))
        side.fail("no wall of the " + std::string(of) + " faces '" + side.string() +
                  "': its walls face " + all);
  // Maps by face (thickness, model, gap): every wall's face, and only those.
  const auto check_face_map = [&](const char* key, const auto& map) {
    if (map.empty()) return;
    const InputNode node = walls.required(key);
    for (const auto& [face, value] : map) {
      if (!has_face(face))
        node.required(face).fail("no wall of the " + std::string(of) + " faces '" + face +
                                 "': its walls face " + all);
      if (!w.has_outline_wall(face))
        node.required(face).fail("there is no " + face + " wall (see sides)");
    }
    for (const MoatFace& f : faces)
      if (w.has_outline_wall(f.name) && !map.count(f.name))
        node.fail(std::string("no ") + key + " for the " + f.name + " wall (its walls face " + all +
                  ")");
  };
  check_face_map("thickness", w.thicknesses);
  check_face_map("model", w.flexible_faces);
  check_face_map("gap", w.outline_gaps);
  return faces;
}

// Walls by face with a bumper: its faces walls of the moat (`faces` as check_moat_faces returns
// them), the rubber thinner than each one's gap, from/to on each face.
void check_outline_bumper(const InputNode& walls, const Building3DConfig& b,
                          const std::vector<MoatFace>& faces) {
  const MoatWalls3DConfig& w = b.walls;
  if (!w.by_face() || !w.bumper.any()) return;
  const InputNode node = walls.required("bumper");
  const auto walled = [&](const std::string& face) {
    return std::any_of(faces.begin(), faces.end(),
                       [&](const MoatFace& f) { return f.name == face; }) &&
           w.has_outline_wall(face);
  };
  if (const auto sides = node.find("sides"))
    for (const InputNode& s : sides->elements())
      if (!walled(s.string())) s.fail("there is no " + s.string() + " wall (see walls.sides)");
  if (!(w.bumper.thickness > 0)) return;
  for (const MoatFace& f : faces) {
    const std::string& face = f.name;
    if (!walled(face) || !w.bumper.on_outline_face(face)) continue;
    if (w.bumper.thickness >= f.gap) {
      char what[200];
      std::snprintf(what, sizeof what,
                    "the bumper (%g cm) must be thinner than the %s wall's gap (%g cm)",
                    100 * w.bumper.thickness, face.c_str(), 100 * f.gap);
      node.fail_at_key("thickness", what);
    }
    try {
      wall_bumper_strips(b, -1, face);
    } catch (const std::invalid_argument& e) {
      node.fail_at_key(node.has("to") ? "to" : "from", "the " + face + " wall: " + e.what());
    }
  }
}

Building3DConfig read_building3d(const InputNode& node) {
  node.expect_keys({"name",
                    "position",
                    "rotation",
                    "isolated",
                    "plan",
                    "grid",
                    "columns",
                    "storeys",
                    "base",
                    "eccentricity",
                    "bearing",
                    "bearings",
                    "damping",
                    "polar_moment_rule",
                    "column_coupling",
                    "walls",
                    "adjacent",
                    "p_delta",
                    "elastic_limit_drift_ratio",
                    "isolation_level",
                    "isolation_height",
                    "struck_columns",
                    "bumper"});
  Building3DConfig b;
  if (const auto n = node.find("name")) {
    b.name = n->string();
    if (b.name.empty()) n->fail("must not be empty");
  }
  if (const auto p = node.find("position")) b.position = read_point(*p);
  node.read_angle("rotation", b.rotation);
  node.read_boolean("isolated", b.isolated);
  node.read_boolean("p_delta", b.p_delta);
  if (const auto s = node.find("struck_columns")) b.struck_columns = read_struck_columns3d(*s);
  node.read_number("elastic_limit_drift_ratio", Bound::kPositive, b.elastic_limit_drift_ratio);
  if (const auto r = node.find("polar_moment_rule"))
    b.polar_moment_rule = r->choice<EccentricPolarMoment>(
        {{"thesis", EccentricPolarMoment::kThesis}, {"centroid", EccentricPolarMoment::kCentroid}});
  if (const auto r = node.find("column_coupling"))
    b.column_coupling = r->choice<ColumnCoupling>(
        {{"thesis", ColumnCoupling::kThesis}, {"full", ColumnCoupling::kFull}});

  // Column lines and default column properties.
  std::vector<std::pair<std::string, Vec2>> grid;
  if (const auto g = node.find("grid")) grid = read_grid(*g);
  ColumnProps defaults;
  const auto columns_node = node.find("columns");
  if (columns_node) {
    columns_node->expect_keys(kColumnPropKeys);
    read_column_props(*columns_node, defaults);
  }
  // Default plan: `plan`, else the grid's outline.
  std::vector<Vec2> plan;
  if (const auto p = node.find("plan")) {
    plan = read_plan(*p);
  } else if (!grid.empty()) {
    Vec2 lo = grid.front().second, hi = grid.back().second;
    plan = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
  }
  Vec2 eccentricity;
  if (const auto e = node.find("eccentricity")) eccentricity = read_point(*e);

  const auto grid_columns = [&](const InputNode& where, const ColumnProps& props) {
    if (grid.empty())
      where.fail("no columns: give grid: {bays_x, bays_y} or a columns list in each storey");
    std::vector<Column3DConfig> cols;
    for (const auto& [label, p] : grid) {
      Column3DConfig c = make_column(props, columns_node ? *columns_node : where);
      c.label = label;
      c.position = p;
      cols.push_back(c);
    }
    return cols;
  };
  const auto check_plan = [&](const Diaphragm3DConfig& d, const InputNode& where) {
    if (d.plan.empty()) where.fail_at_key("plan", "no plan: give plan: or grid: for the building");
  };

  // Storeys: short form {count, height, mass, roof_mass} or a list.
  const InputNode storeys = node.required("storeys");
  if (storeys.is_sequence()) {
    if (storeys.elements().empty()) storeys.fail("no storeys");
    if (storeys.elements().size() > kMaxStoreys) storeys.fail("too many storeys");
    for (const InputNode& item : storeys.elements()) {
      item.expect_keys(
          {"height", "mass", "eccentricity", "polar_moment", "plan", "columns", "hysteresis"});
      // The storey's columns' law (a column's own `hysteresis:` overrides it).
      ColumnProps storey_defaults = defaults;
      if (const auto n = item.find("hysteresis"))
        storey_defaults.hysteresis = read_column_hysteresis(*n);
      Storey3DConfig s;
      s.height = item.required("height").quantity(dim::kLength, Bound::kPositive);
      s.floor.mass = item.required("mass").quantity(dim::kMass, Bound::kPositive);
      s.floor.plan = plan;
      s.floor.eccentricity = eccentricity;
      read_diaphragm_extras(item, s.floor);
      check_plan(s.floor, item);
      if (const auto cols = item.find("columns")) {
        if (!cols->is_sequence()) cols->fail("expected a list of columns");
        for (const InputNode& c : cols->elements()) {
          std::vector<std::string_view> keys = kColumnPropKeys;
          keys.push_back("label");
          keys.push_back("at");
          c.expect_keys(keys);
          ColumnProps p = storey_defaults;
          read_column_props(c, p);
          Column3DConfig col = make_column(p, c);
          col.position = read_point(c.required("at"));
          col.label =
              c.has("label") ? c.required("label").string() : numbered('C', s.columns.size() + 1);
          s.columns.push_back(col);
        }
        if (s.columns.empty()) cols->fail("no columns");
      } else {
        s.columns = grid_columns(item, storey_defaults);
      }
      b.storeys.push_back(s);
    }
  } else {
    storeys.expect_keys({"count", "height", "mass", "roof_mass"});
    const int count = storeys.required("count").integer(1, kMaxStoreys);
    Storey3DConfig s;
    s.height = storeys.required("height").quantity(dim::kLength, Bound::kPositive);
    s.floor.mass = storeys.required("mass").quantity(dim::kMass, Bound::kPositive);
    s.floor.plan = plan;
    s.floor.eccentricity = eccentricity;
    check_plan(s.floor, node);
    s.columns = grid_columns(storeys, defaults);
    b.storeys.assign(static_cast<std::size_t>(count), s);
    storeys.read_quantity("roof_mass", dim::kMass, Bound::kPositive, b.storeys.back().floor.mass);
  }

  // Isolation level (levels3d.h): the bearings on floor k, at least one storey above them.
  if (b.isolated) {
    const int storeys_count = static_cast<int>(b.storeys.size());
    if (const auto k = node.find("isolation_level")) {
      if (storeys_count < 2 && k->integer(0, std::numeric_limits<int>::max()) > 0)
        k->fail("the building has 1 storey: only isolation_level 0 (on the ground) is possible");
      b.isolation_level = k->integer(0, storeys_count - 1);
    }  // absent: on the ground, today's model (not listed as a default: outputs unchanged)
    if (const auto h = node.find("isolation_height")) {
      if (b.isolation_level == 0)
        h->fail("only used with isolation_level > 0 (the base slab's height above that floor)");
      b.isolation_height = h->quantity(dim::kLength, Bound::kPositive);
    } else if (b.isolation_level > 0) {
      node.fail_at_key("isolation_height",
                       "required with isolation_level > 0: the base slab's height above floor " +
                           std::to_string(b.isolation_level));
    }
  } else {
    for (const char* key : {"isolation_level", "isolation_height"})
      if (const auto n = node.find(key))
        n->fail("not allowed for a fixed-base building (isolated: false)");
  }

  // Base slab and bearings.
  if (b.isolated) {
    const InputNode base = node.required("base");
    base.expect_keys({"mass", "eccentricity", "polar_moment", "plan"});
    b.base.mass = base.required("mass").quantity(dim::kMass, Bound::kPositive);
    b.base.plan = plan;
    b.base.eccentricity = eccentricity;
    read_diaphragm_extras(base, b.base);
    check_plan(b.base, base);
    if (const auto law = node.find("bearing")) b.bearing = read_bearing_law(*law);
    if (const auto list = node.find("bearings")) {
      if (!list->is_sequence()) list->fail("expected a list of bearings [{at: [x, y]}, ...]");
      for (const InputNode& item : list->elements()) {
        item.expect_keys({"label", "at", "carried_mass"});
        Bearing3DConfig br;
        br.position = read_point(item.required("at"));
        br.label = item.has("label") ? item.required("label").string()
                                     : numbered('B', b.bearings.size() + 1);
        item.read_quantity("carried_mass", dim::kMass, Bound::kPositive, br.carried_mass);
        b.bearings.push_back(br);
      }
      if (b.bearings.empty()) list->fail("no bearings");
    }
  } else {
    for (const char* key : {"base", "bearing", "bearings"})
      if (const auto n = node.find(key))
        n->fail("not allowed for a fixed-base building (isolated: false)");
  }
  // Columns and bearings inside their slabs: the site checks (site_checks.h).
  if (const auto d = node.find("damping")) read_damping3d(*d, b.isolated, b.damping);
  if (const auto w = node.find("walls")) {
    if (!b.isolated)
      w->fail(
          "moat walls surround the base slab of an isolated building; a fixed-base "
          "building has none (model a wall next to it as its own structure)");
    b.walls = read_walls3d(*w);
    check_bumper_span(*w, b);
    // The level the walls face (levels3d.h order); default the base slab.
    if (const auto l = w->find("level")) {
      const int levels = static_cast<int>(b.storeys.size()) + 1;
      const int level =
          l->integer(std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
      if (level < 0 || level >= levels)
        l->fail("no level " + std::to_string(level) + ": the building's levels are 0.." +
                std::to_string(levels - 1) + " (bottom to top, the base slab is level " +
                std::to_string(b.isolation_level) + ")");
      b.walls_level = level;
    }
    check_outline_bumper(*w, b, check_moat_faces(*w, b));
  }
  if (!b.isolated && b.damping.type == Damping3DConfig::Type::kNonClassical) {
    // Fixed base: the superstructure Rayleigh alone.
  }
  return b;
}

// Plan-frame bounding box of every slab of a building as placed.
std::pair<Vec2, Vec2> plan_box(const Building3DConfig& b) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec2 lo{inf, inf}, hi{-inf, -inf};
  const auto add = [&](const Diaphragm3DConfig& d) {
    for (const Vec2& p_B : d.plan) {
      const Vec2 p = to_plan(b, p_B);
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
  };
  if (b.isolated) add(b.base);
  for (const Storey3DConfig& s : b.storeys) add(s.floor);
  return {lo, hi};
}

// adjacent: {to: NAME, side: east|west|north|south, gap: G}: sets the building's position so
// that its bounding box (in plan) faces the other's on that side at G, centred on it. Sides are
// directions of the model's plan frame (east = +x).
void place_adjacent(const InputNode& adj, const InputNode& item,
                    std::vector<Building3DConfig>& buildings) {
  using W = MoatWalls3DConfig;
  adj.expect_keys({"to", "side", "gap"});
  Building3DConfig& me = buildings.back();
  if (item.has("position"))
    item.fail_at_key("position", "give either position or adjacent, not both");
  const InputNode to = adj.required("to");
  const std::string other_name = to.string();
  const Building3DConfig* other = nullptr;
  for (std::size_t k = 0; k + 1 < buildings.size(); ++k)
    if (buildings[k].name == other_name) other = &buildings[k];
  if (!other)
    to.fail("no structure named '" + other_name +
            "' before this one (list the building it stands next to first)");
  const int side = read_side(adj.required("side"));
  const double gap = adj.required("gap").quantity(dim::kLength, Bound::kPositive);
  me.position = {0.0, 0.0};
  const auto [olo, ohi] = plan_box(*other);
  const auto [mlo, mhi] = plan_box(me);
  const Vec2 ocentre = 0.5 * (olo + ohi), mcentre = 0.5 * (mlo + mhi);
  switch (side) {
    case W::kEast:
      me.position = {ohi.x + gap - mlo.x, ocentre.y - mcentre.y};
      break;
    case W::kWest:
      me.position = {olo.x - gap - mhi.x, ocentre.y - mcentre.y};
      break;
    case W::kNorth:
      me.position = {ocentre.x - mcentre.x, ohi.y + gap - mlo.y};
      break;
    default:
      me.position = {ocentre.x - mcentre.x, olo.y - gap - mhi.y};
      break;
  }
  me.adjacent = {other_name, side, gap};
}

}  // namespace

std::vector<Building3DConfig> read_structures3d(const InputNode& node) {
  if (!node.is_sequence() || node.elements().empty())
    node.fail("expected a list of buildings: - {name, grid, storeys, ...}");
  std::vector<Building3DConfig> out;
  for (const InputNode& item : node.elements()) {
    out.push_back(read_building3d(item));
    try {
      check_damping_modes(out.back());
    } catch (const RayleighModesError& e) {
      const auto damping = item.find("damping");
      if (damping && damping->has("modes")) damping->required("modes").fail(e.what());
      item.fail_at_key("damping", std::string(e.what()) + " (modes [1, 4] is the default)");
    } catch (const std::invalid_argument&) {
      // Any other inconsistency is reported when the model is built, as before.
    }
    for (std::size_t k = 0; k + 1 < out.size(); ++k)
      if (out[k].name == out.back().name)
        item.fail_at_key("name", "two structures are named '" + out.back().name + "'");
    if (const auto adj = item.find("adjacent")) place_adjacent(*adj, item, out);
    // Rubber on the slabs' faces: after the placement, whose side it defaults to.
    if (const auto bumper = item.find("bumper"))
      out.back().bumper = read_slab_bumper3d(*bumper, out.back(), read_side);
  }
  return out;
}

}  // namespace isopound
