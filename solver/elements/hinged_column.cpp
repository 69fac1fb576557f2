// A struck column: two beam elements, node rotation condensed, three plastic hinges solved by
// their active set (each hinge elastic or flowing one way: at most 27 sets of a 4 x 4 system).
#include "solver/elements/hinged_column.h"

#include <cmath>
#include <stdexcept>

namespace isopound {

namespace {

// Euler-Bernoulli beam (v1, phi1, v2, phi2), length l.
Eigen::Matrix4d beam_stiffness(double EI, double l) {
  Eigen::Matrix4d k;
  k << 12, 6 * l, -12, 6 * l,               //
      6 * l, 4 * l * l, -6 * l, 2 * l * l,  //
      -12, -6 * l, 12, -6 * l,              //
      6 * l, 2 * l * l, -6 * l, 4 * l * l;
  return k * (EI / (l * l * l));
}

using Vector7d = Eigen::Matrix<double, 7, 1>;

}  // namespace

HingedColumn::HingedColumn(const HingedColumnSection& section) : s_(section) {
  if (!(s_.E > 0 && s_.I > 0 && s_.length > 0 && s_.node > 0 && s_.node < s_.length &&
        s_.yield_moment >= 0 && s_.hardening >= 0))
    throw std::invalid_argument("struck column: E, I, L > 0, 0 < a < L, M_y >= 0, H >= 0");
  const double a = s_.node, b = s_.length - s_.node, EI = s_.E * s_.I;
  // q = (u_lower, u_node, u_upper, theta, p_b, p_n, p_t). [0, a]: (u_lower, p_b, u_node,
  // theta); [a, L]: (u_node, theta + p_n, u_upper, p_t) (the hinge's jump on its upper side).
  Eigen::Matrix<double, 4, 7> t1 = Eigen::Matrix<double, 4, 7>::Zero();
  Eigen::Matrix<double, 4, 7> t2 = Eigen::Matrix<double, 4, 7>::Zero();
  t1(0, 0) = 1, t1(1, 4) = 1, t1(2, 1) = 1, t1(3, 3) = 1;
  t2(0, 1) = 1, t2(1, 3) = 1, t2(1, 5) = 1, t2(2, 2) = 1, t2(3, 6) = 1;
  end_lower_ = beam_stiffness(EI, a) * t1;
  end_upper_ = beam_stiffness(EI, b) * t2;
  const Eigen::Matrix<double, 7, 7> k = t1.transpose() * end_lower_ + t2.transpose() * end_upper_;
  k_uu_ = k.topLeftCorner<3, 3>();
  k_uy_ = k.topRightCorner<3, 4>();
  k_yu_ = k.bottomLeftCorner<4, 3>();
  k_yy_ = k.bottomRightCorner<4, 4>();
  for (int code = 0; code < 27; ++code) {
    int active[3];
    set_signs(code, active);
    Eigen::Matrix4d A = k_yy_;
    Eigen::Matrix<double, 4, 3> B = k_yu_;
    flowing_[code] = 0;
    for (int i = 0; i < 3; ++i) {
      flowing_[code] += active[i] != 0;
      if (active[i] == 0) {
        A.row(i + 1).setZero();
        A(i + 1, i + 1) = 1.0;
        B.row(i + 1).setZero();
      } else {
        A(i + 1, i + 1) += s_.hardening;
      }
    }
    sets_[code].lu.compute(A);
    sets_[code].tangent = k_uu_ - k_uy_ * sets_[code].lu.solve(B);
  }
}

double HingedColumn::storey_stiffness() const {
  return 12.0 * s_.E * s_.I / (s_.length * s_.length * s_.length);
}

double HingedColumn::local_stiffness() const {
  const double a = s_.node, b = s_.length - s_.node, L = s_.length;
  return 3.0 * s_.E * s_.I * L * L * L / (a * a * a * b * b * b);
}

double HingedColumn::shape_at_node() const {
  const double xi = s_.node / s_.length;
  return xi * xi * (3.0 - 2.0 * xi);
}

void HingedColumn::set_signs(int code, int active[3]) {
  for (int i = 0; i < 3; ++i, code /= 3) active[i] = code % 3 == 0 ? 0 : (code % 3 == 1 ? 1 : -1);
}

bool HingedColumn::try_active_set(const Eigen::Vector3d& u, const HingeRotations& committed,
                                  int code, ColumnState& out, bool any) const {
  const double my = s_.yield_moment, h = s_.hardening;
  int active[3];
  set_signs(code, active);
  // Row 0: the node's moment equilibrium; row 1 + i: hinge i held (p = committed) or on its
  // yield surface m + H p = -sign(dp) M_y (the matrix factored once: sets_).
  Eigen::Vector4d rhs = -k_yu_ * u;
  for (int i = 0; i < 3; ++i) {
    if (active[i] == 0)
      rhs(i + 1) = committed(i);
    else
      rhs(i + 1) -= my * active[i];
  }
  const ActiveSet& set = sets_[code];
  const Eigen::Vector4d y = set.lu.solve(rhs);
  const Eigen::Vector4d r = k_yu_ * u + k_yy_ * y;  // (node moment, hinge moments m)
  for (int i = 0; i < 3; ++i) {
    const double dp = y(i + 1) - committed(i);
    if (any) break;
    if (active[i] != 0 && active[i] * dp < -1e-15) return false;
    if (active[i] == 0 && std::abs(r(i + 1) + h * y(i + 1)) > my * (1.0 + 1e-12)) return false;
  }
  out.plastic = y.tail<3>();
  out.force = k_uu_ * u + k_uy_ * y;
  out.tangent = set.tangent;
  out.moment = r.tail<3>();
  Vector7d q;
  q << u, y;
  out.shear_lower = (end_lower_ * q)(0);
  out.shear_upper = (end_upper_ * q)(0);
  out.stored_energy = 0.5 * (u.dot(out.force) + y.dot(r)) + 0.5 * h * out.plastic.squaredNorm();
  return true;
}

ColumnState HingedColumn::respond(const ColumnDisplacements& u,
                                  const HingeRotations& committed) const {
  ColumnState out;
  constexpr int kElastic = 0;
  if (try_active_set(u, committed, kElastic, out, !(s_.yield_moment > 0))) return out;
  // The flowing hinges: the minimisation is strictly convex, so exactly one set fits; fewer
  // active hinges first.
  for (int count = 1; count <= 3; ++count)
    for (int code = 0; code < 27; ++code)
      if (flowing_[code] == count && try_active_set(u, committed, code, out, false)) return out;
  // Round-off at a set's border: the elastic solution (the next iteration moves off it).
  try_active_set(u, committed, kElastic, out, true);
  return out;
}

}  // namespace isopound
