// Reading the rubber bumpers of moat walls and neighbours (issue 27; docs/impact-laws.md,
// "Bumpers"): the 2D wall or neighbour form and the 3D wall strip share the rubber's e and
// max_strain; each checks its thickness against the gaps it faces.
#include "solver/io/bumper_input.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/overlap.h"
#include "geometry/plan_shape.h"
#include "solver/structures/building3d.h"
#include "solver/structures/bumper_layer3d.h"
#include "solver/structures/levels3d.h"
#include "solver/structures/pounding3d.h"

namespace isopound {

namespace {

// The rubber's coefficient of restitution (required, (0, 1]) and bottoming-out strain (0, 1).
void read_rubber(const InputNode& node, double& e, double& max_strain) {
  const InputNode restitution = node.required("e");
  e = restitution.number(Bound::kPositive);
  if (e > 1.0) restitution.fail("the coefficient of restitution must be in (0, 1]");
  if (const auto strain = node.find("max_strain")) {
    max_strain = strain->number();
    if (!(max_strain > 0 && max_strain < 1))
      strain->fail("max_strain must be in (0, 1) (a fraction of the thickness, e.g. 60 %)");
  } else {
    node.note_default("max_strain", "0.6");
  }
}

}  // namespace

// A rubber bumper on the wall's face (bumper_law.h). Its face must stay clear of the level's rest
// position: thickness < the smallest gap of the sides the wall has (a rubber touching at rest
// has no impact velocity for its damping, which divides by it).
BumperConfig read_bumper(const InputNode& node, double gap) {
  node.expect_keys({"thickness", "law", "k", "E", "area", "e", "max_strain", "min_impact_velocity",
                    "bottoming"});
  BumperConfig b;
  const InputNode thickness = node.required("thickness");
  b.thickness = thickness.quantity(dim::kLength, Bound::kNonNegative);
  if (b.thickness > 0 && b.thickness >= gap) {
    char what[160];
    std::snprintf(what, sizeof what,
                  "the bumper (%g cm) must be thinner than the gap (%g cm): it would touch the "
                  "slab at rest",
                  100 * b.thickness, 100 * gap);
    thickness.fail(what);
  }
  node.read_choice<std::string>("law", {{"linear", "linear"}, {"hertz", "hertz"}}, b.law);
  const double n = b.law == "hertz" ? 1.5 : 1.0;
  if (const auto k = node.find("k")) {
    for (const char* key : {"E", "area"})
      if (node.has(key))
        node.find(key)->fail("give either k, or E and area (k = E A / t), not both");
    b.k = k->quantity(Dimension{1.0 - n, 1.0, -2.0}, Bound::kPositive);
  } else {
    if (!node.has("E") && !node.has("area"))
      node.fail_at_key("k", "missing required key 'k' (or E and area: k = E A / t)");
    b.modulus = node.required("E").quantity(dim::kPressure, Bound::kPositive);
    b.area = node.required("area").quantity(Dimension{2.0, 0.0, 0.0}, Bound::kPositive);
  }
  read_rubber(node, b.e, b.max_strain);
  node.read_quantity("min_impact_velocity", dim::kVelocity, Bound::kPositive,
                     b.min_impact_velocity);
  node.read_choice<BumperBottoming>(
      "bottoming", {{"continuous", BumperBottoming::kContinuous}, {"jump", BumperBottoming::kJump}},
      b.bottoming);
  return b;
}

namespace {

// The rubber of a 3D strip: {thickness, law, E, height, e, max_strain, mu_static, mu_kinetic,
// from, to}; `sides` is read by the caller.
void read_strip_rubber(const InputNode& node, Bumper3DConfig& b) {
  b.thickness = node.required("thickness").quantity(dim::kLength, Bound::kNonNegative);
  node.read_choice<std::string>("law", {{"linear", "linear"}, {"hertz", "hertz"}}, b.law);
  b.modulus = node.required("E").quantity(dim::kPressure, Bound::kPositive);
  b.height = node.required("height").quantity(dim::kLength, Bound::kPositive);
  read_rubber(node, b.e, b.max_strain);
  node.read_number("mu_static", Bound::kNonNegative, b.mu_static);
  node.read_number("mu_kinetic", Bound::kNonNegative, b.mu_kinetic);
  if (b.mu_kinetic > b.mu_static) node.fail_at_key("mu_kinetic", "must not exceed mu_static");
  node.read_quantity("from", dim::kLength, Bound::kNonNegative, b.from);
  if (const auto to = node.find("to")) {
    b.to = to->quantity(dim::kLength, Bound::kPositive);
    if (!(b.from < b.to)) to->fail("'to' must be beyond 'from'");
  }
}

// `sides: [east, ...]`, each at most once, each one that `allowed` accepts (else its message).
void read_sides(const InputNode& sides, const std::function<int(const InputNode&)>& side_of,
                const std::function<std::string(int)>& refused, Bumper3DConfig& b) {
  if (!sides.is_sequence() || sides.elements().empty())
    sides.fail("expected a list of sides, e.g. [east, west]");
  for (const InputNode& s : sides.elements()) {
    const int k = side_of(s);
    if (const std::string why = refused(k); !why.empty()) s.fail(why);
    if (b.on[k]) s.fail("side listed twice");
    b.on[k] = true;
  }
}

// The keys of a 3D bumper, on a wall or on a slab face.
const std::vector<std::string_view> kStripKeys = {
    "sides",      "thickness", "law",        "E",    "height", "e",
    "max_strain", "mu_static", "mu_kinetic", "from", "to"};

constexpr const std::array<const char*, 4>& kSideNames = MoatWalls3DConfig::kSideNames;

}  // namespace

std::vector<std::string> read_face_names(const InputNode& list, const std::string& when_empty) {
  if (list.elements().empty()) list.fail(when_empty);
  std::vector<std::string> faces;
  for (const InputNode& face : list.elements()) {
    if (std::find(faces.begin(), faces.end(), face.string()) != faces.end())
      face.fail("side listed twice");
    faces.push_back(face.string());
  }
  return faces;
}

// bumper: {sides, thickness, law, E, height, e, max_strain, mu_static, mu_kinetic, from, to}
// under walls (issue 27; docs/impact-laws.md). from/to against the face: check_bumper_span.
Bumper3DConfig read_bumper3d(const InputNode& node, const MoatWalls3DConfig& walls,
                             const std::function<int(const InputNode&)>& side_of) {
  node.expect_keys(kStripKeys);
  Bumper3DConfig b;
  if (walls.by_face()) {
    // Faces of the outline's or polyline's walls by name (checked with the plan:
    // check_outline_bumper), or all.
    b.on = walls.present;
    if (const auto sides = node.find("sides")) {
      if (!sides->is_sequence()) sides->fail("expected a list of faces, e.g. [east, north-east]");
      b.faces = read_face_names(*sides, "expected a list of faces, e.g. [east, north-east]");
    } else {
      node.note_default("sides", "every wall");
    }
    read_strip_rubber(node, b);
    return b;  // thinner than each face's gap: check_outline_bumper
  }
  if (const auto sides = node.find("sides")) {
    read_sides(
        *sides, side_of,
        [&](int k) {
          return walls.present[k] ? std::string()
                                  : std::string("there is no ") + kSideNames[k] + " wall";
        },
        b);
  } else {
    node.note_default("sides", "every wall");
    b.on = walls.present;
  }
  read_strip_rubber(node, b);
  for (int k = 0; k < 4; ++k)
    if (b.on[k] && b.thickness > 0 && b.thickness >= walls.gap[k]) {
      char what[160];
      std::snprintf(what, sizeof what,
                    "the bumper (%g cm) must be thinner than the %s wall's gap (%g cm)",
                    100 * b.thickness, kSideNames[k], 100 * walls.gap[k]);
      node.fail_at_key("thickness", what);
    }
  return b;
}

// bumper: {...} on a building: rubber on its slabs' faces (sides in the building frame; default
// the face towards adjacent.to). A convex slab's sides are its bounding box's, and it needs a
// straight edge on each; a non-convex slab's are its outline's faces by name (outline_faces:
// "east", "north 2"), each listed face on some level. Every face over [from, to].
Bumper3DConfig read_slab_bumper3d(const InputNode& node, const Building3DConfig& building,
                                  const std::function<int(const InputNode&)>& side_of) {
  node.expect_keys(kStripKeys);
  Bumper3DConfig b;
  const std::vector<Level3D> levels = levels3d(building);
  const bool by_outline = std::any_of(levels.begin(), levels.end(), [](const Level3D& l) {
    return !is_convex_list(l.diaphragm->plan);
  });
  const auto sides = node.find("sides");
  if (sides && by_outline) {
    const char* example = "expected a list of faces, e.g. [east, north 2]";
    if (!sides->is_sequence()) sides->fail(example);
    b.faces = read_face_names(*sides, example);
    b.on = {true, true, true, true};
  } else if (sides) {
    read_sides(
        *sides, side_of, [](int) { return std::string(); }, b);
  } else if (!building.adjacent.to.empty() && building.rotation == 0.0) {
    // adjacent.side: the side of `to` this building stands on; its own facing side is opposite.
    static constexpr int kOpposite[4] = {1, 0, 3, 2};
    const int k = kOpposite[building.adjacent.side];
    if (by_outline) {
      b.faces = {kSideNames[k]};
      b.on = {true, true, true, true};
    } else {
      b.on[k] = true;
    }
    node.note_default("sides", std::string("[") + kSideNames[k] + "] (the face towards '" +
                                   building.adjacent.to + "')");
  } else {
    node.fail_at_key("sides",
                     "missing required key 'sides' (the faces with rubber, e.g. [west]; it "
                     "defaults to the face towards adjacent.to for an unrotated building)");
  }
  read_strip_rubber(node, b);
  if (!(b.thickness > 0)) return b;
  if (by_outline) {
    // Each listed face is one of some level's (a convex level's: its box sides).
    std::vector<std::string> known;
    for (const Level3D& level : levels) {
      const std::vector<Vec2>& plan = level.diaphragm->plan;
      if (is_convex_list(plan)) {
        known.insert(known.end(), kSideNames.begin(), kSideNames.end());
        continue;
      }
      for (const OutlineFace& f : outline_faces(SimplePolygon(std::span<const Vec2>(plan))))
        known.push_back(f.name);
    }
    for (const std::string& face : b.faces) {
      if (std::find(known.begin(), known.end(), face) != known.end()) continue;
      std::string list;
      for (const std::string& k : known)
        if (list.find("'" + k + "'") == std::string::npos)
          list += (list.empty() ? "'" : ", '") + k + "'";
      const std::string what =
          "no slab of this building has a face '" + face + "' (the outline's faces: " + list + ")";
      if (sides)
        for (const InputNode& e : sides->elements())
          if (e.string() == face) e.fail(what);
      node.fail_at_key("sides", what);
    }
  }
  for (const Level3D& level : levels) {
    try {
      slab_face_strips(level.diaphragm->plan, b);
    } catch (const std::invalid_argument& e) {
      const char* key = node.has("to") ? "to" : node.has("from") ? "from" : "sides";
      node.fail_at_key(key, level.name + ": " + e.what());
    }
  }
  return b;
}

void check_slab_bumpers(const ModelConfig& config, const std::vector<StructureMarks>& marks,
                        const Site& site, double level_tolerance, ProblemList& problems) {
  for (std::size_t i = 0; i < config.structures3d.size() && i < marks.size(); ++i) {
    const Building3DConfig& b = config.structures3d[i];
    if (!b.bumper.any() || !(b.bumper.thickness > 0) || !marks[i].item) continue;
    const auto node = marks[i].item->find("bumper");
    if (!node) continue;
    for (const Level3D& level : levels3d(b))
      for (const FaceStrips& face : slab_face_strips(level.diaphragm->plan, b.bumper)) {
        std::vector<Vec2> rubber_W;
        for (const Vec2& p : face.strips.rubber) rubber_W.push_back(to_plan(b, p));
        const ConvexPolygon rubber(std::span<const Vec2>(rubber_W.data(), rubber_W.size()));
        for (const PlanSlab& other : site.slabs) {
          if (other.structure == static_cast<int>(i) ||
              std::abs(other.elevation - level.elevation) > level_tolerance)
            continue;
          if (plan_separation(rubber.vertices(), other.plan_W).distance > 0) continue;
          char what[240];
          std::snprintf(what, sizeof what,
                        "the rubber on the %s face of '%s/%s' (%g cm) touches or enters '%s/%s' "
                        "at rest: a bumper must be thinner than the gap it faces",
                        face.face.c_str(), b.name.c_str(), level.name.c_str(),
                        100 * b.bumper.thickness, other.name.c_str(), other.level.c_str());
          problems.error_at(*node, "thickness", what);
        }
      }
  }
}

// from/to of the bumper inside every bumpered face (its length: the slab's extent plus the
// walls' extension at each end, as moat_wall_outline builds it).
void check_bumper_span(const InputNode& walls_node, const Building3DConfig& b) {
  const Bumper3DConfig& bumper = b.walls.bumper;
  if (!bumper.any() || b.walls.by_face()) return;  // walls by face: check_outline_bumper
  const InputNode node = walls_node.required("bumper");
  for (int side = 0; side < 4; ++side) {
    if (!bumper.on[side]) continue;
    const std::vector<Vec2> wall = moat_wall_outline(b, side);
    const bool along_y = side <= MoatWalls3DConfig::kWest;
    const double length = along_y ? wall[2].y - wall[0].y : wall[1].x - wall[0].x;
    const auto outside = [&](const char* key, double value) {
      char what[200];
      std::snprintf(what, sizeof what,
                    "%s = %g m lies beyond the %s wall's face (%g m long: the slab plus the "
                    "extension at each end)",
                    key, value, MoatWalls3DConfig::kSideNames[side], length);
      node.fail_at_key(key, what);
    };
    if (bumper.from >= length) outside("from", bumper.from);
    if (std::isfinite(bumper.to) && bumper.to > length * (1 + 1e-12)) outside("to", bumper.to);
  }
}

}  // namespace isopound
