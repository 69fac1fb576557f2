// Bouc-Wen isolator: implicit trapezoidal integration of z over each deformation increment,
// split at z = 0, with a local safeguarded Newton and a chain-ruled consistent tangent.
#include "solver/materials/bouc_wen.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace isopound {

namespace {
constexpr double kMaxSubincrementStiffness = 0.25;  // h |dPhi/dz| per sub-increment
constexpr int kMaxSubincrements = 100000;
}  // namespace

BoucWenMaterial::BoucWenMaterial(const BoucWenParameters& p) : p_(p) {
  if (!(p.elastic_stiffness > 0) || !(p.yield_displacement > 0) || !(p.n > 0) || !(p.A > 0) ||
      !(p.beta + p.gamma > 0) || !(p.alpha >= 0 && p.alpha < 1))
    throw std::invalid_argument(
        "Bouc-Wen: need K_el > 0, u_y > 0, n > 0, A > 0, "
        "beta + gamma > 0 and 0 <= alpha < 1");
  z_saturation_ = std::pow(p.A / (p.beta + p.gamma), 1.0 / p.n);
  z_saturation_pow_n_ = p.A / (p.beta + p.gamma);
  const double rounded = std::round(p.n);
  integer_n_ = (rounded == p.n && rounded >= 1 && rounded <= 16) ? static_cast<int>(rounded) : 0;
  // The branches' sub-increments within saturation, as subincrement() computes them.
  for (Branch* b : {&loading_, &unloading_}) {
    b->c = b == &loading_ ? p.beta + p.gamma : p.beta - p.gamma;
    b->h_sub = subincrement_size(std::abs(b->c) * p.n * z_saturation_pow_n_ / z_saturation_);
  }
  dz_dx_ = p.A;
  dz_dx_commit_ = p.A;
}

double BoucWenMaterial::abs_pow_n(double z) const {
  const double a = std::abs(z);
  if (integer_n_ == 0) return std::pow(a, p_.n);
  double r = a;
  for (int i = 1; i < integer_n_; ++i) r *= a;
  return r;
}

double BoucWenMaterial::force() const {
  return p_.alpha * p_.elastic_stiffness * d_ + (1.0 - p_.alpha) * p_.yield_force * z_;
}

double BoucWenMaterial::tangent() const {
  return p_.alpha * p_.elastic_stiffness +
         (1.0 - p_.alpha) * p_.yield_force * dz_dx_ / p_.yield_displacement;
}

double BoucWenMaterial::stored_energy() const {
  // Elastic spring plus the recoverable part of the hysteretic spring: in the elastic limit
  // dz = A dd / u_y, so int (1-alpha) F_y z dd = (1-alpha) F_y u_y z^2 / (2A).
  return 0.5 * p_.alpha * p_.elastic_stiffness * d_ * d_ +
         (1.0 - p_.alpha) * p_.yield_force * p_.yield_displacement * z_ * z_ / (2.0 * p_.A);
}

void BoucWenMaterial::set_trial(double d) {
  d_ = d;
  const ZUpdate update = integrate(z_commit_, (d - d_commit_) / p_.yield_displacement);
  z_ = update.z;
  dz_dx_ = update.dz_dx;
}

void BoucWenMaterial::commit() {
  d_commit_ = d_;
  z_commit_ = z_;
  dz_dx_commit_ = dz_dx_;
}

void BoucWenMaterial::revert() {
  d_ = d_commit_;
  z_ = z_commit_;
  dz_dx_ = dz_dx_commit_;
}

inline double BoucWenMaterial::dphi(double z, double c) const {
  const double a = std::abs(z);
  if (a == 0.0) return p_.n == 1.0 ? -c * std::copysign(1.0, z) : 0.0;
  const double sign = z > 0 ? 1.0 : -1.0;
  // n = 1 and c in {0, +-1} (beta = gamma = 1/2): -c |z| is exact, so -c |z| / |z| is -c to the
  // bit (and its zero's sign): the division need not be made.
  if (integer_n_ == 1 && (c == 0.0 || std::abs(c) == 1.0) && std::isfinite(a)) return -c * sign;
  return -c * p_.n * abs_pow_n(z) / a * sign;
}

// Pseudocode of integrate(z0, dx):
//   if dx unloads (dx z0 < 0): x* = distance from |z0| to 0 on the unloading branch
//     if |dx| <= x*: integrate the unloading branch (c = beta - gamma) over dx, done
//     else: z = 0 exactly, dx -= sgn(dx) x*   (x* does not depend on dx)
//   integrate the loading branch (c = beta + gamma) over the rest
BoucWenMaterial::ZUpdate BoucWenMaterial::integrate(double z0, double dx) const {
  if (dx == 0.0) {
    // No increment: report the elastic-side slope, the stiffer of the two one-sided ones.
    const double c = p_.beta - p_.gamma;
    return {z0, p_.A - c * abs_pow_n(z0)};
  }
  if (z0 * dx < 0.0) {
    const double x_star = distance_to_zero(z0);
    if (std::abs(dx) <= x_star) return integrate_branch(z0, dx, p_.beta - p_.gamma);
    dx -= std::copysign(x_star, dx);
    z0 = 0.0;
  }
  return integrate_branch(z0, dx, p_.beta + p_.gamma);
}

// Pseudocode of integrate_branch(z_start, L, c):
//   h_sub = (sub-increment bound) / max |dPhi/dz| on the path
//   take floor(|L| / h_sub) trapezoidal sub-increments of size h_sub, then one of the remainder,
//   so that z is a continuous function of L (only the remainder depends on L)
//   each sub-increment: solve z1 = z + h/2 (phi(z) + phi(z1)) (closed form for n = 2, else
//   Newton safeguarded by bisection); dz/dL comes from the remainder step alone.
BoucWenMaterial::ZUpdate BoucWenMaterial::integrate_branch(double z_start, double length,
                                                           double c) const {
  const auto phi = [&](double z) { return p_.A - c * abs_pow_n(z); };

  // Sub-increment from the largest |dPhi/dz| on the path (|z| <= max(|z_start|, z_sat)).
  double bound_pow_n;
  const double total = std::abs(length);
  const double h_path = subincrement(z_start, c, bound_pow_n);
  // An increment shorter than a finite sub-increment (most are) is its own remainder: the
  // quotients would give h_path, no full sub-increment and the whole length (total / h_path < 1
  // rounds below 1), so they are not formed.
  double h_sub = h_path, remainder = total;
  long full = 0;
  if (!(total < h_path && h_path < std::numeric_limits<double>::infinity())) {
    h_sub = std::max(h_path, total / kMaxSubincrements);
    full = h_sub > 0 ? static_cast<long>(std::floor(total / h_sub)) : 0;
    remainder = total - static_cast<double>(full) * h_sub;
  }
  const double sign = length >= 0 ? 1.0 : -1.0;

  const auto step = [&](double z, double phi_z, double h) {
    return trapezoid_step(z, phi_z, h, c, bound_pow_n);
  };

  double z = z_start;
  double phi_z = phi(z);
  for (long k = 0; k < full; ++k) {
    z = step(z, phi_z, sign * h_sub);
    phi_z = phi(z);
  }
  if (remainder <= 0.0) return {z, phi_z};  // dz/dL at the end of a full sub-increment
  const double h = sign * remainder;
  const double z1 = step(z, phi_z, h);
  const double phi1 = phi(z1);
  // d z1 / d h of the trapezoidal map; h grows with L one for one.
  const double dz_dl = 0.5 * (phi_z + phi1) / (1.0 - 0.5 * h * dphi(z1, c));
  return {z1, dz_dl};
}

double BoucWenMaterial::trapezoid_step(double z, double phi_z, double h, double c,
                                       double bound_pow_n) const {
  const auto phi = [&](double x) { return p_.A - c * abs_pow_n(x); };
  const double base = z + 0.5 * h * phi_z;
  double z1 = z + h * phi_z;  // explicit predictor
  // n = 2: phi = A - c z^2, so the trapezoidal equation is the quadratic
  // (h c / 2) z1^2 + z1 - b = 0, b = base + h A / 2; the root continuous in h is
  // z1 = 2 b / (1 + sqrt(1 + 2 h c b)) (no cancellation).
  const double b = base + 0.5 * h * p_.A;
  const double discriminant = 1.0 + 2.0 * h * c * b;
  if (integer_n_ == 2 && discriminant >= 0.0) return 2.0 * b / (1.0 + std::sqrt(discriminant));
  const double reach = std::abs(h) * (std::abs(phi_z) + std::abs(c) * bound_pow_n + p_.A);
  double lo = z - reach, hi = z + reach;
  z1 = std::clamp(z1, lo, hi);
  // r(z1) = z1 - base - h/2 phi(z1) is increasing (r' = 1 - h/2 phi' >= 1/2 by the bound).
  for (int it = 0; it < 60; ++it) {
    const double r = z1 - base - 0.5 * h * phi(z1);
    if (r > 0)
      hi = z1;
    else
      lo = z1;
    const double dr = 1.0 - 0.5 * h * dphi(z1, c);
    double next = z1 - r / dr;
    // Safeguard: bisect when Newton leaves the bracket (a converged iterate may sit on it).
    if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - z1) <= 1e-14 * (1.0 + std::abs(z1));
    z1 = next;
    if (done) break;
  }
  return z1;
}

double BoucWenMaterial::subincrement(double z_start, double c, double& bound_pow_n) const {
  const bool beyond = std::abs(z_start) > z_saturation_;
  const double z_bound = beyond ? std::abs(z_start) : z_saturation_;
  bound_pow_n = beyond ? abs_pow_n(z_bound) : z_saturation_pow_n_;
  // Within saturation the size depends on the branch alone: the two branches' sizes are kept.
  if (!beyond && c == loading_.c) return loading_.h_sub;
  if (!beyond && c == unloading_.c) return unloading_.h_sub;
  return subincrement_size(std::abs(c) * p_.n * bound_pow_n / z_bound);
}

double BoucWenMaterial::subincrement_size(double max_slope) {
  return max_slope > 0 ? kMaxSubincrementStiffness / max_slope : 1e300;
}

double BoucWenMaterial::distance_to_zero(double z0) const {
  // The x at which the unloading branch (c = beta - gamma), integrated with the same
  // trapezoidal sub-increments as integrate_branch, reaches z = 0: so z is continuous there.
  const double c = p_.beta - p_.gamma;
  if (c == 0.0) return std::abs(z0) / p_.A;
  double bound_pow_n;
  const double h_sub = subincrement(z0, c, bound_pow_n);
  const double sign = z0 > 0 ? -1.0 : 1.0;
  double z = z0, x = 0.0;
  for (int k = 0; k < kMaxSubincrements; ++k) {
    const double phi_z = p_.A - c * abs_pow_n(z);
    // Trapezoidal step that lands on 0: 0 = z + h/2 (phi(z) + A), |h| = 2|z| / (phi(z) + A).
    const double to_zero = 2.0 * std::abs(z) / (phi_z + p_.A);
    if (to_zero <= h_sub) return x + to_zero;
    z = trapezoid_step(z, phi_z, sign * h_sub, c, bound_pow_n);
    x += h_sub;
  }
  return x;
}

}  // namespace isopound
