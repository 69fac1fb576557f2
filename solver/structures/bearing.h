// One isolation bearing of a 3D building (or the 2D isolation layer) from the engineer's
// numbers: K_post = m (2 pi/T_b)^2, Q = (Q/W) m g, F_y = Q + K_post u_y (THEORY eq. 2.4, 5.27-5.29).
#pragma once

#include <memory>

#include "solver/materials/biaxial_material.h"

namespace isopound {

// Plain configuration of a bearing law; SI, ratios as fractions. Filled from YAML in solver/io.
struct BearingConfig {
  enum class Model {
    kLinear,             // F = K_eff d in each direction
    kBilinear,           // biaxial elastic-plastic, circular yield surface, kinematic hardening
    kBoucWenCoupled,     // THEORY eq. 5.28 (circular interaction)
    kBoucWenUncoupled,   // two uniaxial Bouc-Wen laws (square interaction)
    kFrictionPendulum,   // single concave surface: F = W d/R + mu(v) W z, circular interaction
  };
  Model model = Model::kBoucWenCoupled;
  double period = 2.0;               // T_b, s (not used by the friction pendulum)
  double strength_ratio = 0.05;      // Q/W (not used by the friction pendulum)
  double yield_displacement = 0.01;  // u_y, m (friction pendulum: the sliding onset, ~0.5 mm)
  double n = 2.0, A = 1.0, beta = 0.5, gamma = 0.5;  // Bouc-Wen shape
  bool strength_is_yield_force = false;  // true: (Q/W) m g is F_y itself
  // Mass carried by this bearing, kg; 0: the structure's total mass / number of bearings.
  double carried_mass = 0.0;
  // Friction pendulum: radius of the concave surface and mu(v) = mu_fast - (mu_fast -
  // mu_slow) exp(-rate_parameter |v|).
  double radius = 0.0;          // R, m
  double mu_slow = 0.0;         // -
  double mu_fast = 0.0;         // -
  double rate_parameter = 0.0;  // a, s/m
};

// The bearing law for a bearing carrying `carried_mass` (kg, > 0). Throws std::invalid_argument
// with a message naming the offending parameter if the numbers give no valid law.
std::unique_ptr<BiaxialMaterial> make_bearing_material(const BearingConfig& config,
                                                       double carried_mass);

}  // namespace isopound
