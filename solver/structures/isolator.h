// Isolator laws from the engineer's parameters (T_b, Q/W, u_y): linear, sharp bilinear and
// Bouc-Wen. K_post = m (2 pi/T_b)^2, Q = (Q/W) m g, F_y = Q + K_post u_y (THEORY eq. 2.4).
#pragma once

#include <memory>

#include "solver/core/constants.h"
#include "solver/materials/hysteresis_law.h"
#include "solver/structures/config.h"

namespace isopound {

// Mechanical constants of an isolation system, derived from IsolatorConfig and the mass.
struct IsolatorProperties {
  double post_yield_stiffness = 0.0;     // K_post, N/m
  double yield_force = 0.0;              // F_y, N
  double elastic_stiffness = 0.0;        // K_el = F_y / u_y, N/m
  double alpha = 0.0;                    // K_post / K_el
  double yield_displacement = 0.0;       // u_y, m
  double characteristic_strength = 0.0;  // (1 - alpha) F_y, N (= Q by default)
};

// Throws std::invalid_argument if the parameters give no valid law (e.g. alpha >= 1).
IsolatorProperties isolator_properties(const IsolatorConfig& config, double carried_mass);

// The isolator's law in the hysteresis table (bilinear or bouc_wen with the config's shape;
// elastic for the linear model and the friction pendulum, which are not table laws) and its yield
// point K_el, F_y, u_y, alpha: the one construction of the uniaxial isolator and the bearings.
HysteresisLawConfig isolator_hysteresis_law(const IsolatorConfig& config);
YieldPoint isolator_yield_point(const IsolatorProperties& p);

// The friction pendulum has no uniaxial law (it is rate dependent): this throws for it; the 2D
// building uses make_bearing_material and a BearingLink instead.
std::unique_ptr<UniaxialMaterial> make_isolator_material(const IsolatorConfig& config,
                                                         double carried_mass);

// Isolation period: T_b, or 2 pi sqrt(R/g) for the friction pendulum (the sliding period).
double isolation_period(const IsolatorConfig& config);

}  // namespace isopound
