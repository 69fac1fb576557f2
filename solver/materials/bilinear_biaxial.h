// Biaxial sharp bilinear bearing: F = alpha K_el d + F_h, F_h elastic-perfectly-plastic with a
// circular yield surface |F_h| <= (1-alpha) F_y (kinematic hardening of the total force), radial
// return.
#pragma once

#include "solver/materials/biaxial_material.h"

namespace isopound {

// Exact for a straight deformation increment (the return map of a circular surface with a
// constant elastic stiffness is exact along a straight path); on a uniaxial path it is the
// uniaxial BilinearMaterial. z = F_h / ((1-alpha) F_y), |z| <= 1.
class BilinearBiaxialMaterial final : public BiaxialMaterial {
 public:
  // elastic_stiffness K_el > 0, 0 <= alpha < 1, yield_force F_y > 0.
  BilinearBiaxialMaterial(double elastic_stiffness, double alpha, double yield_force);

  void set_trial(const Eigen::Vector2d& d, const Eigen::Vector2d& rate) override;
  Eigen::Vector2d force() const override { return alpha_k_ * d_ + fh_; }
  Eigen::Matrix2d tangent() const override { return tangent_; }
  bool symmetric_tangent() const override { return true; }
  Eigen::Vector2d internal() const override { return fh_ / fh_yield_; }
  double stored_energy() const override;
  Eigen::Vector2d deformation() const override { return d_; }
  void commit() override;
  void revert() override;
  std::unique_ptr<BiaxialMaterial> clone() const override {
    return std::make_unique<BilinearBiaxialMaterial>(*this);
  }

 private:
  double alpha_k_;   // alpha K_el, N/m
  double k_h_;       // (1 - alpha) K_el, N/m
  double fh_yield_;  // (1 - alpha) F_y, N
  Eigen::Vector2d d_ = Eigen::Vector2d::Zero(), fh_ = Eigen::Vector2d::Zero();
  Eigen::Matrix2d tangent_;
  Eigen::Vector2d d_commit_ = Eigen::Vector2d::Zero(), fh_commit_ = Eigen::Vector2d::Zero();
};

}  // namespace isopound
