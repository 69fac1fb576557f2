// Linear elastic uniaxial law, F = k d: the "linear" (equivalent-linear) isolator.
// Stored energy k d^2 / 2; nothing is dissipated.
#pragma once

#include "solver/materials/hysteresis.h"

namespace isopound {

class LinearMaterial final : public UniaxialMaterial {
 public:
  explicit LinearMaterial(double stiffness) : k_(stiffness) {}
  void set_trial(double d) override { d_ = d; }
  double force() const override { return k_ * d_; }
  double tangent() const override { return k_; }
  double internal() const override { return 0.0; }
  double stored_energy() const override { return 0.5 * k_ * d_ * d_; }
  double deformation() const override { return d_; }
  void commit() override { d_commit_ = d_; }
  void revert() override { d_ = d_commit_; }
  std::unique_ptr<UniaxialMaterial> clone() const override {
    return std::make_unique<LinearMaterial>(*this);
  }

 private:
  double k_;
  double d_ = 0.0, d_commit_ = 0.0;
};

}  // namespace isopound
