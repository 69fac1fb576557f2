// Bouc-Wen isolator: implicit trapezoidal integration of z over each deformation increment,
// split at z = 0, with a local safeguarded Newton and a chain-ruled consistent tangent.
#include "solver/bouc_wen.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace isopound {

namespace {
constexpr double kMaxSubincrementStiffness = 1.0;  // h |dPhi/dz| per sub-increment
constexpr int kMaxSubincrements = 100000;
}  // namespace

BoucWenMaterial::BoucWenMaterial(const BoucWenParameters& p) : p_(p) {
  if (!(p.elastic_stiffness > 0) || !(p.yield_displacement > 0) || !(p.n > 0) || !(p.A > 0) ||
      !(p.beta + p.gamma > 0) || !(p.alpha >= 0 && p.alpha < 1))
    throw std::invalid_argument("Bouc-Wen: need K_el > 0, u_y > 0, n > 0, A > 0, "
                                "beta + gamma > 0 and 0 <= alpha < 1");
  z_saturation_ = std::pow(p.A / (p.beta + p.gamma), 1.0 / p.n);
  const double rounded = std::round(p.n);
  integer_n_ = (rounded == p.n && rounded >= 1 && rounded <= 16) ? static_cast<int>(rounded) : 0;
  dz_dx_ = p.A;
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
}

void BoucWenMaterial::revert() {
  d_ = d_commit_;
  z_ = z_commit_;
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
    const double x_star = distance_to_zero(std::abs(z0));
    if (std::abs(dx) <= x_star) return integrate_branch(z0, dx, p_.beta - p_.gamma);
    dx -= std::copysign(x_star, dx);
    z0 = 0.0;
  }
  return integrate_branch(z0, dx, p_.beta + p_.gamma);
}

BoucWenMaterial::ZUpdate BoucWenMaterial::integrate_branch(double z_start, double length,
                                                           double c) const {
  const double n = p_.n;
  const auto phi = [&](double z) { return p_.A - c * abs_pow_n(z); };
  // dPhi/dz = -c n |z|^(n-1) sgn z
  const auto dphi = [&](double z) {
    const double a = std::abs(z);
    if (a == 0.0) return n == 1.0 ? -c * std::copysign(1.0, z) : 0.0;
    return -c * n * abs_pow_n(z) / a * (z > 0 ? 1.0 : -1.0);
  };

  // Largest |dPhi/dz| on the path: |z| stays below max(|z_start|, z_sat).
  const double z_bound = std::max(std::abs(z_start), z_saturation_);
  const double max_slope = std::abs(c) * n * std::pow(z_bound, n - 1.0);
  int m = static_cast<int>(std::ceil(std::abs(length) * max_slope / kMaxSubincrementStiffness));
  m = std::clamp(m, 1, kMaxSubincrements);
  const double h = length / m;

  double z = z_start;
  double w = 0.0;  // dz/d(length); the start value does not depend on length
  double phi_z = phi(z);
  double dphi_z = dphi(z);
  for (int k = 0; k < m; ++k) {
    // Solve r(z1) = z1 - z - h/2 (phi(z) + phi(z1)) = 0; r' = 1 - h/2 phi'(z1) >= 1/2.
    const double base = z + 0.5 * h * phi_z;
    double lo = z - std::abs(h) * (std::abs(phi_z) + std::abs(c) * std::pow(z_bound, n) + p_.A);
    double hi = z + std::abs(h) * (std::abs(phi_z) + std::abs(c) * std::pow(z_bound, n) + p_.A);
    double z1 = z + h * phi_z;  // explicit predictor
    z1 = std::clamp(z1, lo, hi);
    for (int it = 0; it < 60; ++it) {
      const double r = z1 - base - 0.5 * h * phi(z1);
      if (r > 0) hi = z1; else lo = z1;
      const double dr = 1.0 - 0.5 * h * dphi(z1);
      double next = z1 - r / dr;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // safeguard: bisect
      const bool done = std::abs(next - z1) <= 1e-15 * (1.0 + std::abs(z1));
      z1 = next;
      if (done) break;
    }
    const double phi1 = phi(z1);
    const double dphi1 = dphi(z1);
    // d/dL of the trapezoidal map, with h = L/m.
    w = (w * (1.0 + 0.5 * h * dphi_z) + (0.5 / m) * (phi_z + phi1)) / (1.0 - 0.5 * h * dphi1);
    z = z1;
    phi_z = phi1;
    dphi_z = dphi1;
  }
  return {z, w};
}

double BoucWenMaterial::distance_to_zero(double abs_z) const {
  // x* = int_0^|z| dw / (A - (beta - gamma) w^n); exact when beta == gamma.
  const double c = p_.beta - p_.gamma;
  if (c == 0.0) return abs_z / p_.A;
  static constexpr std::array<double, 4> kNodes = {0.1834346424956498, 0.5255324099163290,
                                                   0.7966664774136267, 0.9602898564975363};
  static constexpr std::array<double, 4> kWeights = {0.3626837833783620, 0.3137066458778873,
                                                     0.2223810344533745, 0.1012285362903763};
  double sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    for (const double sign : {-1.0, 1.0}) {
      const double w = 0.5 * abs_z * (1.0 + sign * kNodes[i]);
      sum += kWeights[i] / (p_.A - c * abs_pow_n(w));
    }
  }
  return 0.5 * abs_z * sum;
}

}  // namespace isopound
