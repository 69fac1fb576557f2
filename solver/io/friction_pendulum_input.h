// The friction pendulum's keys, read the same way for the 2D isolator and a 3D bearing:
// R, mu_slow, mu_fast, rate_parameter (s/m; not needed when mu_slow = mu_fast), uy,
// friction_hysteresis.
#pragma once

#include "solver/io/yaml_reader.h"

namespace isopound {

// Config: IsolatorConfig or BearingConfig (the same field names). uy is the pre-sliding travel,
// 0.5 mm unless given (THEORY-notes.md, "Friction pendulum").
template <class Config>
void read_friction_pendulum(const InputNode& node, Config& c) {
  constexpr Dimension kSlowness{-1, 0, 1};  // s/m
  c.radius = node.required("R").quantity(dim::kLength, Bound::kPositive);
  c.mu_slow = node.required("mu_slow").number(Bound::kNonNegative);
  c.mu_fast = node.required("mu_fast").number(Bound::kNonNegative);
  if (c.mu_fast != c.mu_slow)
    c.rate_parameter = node.required("rate_parameter").quantity(kSlowness, Bound::kNonNegative);
  else
    node.read_quantity("rate_parameter", kSlowness, Bound::kNonNegative, c.rate_parameter);
  c.yield_displacement = 5e-4;
  node.read_quantity("uy", dim::kLength, Bound::kPositive, c.yield_displacement);
  if (const auto z = node.find("friction_hysteresis"))
    c.smooth_friction = z->choice<bool>({{"plastic", false}, {"bouc_wen", true}});
}

}  // namespace isopound
