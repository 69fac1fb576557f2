// Bearing laws from the engineer's numbers: the constants come from isolator_properties (the 2D
// rules, eq. 2.4), the law is the biaxial counterpart; the friction pendulum from R, mu, a, u_y.
#include "solver/structures/bearing.h"

#include <stdexcept>

#include "solver/core/constants.h"
#include "solver/materials/friction_pendulum.h"
#include "solver/materials/hysteresis_law.h"
#include "solver/materials/linear_biaxial.h"
#include "solver/structures/isolator.h"

namespace isopound {

namespace {

// The uniaxial isolator with the same numbers (for isolator_properties and the uncoupled law).
IsolatorConfig isolator_config(const BearingConfig& c) {
  using B = BearingConfig::Model;
  using I = IsolatorConfig::Model;
  IsolatorConfig iso;
  switch (c.model) {
    case B::kLinear:
      iso.model = I::kLinear;
      break;
    case B::kBilinear:
      iso.model = I::kBilinear;
      break;
    case B::kBoucWenCoupled:
    case B::kBoucWenUncoupled:
      iso.model = I::kBoucWen;
      break;
    case B::kFrictionPendulum:
      iso.model = I::kFrictionPendulum;
      break;
  }
  iso.period = c.period;
  iso.strength_ratio = c.strength_ratio;
  iso.yield_displacement = c.yield_displacement;
  iso.bouc_wen = c.bouc_wen;
  iso.strength_is_yield_force = c.strength_is_yield_force;
  iso.carried_mass = c.carried_mass;
  iso.radius = c.radius;
  iso.mu_slow = c.mu_slow;
  iso.mu_fast = c.mu_fast;
  iso.rate_parameter = c.rate_parameter;
  iso.smooth_friction = c.smooth_friction;
  return iso;
}

}  // namespace

BearingConfig bearing_config(const IsolatorConfig& iso) {
  using B = BearingConfig::Model;
  using I = IsolatorConfig::Model;
  BearingConfig c;
  switch (iso.model) {
    case I::kLinear:
      c.model = B::kLinear;
      break;
    case I::kBilinear:
      c.model = B::kBilinear;
      break;
    case I::kBoucWen:
      c.model = B::kBoucWenCoupled;
      break;
    case I::kFrictionPendulum:
      c.model = B::kFrictionPendulum;
      break;
  }
  c.period = iso.period;
  c.strength_ratio = iso.strength_ratio;
  c.yield_displacement = iso.yield_displacement;
  c.bouc_wen = iso.bouc_wen;
  c.strength_is_yield_force = iso.strength_is_yield_force;
  c.carried_mass = iso.carried_mass;
  c.radius = iso.radius;
  c.mu_slow = iso.mu_slow;
  c.mu_fast = iso.mu_fast;
  c.rate_parameter = iso.rate_parameter;
  c.smooth_friction = iso.smooth_friction;
  return c;
}

HysteresisLawConfig bearing_hysteresis_law(const BearingConfig& c) {
  return isolator_hysteresis_law(isolator_config(c));
}

IsolatorProperties bearing_properties(const BearingConfig& c, double m) {
  return isolator_properties(isolator_config(c), m);
}

std::unique_ptr<BiaxialMaterial> make_bearing_material(const BearingConfig& c, double m) {
  if (!(m > 0)) throw std::invalid_argument("bearing: the carried mass must be > 0");
  if (c.model == BearingConfig::Model::kFrictionPendulum) {
    FrictionPendulumParameters fp;
    fp.weight = m * kGravity;
    fp.radius = c.radius;
    fp.mu_slow = c.mu_slow;
    fp.mu_fast = c.mu_fast;
    fp.rate_parameter = c.rate_parameter;
    fp.yield_displacement = c.yield_displacement;
    fp.smooth = c.smooth_friction;
    fp.shape = c.bouc_wen;
    return std::make_unique<FrictionPendulumMaterial>(fp);
  }
  const IsolatorProperties p = bearing_properties(c, m);
  const HysteresisLawConfig law = bearing_hysteresis_law(c);
  switch (c.model) {
    case BearingConfig::Model::kLinear:
      return std::make_unique<LinearBiaxialMaterial>(p.post_yield_stiffness);
    case BearingConfig::Model::kBilinear:
    case BearingConfig::Model::kBoucWenCoupled:
      return make_biaxial_hysteresis(law, isolator_yield_point(p), BiaxialInteraction::kCircular);
    case BearingConfig::Model::kBoucWenUncoupled:
      return make_biaxial_hysteresis(law, isolator_yield_point(p), BiaxialInteraction::kSquare);
    case BearingConfig::Model::kFrictionPendulum:
      break;  // handled above
  }
  throw std::invalid_argument("bearing: unknown model");
}

}  // namespace isopound
