// A column struck between two rigid diaphragms: an Euler-Bernoulli beam [0, L] with both end
// rotations fixed by the slabs and a lateral node at z = a, as two beam elements [0, a], [a, L]
// whose node rotation is condensed statically; plastic hinges at both ends and at the node.
// Elastic: with the node free, the storey sees exactly 12 E I / L^3; with the floors held, the
// node 3 E I L^3 / (a^3 b^3), b = L - a. Hinges (backward Euler, exact for this piecewise
// linear law): the hinge rotations p minimise
//   Pi(u, theta, p) + H/2 sum p_h^2 + M_y sum |p_h - p_h,committed|,
// so |m_h + H p_h| <= M_y (linear kinematic hardening H, hinge moment m_h = dPi/dp_h), and the
// hinges dissipate M_y sum |dp| >= 0. Beam stiffness: Przemieniecki, Theory of Matrix Structural
// Analysis (1968), eq. 5.116.
#pragma once

#include <Eigen/Dense>
#include <array>

namespace isopound {

// One column, SI. hardening: H, N m/rad, of each hinge (> 0 keeps the node stable when all three
// hinges have formed).
struct HingedColumnSection {
  double E = 0.0, I = 0.0;    // Pa, m^4
  double length = 0.0;        // L, m, between the two diaphragms
  double node = 0.0;          // a, m, the struck point above the lower diaphragm, 0 < a < L
  double yield_moment = 0.0;  // M_y, N m (0: elastic, no hinges)
  double hardening = 0.0;     // H, N m/rad
};

// The column's displacements (u_lower, u_node, u_upper), m, and its hinges' plastic rotations
// (bottom, node, top), rad.
using ColumnDisplacements = Eigen::Vector3d;
using HingeRotations = Eigen::Vector3d;

struct ColumnState {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();    // on (lower, node, upper), N
  Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();  // d force / d u, N/m
  HingeRotations plastic = HingeRotations::Zero();    // p, rad
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();   // at bottom, node, top, N m
  double shear_lower = 0.0, shear_upper = 0.0;        // in [0, a] and [a, L], N
  double stored_energy = 0.0;                         // elastic + hardening, J
};

class HingedColumn {
 public:
  explicit HingedColumn(const HingedColumnSection& section);

  // The state for displacements u from the committed hinge rotations (no allocation).
  ColumnState respond(const ColumnDisplacements& u, const HingeRotations& committed) const;

  const HingedColumnSection& section() const { return s_; }
  // 12 E I / L^3: the column's share of the storey stiffness, N/m.
  double storey_stiffness() const;
  // 3 E I L^3 / (a^3 b^3): the node against the floors held fixed, N/m.
  double local_stiffness() const;
  // The elastic deflected shape of a fixed-fixed column at the node: (3 xi^2 - 2 xi^3), xi = a/L.
  double shape_at_node() const;

 private:
  // Solves for y = (theta, p) with the hinges of active set `code` (set_signs) for y and
  // returns false when that set is not the solution (any: take it regardless).
  bool try_active_set(const Eigen::Vector3d& u, const HingeRotations& committed, int code,
                      ColumnState& out, bool any) const;
  // Active set `code` (0 ... 26, base 3 per hinge: 0 elastic, 1 flowing +, 2 flowing -).
  static void set_signs(int code, int active[3]);

  // Per active set, what does not depend on u: the factors of its 4 x 4 system and the tangent
  // they give (the same operations as factoring at each call, so the same bits, once).
  struct ActiveSet {
    Eigen::PartialPivLU<Eigen::Matrix4d> lu;
    Eigen::Matrix3d tangent;
  };
  std::array<ActiveSet, 27> sets_;
  std::array<int, 27> flowing_;  // the number of flowing hinges of each set

  HingedColumnSection s_;
  // Stiffness of both elements in q = (u_lower, u_node, u_upper, theta, p_b, p_n, p_t), split
  // into u (3) and y = (theta, p) (4).
  Eigen::Matrix3d k_uu_;
  Eigen::Matrix<double, 3, 4> k_uy_;
  Eigen::Matrix<double, 4, 3> k_yu_;
  Eigen::Matrix4d k_yy_;
  // Element end forces from q: rows (V_1a, M_1a, V_1b, M_1b) of [0, a] and of [a, L].
  Eigen::Matrix<double, 4, 7> end_lower_, end_upper_;
};

}  // namespace isopound
