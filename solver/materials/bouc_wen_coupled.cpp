// Coupled biaxial Bouc-Wen: the uniaxial trapezoidal scheme of bouc_wen.cpp applied to the
// vector ODE dz/dl = Phi(z) along the step's straight path, with a chain-ruled tangent dz/dd.
#include "solver/materials/bouc_wen_coupled.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solver/core/packed_math.h"

namespace isopound {

namespace {
constexpr double kMaxSubincrementStiffness = 0.25;  // h |dPhi/dz| per sub-increment
constexpr long kMaxSubincrements = 100000;
constexpr int kMaxNewton = 50;
// A component of z within this of 0 (relative to z_sat) is taken as 0 at the start of a branch:
// it is on neither side of 0, so its branch is the loading one and no split waits for its
// crossing. Split there, the crossing point's gradient 2 z_i / (Phi_i + A e_i)^2 blows up when
// e_i is as small (a push along an axis: z_i and e_i both round-off, the tangent then ~1e19 and
// Newton never converges, issue 37).
constexpr double kNegligibleZ = 1e-12;
using Eigen::Matrix2d;
using Eigen::RowVector2d;
using Eigen::Vector2d;

// A closed-form test's masks combined, for one law (bool) or two lanes (integer masks).
inline bool both(bool a, bool b) {
  return a && b;
}
inline bool and_not(bool a, bool b) {
  return a && !b;
}
template <class Mask>
Mask both(Mask a, Mask b) {
  return a & b;
}
template <class Mask>
Mask and_not(Mask a, Mask b) {
  return a & ~b;
}
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
template <class T>
decltype(T() < T()) CoupledBoucWenMaterial::n2_setup(const N2Parameters<T>& p, T z0x, T z0y, T dx0,
                                                     T dx1, N2Terms<T>& s) {
  const T zero = T();
  // A component at round-off from 0 is 0 (kNegligibleZ), as branch_start() takes it.
  const T negligible_sq = kNegligibleZ * kNegligibleZ * p.z_saturation_sq;
  z0x = z0x * z0x <= negligible_sq ? zero : z0x;
  z0y = z0y * z0y <= negligible_sq ? zero : z0y;
  const auto unloading0 = z0x * dx0 < zero, unloading1 = z0y * dx1 < zero;
  const T c0 = p.beta + (unloading0 ? -p.gamma : p.gamma);
  const T c1 = p.beta + (unloading1 ? -p.gamma : p.gamma);
  const T W0 = c0 * dx0, W1 = c1 * dx1;
  const T z_sq = z0x * z0x + z0y * z0y;
  // l < h_sub  <=>  l |w| 2 z_b < 1/4  <=>  4 |W|^2 z_b^2 < (1/4)^2 (z_b = |z0| beyond z_sat);
  // else full sub-increments: the general path.
  const T z_bound_sq = z_sq > p.z_saturation_sq ? z_sq : p.z_bound_sq;
  auto fast = 4.0 * (W0 * W0 + W1 * W1) * z_bound_sq <
              zero + kMaxSubincrementStiffness * kMaxSubincrementStiffness;
  const T A = p.A;
  // l Phi0 + A dx, and a component reaching 0 within the step (the general path splits there):
  // h_i = -2 z0_i / (Phi0_i + A e_i) < l  <=>  -2 z0_i / D_i < 1,  D = l Phi0 + A dx.
  const T s0 = W0 * z0x + W1 * z0y;
  const T D0 = 2.0 * A * dx0 - z0x * s0, D1 = 2.0 * A * dx1 - z0y * s0;
  const auto reaches_zero = [&](const T& z, const T& D) {
    const T num = -2.0 * z;
    return D > zero ? num < D : (D < zero ? num > D : num < zero);
  };
  fast = and_not(fast, both(unloading0, reaches_zero(z0x, D0)));
  fast = and_not(fast, both(unloading1, reaches_zero(z0y, D1)));
  const T bx = z0x + 0.5 * D0, by = z0y + 0.5 * D1;
  const T discriminant = 1.0 + 2.0 * (W0 * bx + W1 * by);
  fast = both(fast, discriminant > zero);
  s = {z0x, z0y, c0, c1, W0, W1, bx, by, z_sq, discriminant};
  return fast;
}

template <class T>
void CoupledBoucWenMaterial::n2_map(const T& A, const N2Terms<T>& s, const T& q, const T& inv,
                                    T& z1x, T& z1y, T S[4]) {
  const T z0x = s.z0x, z0y = s.z0y, c0 = s.c0, c1 = s.c1, W0 = s.W0, W1 = s.W1;
  const T lambda = 2.0 * q * inv;  // 2 / (1 + q)
  const T inv_det = 2.0 * inv;     // 1 / det m
  z1x = lambda * s.bx;
  z1y = lambda * s.by;
  // (M0 + M1)/2 with M(z) = A I - z (c o z)^T.
  const T r00 = A - 0.5 * (z0x * c0 * z0x + z1x * c0 * z1x);
  const T r01 = -0.5 * (z0x * c1 * z0y + z1x * c1 * z1y);
  const T r10 = -0.5 * (z0y * c0 * z0x + z1y * c0 * z1x);
  const T r11 = A - 0.5 * (z0y * c1 * z0y + z1y * c1 * z1y);
  const T a = 1.0 + 0.5 * (W0 * z1x + W1 * z1y);
  const T m00 = a + 0.5 * z1x * W0, m01 = 0.5 * z1x * W1;
  const T m10 = 0.5 * z1y * W0, m11 = a + 0.5 * z1y * W1;
  S[0] = (m11 * r00 - m01 * r10) * inv_det;
  S[1] = (m11 * r01 - m01 * r11) * inv_det;
  S[2] = (m00 * r10 - m10 * r00) * inv_det;
  S[3] = (m00 * r11 - m10 * r01) * inv_det;
}

bool CoupledBoucWenMaterial::n2_prepare(const Vector2d& z0, const Vector2d& dx, N2Step& s) const {
  return n2_setup<double>(n2_parameters(), z0[0], z0[1], dx[0], dx[1], s);
}

void CoupledBoucWenMaterial::n2_finish(const N2Step& s, double q, double inv, Vector2d& z_out,
                                       Matrix2d& dz_dx_out) const {
  double z1x, z1y, S[4];
  n2_map<double>(p_.A, s, q, inv, z1x, z1y, S);
  z_out = Vector2d(z1x, z1y);
  dz_dx_out << S[0], S[1], S[2], S[3];
  n2_rim(s, z_out, dz_dx_out);
}

void CoupledBoucWenMaterial::n2_rim(const N2Step& s, Vector2d& z, Matrix2d& S) const {
  // Back onto the rim when the trapezoidal map left the disc (as in integrate()).
  if (p_.gamma >= 0.0 && s.z_sq <= rim_sq_) {
    const double r1_sq = z[0] * z[0] + z[1] * z[1];
    if (r1_sq > z_saturation_sq_) {
      const double r1 = std::sqrt(r1_sq);
      const double scale = z_saturation_ / r1;
      const Vector2d n = z / r1;
      S = scale * (Matrix2d::Identity() - n * n.transpose()) * S;
      z *= scale;
    }
  }
}

#if defined(ISOPOUND_PAIRED_N2)
namespace {
// Two lanes of doubles (GCC's vector extension: element-wise IEEE operations, as the scalars).
typedef double Lanes __attribute__((vector_size(16)));
}  // namespace

// n2_prepare() of laws a and b at once (both steps are written).
void CoupledBoucWenMaterial::n2_prepare_two(const CoupledBoucWenMaterial& a,
                                            const CoupledBoucWenMaterial& b, const Vector2d& dx_a,
                                            const Vector2d& dx_b, N2Step& s_a, N2Step& s_b,
                                            bool& fast_a, bool& fast_b) {
  const N2Parameters<double> p_a = a.n2_parameters(), p_b = b.n2_parameters();
  const N2Parameters<Lanes> p = {{p_a.beta, p_b.beta},
                                 {p_a.gamma, p_b.gamma},
                                 {p_a.A, p_b.A},
                                 {p_a.z_saturation_sq, p_b.z_saturation_sq},
                                 {p_a.z_bound_sq, p_b.z_bound_sq}};
  N2Terms<Lanes> s;
  const auto fast = n2_setup<Lanes>(p, Lanes{a.z_commit_[0], b.z_commit_[0]},
                                    Lanes{a.z_commit_[1], b.z_commit_[1]}, Lanes{dx_a[0], dx_b[0]},
                                    Lanes{dx_a[1], dx_b[1]}, s);
  fast_a = fast[0] != 0;
  fast_b = fast[1] != 0;
  const auto lane = [&](int k) {
    return N2Step{s.z0x[k], s.z0y[k], s.c0[k], s.c1[k],   s.W0[k],
                  s.W1[k],  s.bx[k],  s.by[k], s.z_sq[k], s.discriminant[k]};
  };
  s_a = lane(0);
  s_b = lane(1);
}

// n2_finish() of laws a and b at once.
void CoupledBoucWenMaterial::n2_finish_two(CoupledBoucWenMaterial& a, CoupledBoucWenMaterial& b,
                                           const N2Step& s_a, const N2Step& s_b, double q_a,
                                           double q_b, double inv_a, double inv_b) {
  const N2Terms<Lanes> s = {{s_a.z0x, s_b.z0x},   {s_a.z0y, s_b.z0y},
                            {s_a.c0, s_b.c0},     {s_a.c1, s_b.c1},
                            {s_a.W0, s_b.W0},     {s_a.W1, s_b.W1},
                            {s_a.bx, s_b.bx},     {s_a.by, s_b.by},
                            {s_a.z_sq, s_b.z_sq}, {s_a.discriminant, s_b.discriminant}};
  Lanes z1x, z1y, S[4];
  n2_map<Lanes>(Lanes{a.p_.A, b.p_.A}, s, Lanes{q_a, q_b}, Lanes{inv_a, inv_b}, z1x, z1y, S);
  a.z_ = Vector2d(z1x[0], z1y[0]);
  b.z_ = Vector2d(z1x[1], z1y[1]);
  a.dz_dx_ << S[0][0], S[1][0], S[2][0], S[3][0];
  b.dz_dx_ << S[0][1], S[1][1], S[2][1], S[3][1];
  a.n2_rim(s_a, a.z_, a.dz_dx_);
  b.n2_rim(s_b, b.z_, b.dz_dx_);
}
#endif

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
  // Passes: the closed forms' set-ups (two laws at a time where the lanes are available), the
  // general paths' starts, their sub-increments, then every closed form's square root and
  // division (independent, so they overlap instead of each waiting on the one before), then the
  // closed forms' rest.
  Vector2d dx[kTrialBatch];
  double length_sq[kTrialBatch];
  int closed[kTrialBatch];  // the laws that may take the closed form, then those that do
  int n_closed = 0;
  for (int i = 0; i < n; ++i) {
    CoupledBoucWenMaterial& m = *law[i];
    m.d_ = d[i];
    // A product, not a quotient: the division's latency sat on every step's critical path.
    dx[i] = (m.d_ - m.d_commit_) * m.inverse_yield_displacement_;
    length_sq[i] = dx[i].squaredNorm();
    // The common case (as integrate() would take it), else integrate() without retrying it.
    if (m.p_.n == 2.0 && length_sq[i] > 0.0) closed[n_closed++] = i;
  }
  N2Step steps[kTrialBatch];
  bool fast[kTrialBatch] = {};
  int k = 0;
#if defined(ISOPOUND_PAIRED_N2)
  for (; k + 2 <= n_closed; k += 2) {
    const int i = closed[k], j = closed[k + 1];
    n2_prepare_two(*law[i], *law[j], dx[i], dx[j], steps[i], steps[j], fast[i], fast[j]);
  }
#endif
  for (; k < n_closed; ++k) {
    const int i = closed[k];
    fast[i] = law[i]->n2_prepare(law[i]->z_commit_, dx[i], steps[i]);
  }
  n_closed = 0;
  Path paths[kTrialBatch];
  int general[kTrialBatch];  // the laws of paths[]
  int n_general = 0;
  for (int i = 0; i < n; ++i) {
    if (fast[i]) {
      closed[n_closed++] = i;
      continue;
    }
    CoupledBoucWenMaterial& m = *law[i];
    if (length_sq[i] > 0.0 && std::isfinite(length_sq[i])) {
      // integrate()'s general path, its sub-increments taken below.
      m.path_start(m.z_commit_, dx[i], length_sq[i], paths[n_general]);
      general[n_general++] = i;
      continue;
    }
    const ZUpdate update = m.integrate(m.z_commit_, dx[i], false);
    m.z_ = update.z;
    m.dz_dx_ = update.dz_dx;
  }
  // The general paths' sub-increments, one of each bearing in turn (each bearing's are a chain;
  // in turn, the next bearing's step overlaps this one's).
  int slot[kTrialBatch];
  for (int j = 0; j < n_general; ++j) slot[j] = j;
  for (int active = n_general; active > 0;) {
    int still = 0;
    for (int j = 0; j < active; ++j) {
      Path& path = paths[slot[j]];
      CoupledBoucWenMaterial& m = *law[general[slot[j]]];
      if (!m.path_step(path)) {
        slot[still++] = slot[j];
        continue;
      }
      m.z_ = path.z;
      m.dz_dx_ = path.S;
    }
    active = still;
  }
  double q[kTrialBatch], inv[kTrialBatch];
  for (k = 0; k < n_closed; ++k) q[k] = steps[closed[k]].discriminant;
  sqrt_each(q, q, n_closed);
  inverse_q_one_plus_q(q, inv, n_closed);
  k = 0;
#if defined(ISOPOUND_PAIRED_N2)
  for (; k + 2 <= n_closed; k += 2) {
    const int i = closed[k], j = closed[k + 1];
    n2_finish_two(*law[i], *law[j], steps[i], steps[j], q[k], q[k + 1], inv[k], inv[k + 1]);
  }
#endif
  for (; k < n_closed; ++k) {
    CoupledBoucWenMaterial& m = *law[closed[k]];
    m.n2_finish(steps[closed[k]], q[k], inv[k], m.z_, m.dz_dx_);
  }
}

// Pseudocode of integrate(z0, dx), l = |dx|, e = dx/l, S = dz/dx carried along:
//   repeat (at most 3 branches: each split turns an unloading component into a loading one)
//     c_i = beta - gamma where e_i z_i < 0 (unloading), else beta + gamma; w = c o e
//     h_sub = 1/(4 n |w| z_b^(n-1)) (or l/kMax); full = floor(L/h_sub), rem = L - full h_sub
//     for k = 0..full: if an unloading component reaches 0 within h_sub (closed form) and
//       before L: step exactly onto z_i = 0, L -= distance so far, next branch
//       else step h_sub (k < full) or rem (k = full)
//   every step: S <- (I - h/2 J1)^-1 [(I + h/2 J0) S + (Phi0 + Phi1)/2 dh/dx + h/2 (M0 + M1) de/dx]
// The loop is a resumable Path (path_start, then path_step until it says done), so that
// set_trials can take the sub-increments of several bearings in turn: each bearing's are a
// chain (square root, division, next step), the bearings' are independent.
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
  Path path;
  path_start(z0, dx, length_sq, path);
  while (!path_step(path)) {
  }
  return {path.z, path.S};
}

void CoupledBoucWenMaterial::path_start(const Vector2d& z0, const Vector2d& dx, double length_sq,
                                        Path& p) const {
  const double length = std::sqrt(length_sq);
  p.e = dx / length;
  p.de_dx = (Matrix2d::Identity() - p.e * p.e.transpose()) / length;
  p.z = z0;
  p.S = Matrix2d::Zero();
  p.s_is_zero = true;
  p.L = length;
  p.dL_dx = p.e.transpose();
  p.branch = 0;
  branch_start(p);
}

void CoupledBoucWenMaterial::branch_start(Path& p) const {
  // A component at round-off from 0 is 0: it is on neither side, so no branch split waits for it.
  for (int i = 0; i < 2; ++i)
    if (std::abs(p.z[i]) <= kNegligibleZ * z_saturation_) p.z[i] = 0.0;
  const Vector2d& z = p.z;
  const Vector2d& e = p.e;
  p.unloading[0] = z[0] * e[0] < 0.0;
  p.unloading[1] = z[1] * e[1] < 0.0;
  // c from two scalars, not written entry by entry: a packet load of two fresh 8-byte stores
  // stalls (no store forwarding), and it sat on this path's critical chain.
  p.c = Vector2d(p_.beta + (p.unloading[0] ? -p_.gamma : p_.gamma),
                 p_.beta + (p.unloading[1] ? -p_.gamma : p_.gamma));
  p.w = p.c.cwiseProduct(e);
  const double w_norm = p.w.norm();

  // Sub-increment from the largest |dPhi/dz| on the path (|z| <= max(|z_start|, z_sat)).
  const double z_norm = z.norm();
  const bool beyond = z_norm > z_saturation_;
  const double z_bound = beyond ? z_norm : z_saturation_;
  const double bound_pow_n = beyond ? std::pow(z_norm, p_.n) : z_saturation_pow_n_;
  const double max_slope = w_norm * p_.n * bound_pow_n / z_bound;
  const double h_bound = max_slope > 0 ? kMaxSubincrementStiffness / max_slope : 1e300;
  p.h_sub = std::max(h_bound, p.L / kMaxSubincrements);
  // L / h_sub >= 0: truncation is floor (without libm's call).
  p.full = static_cast<long>(p.L / p.h_sub);
  p.remainder = p.L - static_cast<double>(p.full) * p.h_sub;
  // dh_sub/dx matters only when full sub-increments are taken.
  p.dh_sub_dx = RowVector2d::Zero();
  if (p.full > 0) {
    if (p.h_sub != h_bound)
      p.dh_sub_dx = p.dL_dx / static_cast<double>(kMaxSubincrements);
    else if (max_slope > 0)  // h_bound = K / |w|, d|w| = (w o c)^T de / |w|
      p.dh_sub_dx = (-h_bound / (w_norm * w_norm)) * p.w.cwiseProduct(p.c).transpose() * p.de_dx;
  }

  phi_parts(z, z_norm, p.c, p.w, p.M0, p.J0);
  p.phi0 = p.M0 * e;
  // For gamma >= 0 the exact z never leaves the disc |z| <= z_sat (on its rim
  // d|z|^2/dl = 2 z_sat^n gamma (e.z - sum |e_i z_i|) <= 0), but the trapezoidal map may, by
  // its local error (~1e-6 on a circular orbit): such a step is scaled back onto the rim.
  // A uniaxial step never leaves it (its map is monotone), so this keeps the reduction exact.
  p.keep_in_disc = p_.gamma >= 0.0 && z_norm <= z_saturation_ * (1.0 + 1e-12);
  p.x = 0.0;
  p.dx_dx = RowVector2d::Zero();
  p.k = 0;
}

// One trapezoidal step of size h (gradient dh_dx) from (z, phi0, M0, J0), updating S.
void CoupledBoucWenMaterial::advance(Path& p, double h, const RowVector2d& dh_dx) const {
  const Matrix2d I = Matrix2d::Identity();
  const Vector2d& e = p.e;
  const Vector2d& c = p.c;
  const Vector2d& w = p.w;
  const double hh = h > 0.0 ? 0.5 * h : 0.0;
  Vector2d z1;
  Matrix2d M1, J1, m_inverse;
  double r1;
  // n = 2: z1 = lambda b in closed form and, as in integrate_single_step_n2, det(I - h/2 J1)
  // = q (1 + q)/2: one square root and one division; else the general sub-increment.
  const Vector2d b = p.z + hh * (p.phi0 + p_.A * e);
  const double discriminant = p_.n == 2.0 && h > 0.0 ? 1.0 + 2.0 * h * w.dot(b) : 0.0;
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
    r1 = p.keep_in_disc && z1.squaredNorm() > z_saturation_sq_ ? z1.norm() : 0.0;
  } else {
    z1 = h > 0.0 ? trapezoid_step(p.z, p.phi0, h, e, c) : p.z;
    r1 = phi_parts(z1, c, w, M1, J1);
    m_inverse = (I - hh * J1).inverse();
  }
  Vector2d phi1 = M1 * e;
  Matrix2d rhs = 0.5 * (p.phi0 + phi1) * dh_dx + hh * (p.M0 + M1) * p.de_dx;
  if (!p.s_is_zero) rhs += (I + hh * p.J0) * p.S;
  p.S = m_inverse * rhs;
  p.s_is_zero = false;
  p.z = z1;
  if (p.keep_in_disc && r1 > z_saturation_) {
    // z <- z_sat z/|z|, so dz <- (z_sat/|z|) (I - n n^T) dz.
    const double scale = z_saturation_ / r1;
    const Vector2d n = z1 / r1;
    p.S = scale * (I - n * n.transpose()) * p.S;
    p.z = scale * z1;
    phi_parts(p.z, c, w, M1, J1);
    phi1 = M1 * e;
  }
  p.phi0 = phi1;
  p.M0 = M1;
  p.J0 = J1;
}

bool CoupledBoucWenMaterial::path_step(Path& p) const {
  // A trapezoidal step landing on z_i = 0 (where Phi_i = A e_i): 0 = z_i + h/2 (Phi_i + A e_i).
  int crossing = -1;
  double to_zero = 0.0;
  for (int i = 0; i < 2; ++i) {
    if (!p.unloading[i] || !(p.z[i] * p.e[i] < 0.0)) continue;
    const double h = -2.0 * p.z[i] / (p.phi0[i] + p_.A * p.e[i]);
    if (h <= p.h_sub && p.x + h < p.L && (crossing < 0 || h < to_zero)) {
      crossing = i;
      to_zero = h;
    }
  }
  if (crossing >= 0) {
    const int i = crossing;
    const double den = p.phi0[i] + p_.A * p.e[i];
    const RowVector2d dden = p.J0.row(i) * p.S + p.M0.row(i) * p.de_dx + p_.A * p.de_dx.row(i);
    const RowVector2d dh = (-2.0 / den) * p.S.row(i) + (2.0 * p.z[i] / (den * den)) * dden;
    advance(p, to_zero, dh);
    p.z[i] = 0.0;
    p.S.row(i).setZero();
    p.dx_dx += dh;
    p.L -= p.x + to_zero;
    p.dL_dx -= p.dx_dx;
    if (++p.branch == 3) return true;
    branch_start(p);
    return false;
  }
  if (p.k < p.full) {
    advance(p, p.h_sub, p.dh_sub_dx);
  } else {
    const RowVector2d drem = p.dL_dx - static_cast<double>(p.full) * p.dh_sub_dx;
    advance(p, p.remainder, drem);
  }
  p.x += p.h_sub;
  p.dx_dx += p.dh_sub_dx;
  return ++p.k > p.full;
}

}  // namespace isopound
