// Isolator laws from the engineer's parameters: derive K_post, F_y, K_el, alpha and build the
// chosen uniaxial law through the hysteresis table (THEORY section 2, eq. 2.4; F_y convention is
// an option).
#include "solver/structures/isolator.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "solver/materials/linear_material.h"

namespace isopound {

IsolatorProperties isolator_properties(const IsolatorConfig& c, double m) {
  if (c.model == IsolatorConfig::Model::kFrictionPendulum) {
    // Pendulum stiffness W/R as K_post, friction at rest mu_slow W as Q, pre-sliding travel u_y.
    if (!(m > 0) || !(c.radius > 0) || !(c.yield_displacement > 0) || !(c.mu_slow >= 0))
      throw std::invalid_argument(
          "friction pendulum: need carried mass > 0, R > 0, uy > 0, mu_slow >= 0");
    IsolatorProperties p;
    p.post_yield_stiffness = m * kGravity / c.radius;
    p.yield_displacement = c.yield_displacement;
    p.characteristic_strength = c.mu_slow * m * kGravity;
    p.yield_force = p.characteristic_strength + p.post_yield_stiffness * c.yield_displacement;
    p.elastic_stiffness = p.yield_force / c.yield_displacement;
    p.alpha = p.post_yield_stiffness / p.elastic_stiffness;
    return p;
  }
  if (!(m > 0) || !(c.period > 0) || !(c.yield_displacement > 0) || !(c.strength_ratio >= 0))
    throw std::invalid_argument("isolator: need carried mass > 0, Tb > 0, uy > 0, QW >= 0");
  IsolatorProperties p;
  const double omega_b = 2.0 * std::numbers::pi / c.period;
  p.post_yield_stiffness = m * omega_b * omega_b;
  p.yield_displacement = c.yield_displacement;
  const double strength = c.strength_ratio * m * kGravity;
  p.yield_force = c.strength_is_yield_force
                      ? strength
                      : strength + p.post_yield_stiffness * c.yield_displacement;
  p.elastic_stiffness = p.yield_force / c.yield_displacement;
  p.alpha = p.elastic_stiffness > 0 ? p.post_yield_stiffness / p.elastic_stiffness : 1.0;
  p.characteristic_strength = (1.0 - p.alpha) * p.yield_force;
  if (c.model != IsolatorConfig::Model::kLinear && !(p.alpha < 1.0))
    throw std::invalid_argument("isolator: the yield force is not above K_post u_y (alpha = " +
                                std::to_string(p.alpha) + " >= 1); raise QW or uy, or lengthen Tb");
  return p;
}

HysteresisLawConfig isolator_hysteresis_law(const IsolatorConfig& c) {
  HysteresisLawConfig law;
  if (c.model == IsolatorConfig::Model::kBilinear) law.model = HysteresisModel::kBilinear;
  if (c.model == IsolatorConfig::Model::kBoucWen) law.model = HysteresisModel::kBoucWen;
  law.bouc_wen = c.bouc_wen;
  return law;
}

YieldPoint isolator_yield_point(const IsolatorProperties& p) {
  return {p.elastic_stiffness, p.yield_force, p.yield_displacement, p.alpha, 0.0};
}

std::unique_ptr<UniaxialMaterial> make_isolator_material(const IsolatorConfig& c, double m) {
  const IsolatorProperties p = isolator_properties(c, m);
  switch (c.model) {
    case IsolatorConfig::Model::kLinear:
      return std::make_unique<LinearMaterial>(p.post_yield_stiffness);
    case IsolatorConfig::Model::kBilinear:
    case IsolatorConfig::Model::kBoucWen:
      return make_uniaxial_hysteresis(isolator_hysteresis_law(c), isolator_yield_point(p));
    case IsolatorConfig::Model::kFrictionPendulum:
      throw std::invalid_argument(
          "isolator: the friction pendulum is rate dependent, not a uniaxial law; build it with "
          "make_bearing_material (solver/structures/bearing.h)");
  }
  throw std::invalid_argument("isolator: unknown model");
}

double isolation_period(const IsolatorConfig& c) {
  if (c.model == IsolatorConfig::Model::kFrictionPendulum)
    return 2.0 * std::numbers::pi * std::sqrt(c.radius / kGravity);
  return c.period;
}

}  // namespace isopound
