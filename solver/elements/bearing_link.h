// A bearing between the ground and a rigid diaphragm at plan position p = (x, y) relative to
// the diaphragm's DOF origin: deformation d = (u - y theta, v + x theta), force F(d) on the slab.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "solver/core/element.h"
#include "solver/materials/biaxial_material.h"

namespace isopound {

// DOF indices of the diaphragm the bearing carries; -1 for a DOF the model does not have
// (a 2D building has only ux: dof_uy = dof_theta = -1, and the bearing acts along x only).
struct DiaphragmDofs {
  int ux = -1, uy = -1, theta = -1;
};

// Generalised force on the diaphragm: f = T^T F with T = [[1, 0, -y], [0, 1, x]] (x, y the
// bearing's position in the diaphragm DOFs' frame); tangent T^T (K + velocity_factor K_v) T.
class BearingLink final : public Element {
 public:
  BearingLink(std::string label, DiaphragmDofs dofs, Eigen::Vector2d p_OB,
              std::unique_ptr<BiaxialMaterial> law);
  // ... Element overrides; outputs: force x, y, resultant; deformation x, y, resultant; z x, y.
};

}  // namespace isopound
