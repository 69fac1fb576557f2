// The element of one 3D bearing: BearingLink with make_bearing_material's law,
// between the ground (or a lower diaphragm) and a diaphragm at plan position p: d = (u - y theta, v
// + x theta), f = T^T F.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "solver/core/element.h"
#include "solver/elements/bearing_link.h"
#include "solver/structures/bearing.h"
#include "solver/structures/isolator.h"

namespace isopound {

// The bearing element for a bearing carrying `carried_mass` at p_OB (relative to the DOFs'
// origin), on the diaphragm `lower` (DiaphragmDofs{}: the ground). Throws std::invalid_argument
// naming the parameter if the law is invalid.
std::unique_ptr<Element> make_bearing_element(const std::string& label, DiaphragmDofs dofs,
                                              const Eigen::Vector2d& p_OB,
                                              const BearingConfig& config, double carried_mass,
                                              DiaphragmDofs lower = {});

// The bearing's secant stiffnesses in each direction (N/m), for damping and modes: post-yield
// K_post (friction pendulum: W/R) and initial K_el (friction pendulum: mu_slow W / u_y + W/R).
struct BearingStiffness {
  double post_yield = 0.0;
  double initial = 0.0;
};
BearingStiffness bearing_stiffness(const BearingConfig& config, double carried_mass);

}  // namespace isopound
