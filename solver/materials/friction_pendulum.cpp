// Friction pendulum bearing: pendulum spring W/R plus velocity-dependent Coulomb friction
// mu(|v|) W z, z from a radial return (or the coupled Bouc-Wen z), consistent and rate tangents.
#include "solver/materials/friction_pendulum.h"

#include <cmath>
#include <stdexcept>

namespace isopound {

namespace {
const FrictionPendulumParameters& validated(const FrictionPendulumParameters& p) {
  if (!(p.weight > 0) || !(p.radius > 0) || !(p.mu_slow >= 0) || !(p.mu_fast >= 0) ||
      !(p.rate_parameter >= 0) || !(p.yield_displacement > 0))
    throw std::invalid_argument(
        "friction pendulum: need W > 0, R > 0, mu_slow >= 0, mu_fast >= 0, rate parameter >= 0 "
        "and a sliding-onset displacement u_y > 0");
  return p;
}

// K_el = F_y / u_y with F_y = 1, alpha = 0: the force is z.
BoucWenParameters unit_bouc_wen(const FrictionPendulumParameters& p) {
  return bouc_wen_parameters(p.shape,
                             {1.0 / p.yield_displacement, 1.0, p.yield_displacement, 0.0, 0.0});
}
}  // namespace

FrictionPendulumMaterial::FrictionPendulumMaterial(const FrictionPendulumParameters& p)
    : p_(validated(p)),
      pendulum_stiffness_(p.weight / p.radius),
      smooth_z_(unit_bouc_wen(p)),
      dz_dd_(Eigen::Matrix2d::Identity() / p.yield_displacement) {}

double FrictionPendulumMaterial::friction_coefficient(double speed) const {
  return p_.mu_fast - (p_.mu_fast - p_.mu_slow) * std::exp(-p_.rate_parameter * speed);
}

void FrictionPendulumMaterial::set_trial(const Eigen::Vector2d& d, const Eigen::Vector2d& rate) {
  d_ = d;
  rate_ = rate;
  if (p_.smooth) {
    smooth_z_.set_trial(d, rate);
    z_ = smooth_z_.force();
    dz_dd_ = smooth_z_.tangent();
    return;
  }
  const Eigen::Vector2d z_trial = z_commit_ + (d - d_commit_) / p_.yield_displacement;
  const double norm = z_trial.norm();
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  if (norm > 1.0) {
    const Eigen::Vector2d n = z_trial / norm;
    z_ = n;
    dz_dd_ = (I - n * n.transpose()) / (p_.yield_displacement * norm);
  } else {
    z_ = z_trial;
    dz_dd_ = I / p_.yield_displacement;
  }
}

Eigen::Vector2d FrictionPendulumMaterial::force() const {
  return pendulum_stiffness_ * d_ + friction_coefficient(rate_.norm()) * p_.weight * z_;
}

Eigen::Matrix2d FrictionPendulumMaterial::tangent() const {
  return pendulum_stiffness_ * Eigen::Matrix2d::Identity() +
         (friction_coefficient(rate_.norm()) * p_.weight) * dz_dd_;
}

Eigen::Matrix2d FrictionPendulumMaterial::rate_tangent() const {
  const double speed = rate_.norm();
  if (speed == 0.0) return Eigen::Matrix2d::Zero();  // mu(|v|) has a kink at v = 0
  const double dmu_dspeed =
      (p_.mu_fast - p_.mu_slow) * p_.rate_parameter * std::exp(-p_.rate_parameter * speed);
  return (p_.weight * dmu_dspeed / speed) * z_ * rate_.transpose();
}

double FrictionPendulumMaterial::stored_energy() const {
  // Pendulum (gravity) energy W |d|^2/(2R) plus the elastic pre-sliding part of the friction
  // spring (stiffness mu W/u_y at the trial mu): mu W u_y |z|^2/2 (|z|^2/(2A) for Bouc-Wen).
  const double mu_w = friction_coefficient(rate_.norm()) * p_.weight;
  const double pre_sliding =
      p_.smooth ? z_.squaredNorm() / (2.0 * p_.shape.A) : 0.5 * z_.squaredNorm();
  return 0.5 * pendulum_stiffness_ * d_.squaredNorm() + mu_w * p_.yield_displacement * pre_sliding;
}

void FrictionPendulumMaterial::commit() {
  d_commit_ = d_;
  z_commit_ = z_;
  rate_commit_ = rate_;
  if (p_.smooth) smooth_z_.commit();
}

void FrictionPendulumMaterial::revert() {
  d_ = d_commit_;
  z_ = z_commit_;
  rate_ = rate_commit_;
  if (p_.smooth) {
    smooth_z_.revert();
    dz_dd_ = smooth_z_.tangent();
  } else if (z_.norm() < 1.0) {
    dz_dd_ = Eigen::Matrix2d::Identity() / p_.yield_displacement;
  } else {  // sliding: the radial-return tangent of a zero increment
    const Eigen::Vector2d n = z_.normalized();
    dz_dd_ = (Eigen::Matrix2d::Identity() - n * n.transpose()) / p_.yield_displacement;
  }
}

}  // namespace isopound
