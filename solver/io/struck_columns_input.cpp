// Reading the facing column line of a 2D building (`columns:`): the section, the hinges' yield
// moment and hardening, the shear check; their share of each storey's stiffness checked.
#include "solver/io/struck_columns_input.h"

#include <cstdio>
#include <string>

namespace isopound {

namespace {
constexpr Dimension kAreaMoment{4, 0, 0};  // m^4
constexpr Dimension kMoment{2, 1, -2};     // N m

// shear_check and V_n: V_n required with shear_check: true, refused without it.
void read_shear_check(const InputNode& node, bool& check, double& capacity) {
  node.read_boolean("shear_check", check);
  if (check) {
    if (!node.has("V_n"))
      node.fail_at_key("V_n",
                       "missing required key 'V_n' (the column's shear capacity): shear_check "
                       "is true");
    capacity = node.required("V_n").quantity(dim::kForce, Bound::kPositive);
  } else if (const auto v = node.find("V_n")) {
    v->fail("only with shear_check: true");
  }
}

}  // namespace

StruckColumnsConfig read_struck_columns(const InputNode& node, const BuildingConfig& b) {
  node.expect_keys({"count", "E", "I", "M_y", "hardening_ratio", "shear_check", "V_n"});
  StruckColumnsConfig c;
  c.given = true;
  node.read_integer("count", 1, 10000, c.count);
  c.E = node.required("E").quantity(dim::kPressure, Bound::kPositive);
  c.I = node.required("I").quantity(kAreaMoment, Bound::kPositive);
  const InputNode yield = node.required("M_y");
  c.yield_moment = yield.quantity(kMoment, Bound::kPositive);
  // Hardening keeps the node stable once all three hinges have formed (a mechanism).
  node.read_number("hardening_ratio", Bound::kPositive, c.hardening_ratio);
  read_shear_check(node, c.shear_check, c.shear_capacity);
  // The two façade lines (left and right, `count` columns each) are part of every storey
  // (column_line.h): their share must fit in its stiffness, and their hinges are the storey's
  // yielding, so a storey's own hysteresis: would define it twice.
  for (std::size_t f = 0; f < b.floors.size(); ++f) {
    const double h = b.floors[f].height;
    const double k = 2.0 * c.count * 12.0 * c.E * c.I / (h * h * h);
    if (k > b.floors[f].stiffness) {
      char what[240];
      std::snprintf(what, sizeof what,
                    "the façade columns (2 lines x count x 12 E I / h^3 = %.4g MN/m) are stiffer "
                    "than storey %zu of '%s' (%.4g MN/m)",
                    k / 1e6, f + 1, b.name.c_str(), b.floors[f].stiffness / 1e6);
      node.fail_at_key("I", what);
    }
    if (b.floors[f].hysteresis.yields()) {
      char what[240];
      std::snprintf(what, sizeof what,
                    "storey %zu of '%s' yields through its hysteresis: law; with columns: its "
                    "yielding is the façade columns' hinges (M_y). Give one of the two",
                    f + 1, b.name.c_str());
      node.fail_at_key("M_y", what);
    }
  }
  return c;
}

StruckColumns3DConfig read_struck_columns3d(const InputNode& node) {
  node.expect_keys({"M_y", "hardening_ratio", "shear_check", "V_n"});
  StruckColumns3DConfig c;
  c.given = true;
  // One M_y for both axes, or [M_y along axis 1, M_y along axis 2].
  const InputNode yield = node.required("M_y");
  if (yield.is_sequence()) {
    if (yield.elements().size() != 2)
      yield.fail("give one M_y or two: [along axis 1, along axis 2]");
    for (std::size_t i = 0; i < 2; ++i)
      c.yield_moment[i] = yield.elements()[i].quantity(kMoment, Bound::kPositive);
  } else {
    c.yield_moment[0] = c.yield_moment[1] = yield.quantity(kMoment, Bound::kPositive);
  }
  node.read_number("hardening_ratio", Bound::kPositive, c.hardening_ratio);
  read_shear_check(node, c.shear_check, c.shear_capacity);
  return c;
}

}  // namespace isopound
