// One isolation bearing of a 3D building (or the 2D isolation layer) from the engineer's
// numbers: K_post = m (2 pi/T_b)^2, Q = (Q/W) m g, F_y = Q + K_post u_y (THEORY
// eq. 2.4, 5.27-5.29).
#pragma once

#include <memory>

#include "solver/materials/biaxial_material.h"
#include "solver/structures/config.h"
#include "solver/structures/isolator.h"

namespace isopound {

// Plain configuration of a bearing law; SI, ratios as fractions. Filled from YAML in solver/io.
struct BearingConfig {
  enum class Model {
    kLinear,            // F = K_eff d in each direction
    kBilinear,          // biaxial elastic-plastic, circular yield surface, kinematic hardening
    kBoucWenCoupled,    // THEORY eq. 5.28 (circular interaction)
    kBoucWenUncoupled,  // two uniaxial Bouc-Wen laws (square interaction)
    kFrictionPendulum,  // single concave surface: F = W d/R + mu(v) W z, circular interaction
  };
  Model model = Model::kBoucWenCoupled;
  double period = 2.0;               // T_b, s (not used by the friction pendulum)
  double strength_ratio = 0.05;      // Q/W (not used by the friction pendulum)
  double yield_displacement = 0.01;  // u_y, m (friction pendulum: the sliding onset, ~0.5 mm)
  BoucWenShape bouc_wen;             // Bouc-Wen shape (also of the pendulum's smooth z)
  bool strength_is_yield_force = false;  // true: (Q/W) m g is F_y itself
  // Mass carried by this bearing, kg; 0: the structure's total mass / number of bearings.
  double carried_mass = 0.0;
  // Friction pendulum: radius of the concave surface and mu(v) = mu_fast - (mu_fast -
  // mu_slow) exp(-rate_parameter |v|).
  double radius = 0.0;          // R, m
  double mu_slow = 0.0;         // -
  double mu_fast = 0.0;         // -
  double rate_parameter = 0.0;  // a, s/m
  // Friction pendulum z: false = elastic-perfectly-plastic, radial return (default, sharp);
  // true = the coupled Bouc-Wen z of the shape above (smooth corners).
  bool smooth_friction = false;
};

// The bearing's constants (K_post, F_y, K_el, alpha, u_y, Q) by the 2D rules, for modes and
// Rayleigh damping (K_post; the friction pendulum: W/R, Q = mu_slow W). Throws as above.
IsolatorProperties bearing_properties(const BearingConfig& config, double carried_mass);

// The same bearing law as a 2D isolator: the BearingConfig of an IsolatorConfig (uniaxial
// models map to their biaxial counterparts; bouc_wen to the coupled law).
BearingConfig bearing_config(const IsolatorConfig& isolator);

// The bearing's law in the hysteresis table (bouc_wen for both Bouc-Wen models; elastic for the
// linear model and the friction pendulum).
HysteresisLawConfig bearing_hysteresis_law(const BearingConfig& config);

// The bearing law for a bearing carrying `carried_mass` (kg, > 0). Throws std::invalid_argument
// with a message naming the offending parameter if the numbers give no valid law.
std::unique_ptr<BiaxialMaterial> make_bearing_material(const BearingConfig& config,
                                                       double carried_mass);

}  // namespace isopound
