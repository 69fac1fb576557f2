// P-Delta of a 3D storey (issue 23 item 3): the geometric stiffness of the gravity load above.
//
// Derivation. Storey s carries the weight of every level above it. Let that weight reach the
// storey's columns in proportion to where the mass above is in plan (a mass element dm at plan
// point p loads the column line under it with g dm). A relative drift of the storey moves that
// point by d(p) = T(p) dq (T = [[1, 0, -y], [0, 1, x]], dq = q_upper - q_lower); the load g dm
// over the height h, leaning by d(p)/h, pushes the upper diaphragm along d with the force
// g dm d(p) / h (a destabilising spring of stiffness -g dm / h). Its generalised force on
// (u, v, theta) is T(p)^T (g dm / h) T(p) dq, so summed over the masses above
//   k_G = -(g / h) int T(p)^T T(p) dm = -(g / h) sum_{levels above} M_level,
// with M_level each level's 3 x 3 mass matrix about the plan origin (building3d.h,
// diaphragm_mass). Its translational entries are -P/h (P = g m_above), its torsional entry
// -(P/h) (I_p / m_above) with I_p the polar moment of the masses above about the plan origin
// (the polar radius of gyration squared), and the off-diagonal terms the offset of their centre
// of mass. It is placed between the two levels as a storey stiffness ([k, -k; -k, k]), constant
// (small rotations; the axial load does not change with the lateral motion).
#include <stdexcept>

#include "solver/core/constants.h"
#include "solver/structures/building3d.h"

namespace isopound {

Eigen::Matrix3d p_delta_stiffness(const Building3DConfig& b, std::size_t storey) {
  if (storey >= b.storeys.size()) throw std::invalid_argument("P-Delta: no such storey");
  const double h = b.storeys[storey].height;
  Eigen::Matrix3d mass_above = Eigen::Matrix3d::Zero();
  for (std::size_t l = storey; l < b.storeys.size(); ++l) {
    mass_above += diaphragm_mass(diaphragm_in_plan(b, b.storeys[l].floor), b.polar_moment_rule);
  }
  return -(kGravity / h) * mass_above;
}

}  // namespace isopound
