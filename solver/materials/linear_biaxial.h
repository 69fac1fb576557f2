// Linear (equivalent-linear) bearing in plan: F = k d in every direction.
// Stored energy k |d|^2 / 2; nothing is dissipated.
#pragma once

#include "solver/materials/biaxial_material.h"

namespace isopound {

class LinearBiaxialMaterial final : public BiaxialMaterial {
 public:
  explicit LinearBiaxialMaterial(double stiffness) : k_(stiffness) {}
  void set_trial(const Eigen::Vector2d& d, const Eigen::Vector2d&) override { d_ = d; }
  Eigen::Vector2d force() const override { return k_ * d_; }
  Eigen::Matrix2d tangent() const override { return k_ * Eigen::Matrix2d::Identity(); }
  bool symmetric_tangent() const override { return true; }
  Eigen::Vector2d internal() const override { return Eigen::Vector2d::Zero(); }
  double stored_energy() const override { return 0.5 * k_ * d_.squaredNorm(); }
  Eigen::Vector2d deformation() const override { return d_; }
  void commit() override { d_commit_ = d_; }
  void revert() override { d_ = d_commit_; }
  std::unique_ptr<BiaxialMaterial> clone() const override {
    return std::make_unique<LinearBiaxialMaterial>(*this);
  }

 private:
  double k_;
  Eigen::Vector2d d_ = Eigen::Vector2d::Zero(), d_commit_ = Eigen::Vector2d::Zero();
};

}  // namespace isopound
