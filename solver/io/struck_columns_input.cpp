// Reading the facing column line of a 2D building (`columns:`): the section, the hinges' yield
// moment and hardening, the shear check; their share of each storey's stiffness checked.
#include "solver/io/struck_columns_input.h"

#include <cstdio>
#include <string>

namespace isopound {

namespace {
constexpr Dimension kAreaMoment{4, 0, 0};  // m^4
constexpr Dimension kMoment{2, 1, -2};     // N m
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
  node.read_boolean("shear_check", c.shear_check);
  if (c.shear_check) {
    if (!node.has("V_n"))
      node.fail_at_key("V_n",
                       "missing required key 'V_n' (the column's shear capacity): shear_check "
                       "is true");
    c.shear_capacity = node.required("V_n").quantity(dim::kForce, Bound::kPositive);
  } else if (const auto v = node.find("V_n")) {
    v->fail("only with shear_check: true");
  }
  // The struck columns are part of the storey: their share must fit in its stiffness.
  for (std::size_t f = 0; f < b.floors.size(); ++f) {
    const double h = b.floors[f].height;
    const double k = c.count * 12.0 * c.E * c.I / (h * h * h);
    if (k > b.floors[f].stiffness) {
      char what[200];
      std::snprintf(what, sizeof what,
                    "the struck columns (count x 12 E I / h^3 = %.4g MN/m) are stiffer than "
                    "storey %zu of '%s' (%.4g MN/m)",
                    k / 1e6, f + 1, b.name.c_str(), b.floors[f].stiffness / 1e6);
      node.fail_at_key("I", what);
    }
  }
  return c;
}

}  // namespace isopound
