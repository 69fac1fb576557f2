// Coupled biaxial Bouc-Wen: the uniaxial trapezoidal scheme of bouc_wen.cpp applied to the
// vector ODE dz/dl = Phi(z) along the step's straight path, with a chain-ruled tangent dz/dd.
#include "solver/materials/bouc_wen_coupled.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace isopound {

namespace {
constexpr double kMaxSubincrementStiffness = 0.25;  // h |dPhi/dz| per sub-increment
constexpr long kMaxSubincrements = 100000;
constexpr int kMaxNewton = 50;
using Eigen::Matrix2d;
using Eigen::RowVector2d;
using Eigen::Vector2d;
}  // namespace

CoupledBoucWenMaterial::CoupledBoucWenMaterial(const BoucWenParameters& p) : p_(p) {
  if (!(p.elastic_stiffness > 0) || !(p.yield_displacement > 0) || !(p.n >= 1) || !(p.A > 0) ||
      !(p.beta + p.gamma > 0) || !(p.alpha >= 0 && p.alpha < 1))
    throw std::invalid_argument(
        "coupled Bouc-Wen: need K_el > 0, u_y > 0, n >= 1, A > 0, "
        "beta + gamma > 0 and 0 <= alpha < 1");
  z_saturation_ = std::pow(p.A / (p.beta + p.gamma), 1.0 / p.n);
  z_saturation_pow_n_ = p.A / (p.beta + p.gamma);
  z_saturation_sq_ = z_saturation_ * z_saturation_;
  inverse_yield_displacement_ = 1.0 / p.yield_displacement;
  hysteretic_stiffness_ = (1.0 - p.alpha) * p.yield_force / p.yield_displacement;
  hysteretic_energy_ = (1.0 - p.alpha) * p.yield_force * p.yield_displacement / (2.0 * p.A);
  const double z_bound = z_saturation_pow_n_ / z_saturation_;
  z_bound_sq_ = z_bound * z_bound;
  rim_sq_ = z_saturation_ * (1.0 + 1e-12) * z_saturation_ * (1.0 + 1e-12);
  dz_dx_ = p.A * Matrix2d::Identity();
  dz_dx_commit_ = dz_dx_;
}

double CoupledBoucWenMaterial::pow_n_minus_2(double r) const {
  return p_.n == 2.0 ? 1.0 : std::pow(r, p_.n - 2.0);
}

void CoupledBoucWenMaterial::set_trial(const Vector2d& d, const Vector2d&) {
  CoupledBoucWenMaterial* self = this;
  set_trials(&self, &d, 1);
}

void CoupledBoucWenMaterial::commit() {
  d_commit_ = d_;
  z_commit_ = z_;
  dz_dx_commit_ = dz_dx_;
}

void CoupledBoucWenMaterial::revert() {
  d_ = d_commit_;
  z_ = z_commit_;
  dz_dx_ = dz_dx_commit_;
}

// M(z) = A I - g(z) (c o z)^T with g(z) = z |z|^(n-2): Phi = M e on the branch with factors c.
Matrix2d CoupledBoucWenMaterial::phi_matrix(const Vector2d& z, const Vector2d& c) const {
  const double r = z.norm();
  Matrix2d m = p_.A * Matrix2d::Identity();
  if (r > 0.0) m -= (pow_n_minus_2(r) * z) * c.cwiseProduct(z).transpose();
  return m;
}

// dPhi/dz = -(w.z) dg/dz - g w^T, dg/dz = |z|^(n-2) (I + (n-2) z z^T/|z|^2); 0 at z = 0 (n >= 1).
Matrix2d CoupledBoucWenMaterial::phi_jacobian(const Vector2d& z, const Vector2d& w) const {
  const double r = z.norm();
  if (r == 0.0) return Matrix2d::Zero();
  const double p = pow_n_minus_2(r);
  const Matrix2d dg = p * (Matrix2d::Identity() + ((p_.n - 2.0) / (r * r)) * z * z.transpose());
  return -w.dot(z) * dg - (p * z) * w.transpose();
}

double CoupledBoucWenMaterial::phi_parts(const Vector2d& z, const Vector2d& c, const Vector2d& w,
                                         Matrix2d& M, Matrix2d& J) const {
  return phi_parts(z, z.norm(), c, w, M, J);
}

double CoupledBoucWenMaterial::phi_parts(const Vector2d& z, double r, const Vector2d& c,
                                         const Vector2d& w, Matrix2d& M, Matrix2d& J) const {
  // phi_matrix and phi_jacobian with one |z| and one |z|^(n-2) (the inner loop's cost).
  M = p_.A * Matrix2d::Identity();
  if (r == 0.0) {
    J.setZero();
    return r;
  }
  const double p = pow_n_minus_2(r);
  const Vector2d g = p * z;
  M -= g * c.cwiseProduct(z).transpose();
  J = (-w.dot(z) * p) * Matrix2d::Identity() - g * w.transpose();
  if (p_.n != 2.0) J -= (w.dot(z) * p * (p_.n - 2.0) / (r * r)) * z * z.transpose();
  return r;
}

Vector2d CoupledBoucWenMaterial::trapezoid_step(const Vector2d& z, const Vector2d& phi_z, double h,
                                                const Vector2d& e, const Vector2d& c) const {
  const Vector2d w = c.cwiseProduct(e);
  const Vector2d base = z + 0.5 * h * phi_z;
  if (p_.n == 2.0) {
    // z1 + (h/2) (w.z1) z1 = b with b = base + h A e/2: z1 is parallel to b, z1 = lambda b with
    // (h w.b/2) lambda^2 + lambda - 1 = 0; the root continuous in h (uniaxial: the same formula).
    const Vector2d b = base + 0.5 * h * p_.A * e;
    const double discriminant = 1.0 + 2.0 * h * w.dot(b);
    if (discriminant >= 0.0) return (2.0 / (1.0 + std::sqrt(discriminant))) * b;
  }
  // Newton from the explicit predictor; h |dPhi/dz| <= 1/4 makes the Jacobian close to I.
  Vector2d z1 = z + h * phi_z;
  for (int it = 0; it < kMaxNewton; ++it) {
    const Vector2d r = z1 - base - 0.5 * h * (phi_matrix(z1, c) * e);
    const Matrix2d J = Matrix2d::Identity() - 0.5 * h * phi_jacobian(z1, w);
    const Vector2d step = J.inverse() * r;
    z1 -= step;
    if (step.cwiseAbs().maxCoeff() <= 1e-14 * (1.0 + z1.cwiseAbs().maxCoeff())) break;
  }
  return z1;
}

// The common case for n = 2 (a Newton iterate's increment): the whole path is one remainder
// sub-increment (no full sub-increment, no component crossing 0). Then the general scheme below
// reduces to z1 = lambda b (trapezoid_step's closed form) and, because M(z) e = Phi(z) and
// de/dx = (I - e e^T)/l, its chain rule S = (I - l/2 J1)^-1 [(Phi0 + Phi1)/2 e^T + l/2 (M0 + M1)
// de/dx] collapses to S = (I - l/2 J1)^-1 (M0 + M1)/2, with J(z) = -(w.z) I - z w^T and
// M(z) = A I - z (c o z)^T for n = 2. The same scheme; only the rounding differs.
//
// Written without l = |dx| (the step is latency-bound on its square roots and divisions):
// with W = l w = c o dx, l Phi0 = A dx - z0 (W.z0), b = z0 + (l Phi0 + A dx)/2 and
// q = sqrt(1 + 2 W.b), z1 = lambda b with lambda = 2/(1 + q); the matrix inverted,
// m = I - l/2 J1 = a I + z1 W^T/2 with a = 1 + W.z1/2, has a = 1/lambda and
// det m = a (2a - 1) = q (1 + q)/2 exactly, so lambda and 1/det share one division. The tests
// l < h_sub (h |dPhi/dz| <= 1/4 with |dPhi/dz| <= 2 |w| z_b) and "no component reaches 0" are
// taken on squares and products. Returns false (nothing written) when the general path is needed.
bool CoupledBoucWenMaterial::n2_prepare(const Vector2d& z0, const Vector2d& dx, N2Step& s) const {
  const double z0x = z0[0], z0y = z0[1], dx0 = dx[0], dx1 = dx[1];
  const bool unloading0 = z0x * dx0 < 0.0, unloading1 = z0y * dx1 < 0.0;
  const double c0 = p_.beta + (unloading0 ? -p_.gamma : p_.gamma);
  const double c1 = p_.beta + (unloading1 ? -p_.gamma : p_.gamma);
  const double W0 = c0 * dx0, W1 = c1 * dx1;
  const double z_sq = z0x * z0x + z0y * z0y;
  // l < h_sub  <=>  l |w| 2 z_b < 1/4  <=>  4 |W|^2 z_b^2 < (1/4)^2 (z_b = |z0| beyond z_sat).
  const double z_bound_sq = z_sq > z_saturation_sq_ ? z_sq : z_bound_sq_;
  if (!(4.0 * (W0 * W0 + W1 * W1) * z_bound_sq <
        kMaxSubincrementStiffness * kMaxSubincrementStiffness))
    return false;  // full sub-increments: the general path
  const double A = p_.A;
  // l Phi0 + A dx, and a component reaching 0 within the step (the general path splits there):
  // h_i = -2 z0_i / (Phi0_i + A e_i) < l  <=>  -2 z0_i / D_i < 1,  D = l Phi0 + A dx.
  const double s0 = W0 * z0x + W1 * z0y;
  const double D0 = 2.0 * A * dx0 - z0x * s0, D1 = 2.0 * A * dx1 - z0y * s0;
  const auto reaches_zero = [](double z, double D) {
    const double num = -2.0 * z;
    return D > 0.0 ? num < D : D < 0.0 ? num > D : num < 0.0;
  };
  if (unloading0 && reaches_zero(z0x, D0)) return false;
  if (unloading1 && reaches_zero(z0y, D1)) return false;
  const double bx = z0x + 0.5 * D0, by = z0y + 0.5 * D1;
  const double discriminant = 1.0 + 2.0 * (W0 * bx + W1 * by);
  if (!(discriminant > 0.0)) return false;
  s = {z0x, z0y, c0, c1, W0, W1, bx, by, z_sq, discriminant};
  return true;
}

void CoupledBoucWenMaterial::n2_finish(const N2Step& s, double q, double inv, Vector2d& z_out,
                                       Matrix2d& dz_dx_out) const {
  const double A = p_.A;
  const double z0x = s.z0x, z0y = s.z0y, c0 = s.c0, c1 = s.c1, W0 = s.W0, W1 = s.W1;
  const double lambda = 2.0 * q * inv;  // 2 / (1 + q)
  const double inv_det = 2.0 * inv;     // 1 / det m
  const double z1x = lambda * s.bx, z1y = lambda * s.by;
  // (M0 + M1)/2 with M(z) = A I - z (c o z)^T.
  const double r00 = A - 0.5 * (z0x * c0 * z0x + z1x * c0 * z1x);
  const double r01 = -0.5 * (z0x * c1 * z0y + z1x * c1 * z1y);
  const double r10 = -0.5 * (z0y * c0 * z0x + z1y * c0 * z1x);
  const double r11 = A - 0.5 * (z0y * c1 * z0y + z1y * c1 * z1y);
  const double a = 1.0 + 0.5 * (W0 * z1x + W1 * z1y);
  const double m00 = a + 0.5 * z1x * W0, m01 = 0.5 * z1x * W1;
  const double m10 = 0.5 * z1y * W0, m11 = a + 0.5 * z1y * W1;
  Matrix2d S;
  S(0, 0) = (m11 * r00 - m01 * r10) * inv_det;
  S(0, 1) = (m11 * r01 - m01 * r11) * inv_det;
  S(1, 0) = (m00 * r10 - m10 * r00) * inv_det;
  S(1, 1) = (m00 * r11 - m10 * r01) * inv_det;
  Vector2d z(z1x, z1y);
  // Back onto the rim when the trapezoidal map left the disc (as in integrate()).
  if (p_.gamma >= 0.0 && s.z_sq <= rim_sq_) {
    const double r1_sq = z1x * z1x + z1y * z1y;
    if (r1_sq > z_saturation_sq_) {
      const double r1 = std::sqrt(r1_sq);
      const double scale = z_saturation_ / r1;
      const Vector2d n = z / r1;
      S = scale * (Matrix2d::Identity() - n * n.transpose()) * S;
      z *= scale;
    }
  }
  z_out = z;
  dz_dx_out = S;
}

bool CoupledBoucWenMaterial::integrate_single_step_n2(const Vector2d& z0, const Vector2d& dx,
                                                      Vector2d& z_out, Matrix2d& dz_dx_out) const {
  N2Step s;
  if (!n2_prepare(z0, dx, s)) return false;
  const double q = std::sqrt(s.discriminant);
  n2_finish(s, q, 1.0 / (q * (1.0 + q)), z_out, dz_dx_out);
  return true;
}

void CoupledBoucWenMaterial::set_trials(CoupledBoucWenMaterial* const* law, const Vector2d* d,
                                        int n) {
  // Three passes: the closed forms' set-ups, then every square root and division (independent,
  // so they overlap instead of each waiting on the one before), then the rest.
  N2Step steps[kTrialBatch];
  double q[kTrialBatch], inv[kTrialBatch];
  bool fast[kTrialBatch];
  for (int i = 0; i < n; ++i) {
    CoupledBoucWenMaterial& m = *law[i];
    m.d_ = d[i];
    // A product, not a quotient: the division's latency sat on every step's critical path.
    const Vector2d dx = (m.d_ - m.d_commit_) * m.inverse_yield_displacement_;
    // The common case (as integrate() would take it), else integrate() without retrying it.
    fast[i] = m.p_.n == 2.0 && dx.squaredNorm() > 0.0 && m.n2_prepare(m.z_commit_, dx, steps[i]);
    if (!fast[i]) {
      const ZUpdate update = m.integrate(m.z_commit_, dx, false);
      m.z_ = update.z;
      m.dz_dx_ = update.dz_dx;
      steps[i].discriminant = 1.0;  // a harmless operand for the next pass
    }
  }
  for (int i = 0; i < n; ++i) q[i] = std::sqrt(steps[i].discriminant);
  for (int i = 0; i < n; ++i) inv[i] = 1.0 / (q[i] * (1.0 + q[i]));
  for (int i = 0; i < n; ++i)
    if (fast[i]) law[i]->n2_finish(steps[i], q[i], inv[i], law[i]->z_, law[i]->dz_dx_);
}

// Pseudocode of integrate(z0, dx), l = |dx|, e = dx/l, S = dz/dx carried along:
//   repeat (at most 3 branches: each split turns an unloading component into a loading one)
//     c_i = beta - gamma where e_i z_i < 0 (unloading), else beta + gamma; w = c o e
//     h_sub = 1/(4 n |w| z_b^(n-1)) (or l/kMax); full = floor(L/h_sub), rem = L - full h_sub
//     for k = 0..full: if an unloading component reaches 0 within h_sub (closed form) and
//       before L: step exactly onto z_i = 0, L -= distance so far, next branch
//       else step h_sub (k < full) or rem (k = full)
//   every step: S <- (I - h/2 J1)^-1 [(I + h/2 J0) S + (Phi0 + Phi1)/2 dh/dx + h/2 (M0 + M1) de/dx]
CoupledBoucWenMaterial::ZUpdate CoupledBoucWenMaterial::integrate(const Vector2d& z0,
                                                                  const Vector2d& dx,
                                                                  bool closed_form_n2) const {
  const double length_sq = dx.squaredNorm();
  if (length_sq == 0.0) {
    // No increment: the elastic-side (unloading) slope, as the uniaxial law.
    return {z0, phi_matrix(z0, Vector2d::Constant(p_.beta - p_.gamma))};
  }
  if (!std::isfinite(length_sq)) {
    // A diverging Newton iterate: report NaN (the stepper then cuts the step), never loop.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {Vector2d::Constant(nan), Matrix2d::Constant(nan)};
  }
  if (p_.n == 2.0 && closed_form_n2) {
    ZUpdate fast;
    if (integrate_single_step_n2(z0, dx, fast.z, fast.dz_dx)) return fast;
  }
  const double length = std::sqrt(length_sq);
  const Matrix2d I = Matrix2d::Identity();
  const Vector2d e = dx / length;
  const Matrix2d de_dx = (I - e * e.transpose()) / length;

  Vector2d z = z0;
  Matrix2d S = Matrix2d::Zero();  // dz/dx
  bool s_is_zero = true;          // S is still exactly zero (skip its products)
  double L = length;              // length left to integrate
  RowVector2d dL_dx = e.transpose();

  for (int branch = 0; branch < 3; ++branch) {
    const bool unloading[2] = {z[0] * e[0] < 0.0, z[1] * e[1] < 0.0};
    // c from two scalars, not written entry by entry: a packet load of two fresh 8-byte stores
    // stalls (no store forwarding), and it sat on this path's critical chain.
    const Vector2d c(p_.beta + (unloading[0] ? -p_.gamma : p_.gamma),
                     p_.beta + (unloading[1] ? -p_.gamma : p_.gamma));
    const Vector2d w = c.cwiseProduct(e);
    const double w_norm = w.norm();

    // Sub-increment from the largest |dPhi/dz| on the path (|z| <= max(|z_start|, z_sat)).
    const double z_norm = z.norm();
    const bool beyond = z_norm > z_saturation_;
    const double z_bound = beyond ? z_norm : z_saturation_;
    const double bound_pow_n = beyond ? std::pow(z_norm, p_.n) : z_saturation_pow_n_;
    const double max_slope = w_norm * p_.n * bound_pow_n / z_bound;
    const double h_bound = max_slope > 0 ? kMaxSubincrementStiffness / max_slope : 1e300;
    const double h_sub = std::max(h_bound, L / kMaxSubincrements);
    // L / h_sub >= 0: truncation is floor (without libm's call).
    const long full = static_cast<long>(L / h_sub);
    const double remainder = L - static_cast<double>(full) * h_sub;
    // dh_sub/dx matters only when full sub-increments are taken.
    RowVector2d dh_sub_dx = RowVector2d::Zero();
    if (full > 0) {
      if (h_sub != h_bound)
        dh_sub_dx = dL_dx / static_cast<double>(kMaxSubincrements);
      else if (max_slope > 0)  // h_bound = K / |w|, d|w| = (w o c)^T de / |w|
        dh_sub_dx = (-h_bound / (w_norm * w_norm)) * w.cwiseProduct(c).transpose() * de_dx;
    }

    Matrix2d M0, J0;
    phi_parts(z, z_norm, c, w, M0, J0);
    Vector2d phi0 = M0 * e;
    // One trapezoidal step of size h (gradient dh_dx) from (z, phi0, M0, J0), updating S.
    // For gamma >= 0 the exact z never leaves the disc |z| <= z_sat (on its rim
    // d|z|^2/dl = 2 z_sat^n gamma (e.z - sum |e_i z_i|) <= 0), but the trapezoidal map may, by
    // its local error (~1e-6 on a circular orbit): such a step is scaled back onto the rim.
    // A uniaxial step never leaves it (its map is monotone), so this keeps the reduction exact.
    const bool keep_in_disc = p_.gamma >= 0.0 && z_norm <= z_saturation_ * (1.0 + 1e-12);
    const bool n2 = p_.n == 2.0;
    const auto advance = [&](double h, const RowVector2d& dh_dx) {
      const double hh = h > 0.0 ? 0.5 * h : 0.0;
      Vector2d z1;
      Matrix2d M1, J1, m_inverse;
      double r1;
      // n = 2: z1 = lambda b in closed form and, as in integrate_single_step_n2, det(I - h/2 J1)
      // = q (1 + q)/2: one square root and one division; else the general sub-increment.
      const Vector2d b = z + hh * (phi0 + p_.A * e);
      const double discriminant = n2 && h > 0.0 ? 1.0 + 2.0 * h * w.dot(b) : 0.0;
      if (discriminant > 0.0) {
        const double q = std::sqrt(discriminant);
        const double inv = 1.0 / (q * (1.0 + q));
        z1 = (2.0 * q * inv) * b;
        const double s1 = w.dot(z1);
        M1 = p_.A * I - z1 * c.cwiseProduct(z1).transpose();
        J1 = -s1 * I - z1 * w.transpose();
        const Matrix2d m = I - hh * J1;
        m_inverse << m(1, 1), -m(0, 1), -m(1, 0), m(0, 0);
        m_inverse *= 2.0 * inv;
        r1 = keep_in_disc && z1.squaredNorm() > z_saturation_sq_ ? z1.norm() : 0.0;
      } else {
        z1 = h > 0.0 ? trapezoid_step(z, phi0, h, e, c) : z;
        r1 = phi_parts(z1, c, w, M1, J1);
        m_inverse = (I - hh * J1).inverse();
      }
      Vector2d phi1 = M1 * e;
      Matrix2d rhs = 0.5 * (phi0 + phi1) * dh_dx + hh * (M0 + M1) * de_dx;
      if (!s_is_zero) rhs += (I + hh * J0) * S;
      S = m_inverse * rhs;
      s_is_zero = false;
      z = z1;
      if (keep_in_disc && r1 > z_saturation_) {
        // z <- z_sat z/|z|, so dz <- (z_sat/|z|) (I - n n^T) dz.
        const double scale = z_saturation_ / r1;
        const Vector2d n = z1 / r1;
        S = scale * (I - n * n.transpose()) * S;
        z = scale * z1;
        phi_parts(z, c, w, M1, J1);
        phi1 = M1 * e;
      }
      phi0 = phi1;
      M0 = M1;
      J0 = J1;
    };

    double x = 0.0;  // distance travelled on this branch in full sub-increments
    RowVector2d dx_dx = RowVector2d::Zero();
    bool split = false;
    for (long k = 0; k <= full; ++k) {
      // A trapezoidal step landing on z_i = 0 (where Phi_i = A e_i): 0 = z_i + h/2 (Phi_i + A e_i).
      int crossing = -1;
      double to_zero = 0.0;
      for (int i = 0; i < 2; ++i) {
        if (!unloading[i] || !(z[i] * e[i] < 0.0)) continue;
        const double h = -2.0 * z[i] / (phi0[i] + p_.A * e[i]);
        if (h <= h_sub && x + h < L && (crossing < 0 || h < to_zero)) {
          crossing = i;
          to_zero = h;
        }
      }
      if (crossing >= 0) {
        const int i = crossing;
        const double den = phi0[i] + p_.A * e[i];
        const RowVector2d dden = J0.row(i) * S + M0.row(i) * de_dx + p_.A * de_dx.row(i);
        const RowVector2d dh = (-2.0 / den) * S.row(i) + (2.0 * z[i] / (den * den)) * dden;
        advance(to_zero, dh);
        z[i] = 0.0;
        S.row(i).setZero();
        dx_dx += dh;
        L -= x + to_zero;
        dL_dx -= dx_dx;
        split = true;
        break;
      }
      if (k < full) {
        advance(h_sub, dh_sub_dx);
      } else {
        const RowVector2d drem = dL_dx - static_cast<double>(full) * dh_sub_dx;
        advance(remainder, drem);
      }
      x += h_sub;
      dx_dx += dh_sub_dx;
    }
    if (!split) break;
  }
  return {z, S};
}

}  // namespace isopound
