// Reading the rubber bumpers of moat walls and neighbours (issue 27; docs/impact-laws.md,
// "Bumpers"): the 2D wall or neighbour form and the 3D wall strip share the rubber's e and
// max_strain; each checks its thickness against the gaps it faces.
#include "solver/io/bumper_input.h"

#include <cmath>
#include <cstdio>
#include <string>

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

// bumper: {sides, thickness, law, E, height, e, max_strain, mu_static, mu_kinetic, from, to}
// under walls (issue 27; docs/impact-laws.md). from/to against the face: check_bumper_span.
MoatBumper3DConfig read_bumper3d(const InputNode& node, const MoatWalls3DConfig& walls,
                                 const std::function<int(const InputNode&)>& side_of) {
  using W = MoatWalls3DConfig;
  node.expect_keys({"sides", "thickness", "law", "E", "height", "e", "max_strain", "mu_static",
                    "mu_kinetic", "from", "to"});
  MoatBumper3DConfig b;
  if (const auto sides = node.find("sides")) {
    if (!sides->is_sequence() || sides->elements().empty())
      sides->fail("expected a list of walls, e.g. [east, west]");
    for (const InputNode& s : sides->elements()) {
      const int k = side_of(s);
      if (!walls.present[k]) s.fail(std::string("there is no ") + W::kSideNames[k] + " wall");
      if (b.on[k]) s.fail("side listed twice");
      b.on[k] = true;
    }
  } else {
    node.note_default("sides", "every wall");
    b.on = walls.present;
  }
  const InputNode thickness = node.required("thickness");
  b.thickness = thickness.quantity(dim::kLength, Bound::kNonNegative);
  for (int k = 0; k < 4; ++k)
    if (b.on[k] && b.thickness > 0 && b.thickness >= walls.gap[k]) {
      char what[160];
      std::snprintf(what, sizeof what,
                    "the bumper (%g cm) must be thinner than the %s wall's gap (%g cm)",
                    100 * b.thickness, W::kSideNames[k], 100 * walls.gap[k]);
      thickness.fail(what);
    }
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
  return b;
}

// from/to of the bumper inside every bumpered face (its length: the slab's extent plus the
// walls' extension at each end, as moat_wall_outline builds it).
void check_bumper_span(const InputNode& walls_node, const Building3DConfig& b) {
  const MoatBumper3DConfig& bumper = b.walls.bumper;
  if (!bumper.any()) return;
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
