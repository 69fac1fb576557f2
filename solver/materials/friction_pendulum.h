// Single concave friction pendulum bearing (radius R): F = (W/R) d + mu(|v|) W z, W = m g,
// mu(v) = mu_fast - (mu_fast - mu_slow) exp(-a |v|), z a circular-interaction hysteretic variable.
#pragma once

#include <memory>

#include "solver/materials/biaxial_material.h"
#include "solver/materials/bouc_wen_coupled.h"
#include "solver/materials/hysteresis_law.h"

namespace isopound {

struct FrictionPendulumParameters {
  double weight = 0.0;               // W = m g, N (vertical load, constant)
  double radius = 0.0;               // R, m (pendulum stiffness W/R)
  double mu_slow = 0.0;              // friction coefficient at v -> 0
  double mu_fast = 0.0;              // friction coefficient at high velocity
  double rate_parameter = 0.0;       // a, s/m
  double yield_displacement = 5e-4;  // u_y, m: sliding starts after ~u_y of elastic travel
  // z law: false = elastic-perfectly-plastic with radial return (|z| <= 1, sharp corners, the
  // textbook friction model); true = the coupled Bouc-Wen z (smooth, THEORY eq. 5.28) with the
  // shape below.
  bool smooth = false;
  BoucWenShape shape;
};

// Plastic z (default): z* = z_c + dd/u_y; z = z* if |z*| <= 1, else z*/|z*| (exact along a
// straight increment). Tangent dF/dd = (W/R) I + mu W dz/dd (symmetric); rate tangent
// dF/dv = W z (dmu/dv)^T = W z mu'(|v|) v^T/|v| (non-symmetric in plan; 0 at v = 0).
class FrictionPendulumMaterial final : public BiaxialMaterial {
 public:
  explicit FrictionPendulumMaterial(const FrictionPendulumParameters& p);

  void set_trial(const Eigen::Vector2d& d, const Eigen::Vector2d& rate) override;
  Eigen::Vector2d force() const override;
  Eigen::Matrix2d tangent() const override;
  Eigen::Matrix2d rate_tangent() const override;
  bool symmetric_tangent() const override { return false; }
  Eigen::Vector2d internal() const override { return z_; }
  double stored_energy() const override;
  Eigen::Vector2d deformation() const override { return d_; }
  void commit() override;
  void revert() override;
  std::unique_ptr<BiaxialMaterial> clone() const override {
    return std::make_unique<FrictionPendulumMaterial>(*this);
  }

  double friction_coefficient(double speed) const;  // mu(|v|)

 private:
  FrictionPendulumParameters p_;
  double pendulum_stiffness_;  // W / R
  // Smooth z: a coupled Bouc-Wen law with K_el = 1/u_y, F_y = 1, alpha = 0, whose force is z.
  CoupledBoucWenMaterial smooth_z_;
  Eigen::Vector2d d_ = Eigen::Vector2d::Zero(), z_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d rate_ = Eigen::Vector2d::Zero();
  Eigen::Matrix2d dz_dd_;
  Eigen::Vector2d d_commit_ = Eigen::Vector2d::Zero(), z_commit_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d rate_commit_ = Eigen::Vector2d::Zero();
};

}  // namespace isopound
