// Sharp bilinear isolator with kinematic hardening: F = alpha K_el d + F_h, where F_h is an
// elastic-perfectly-plastic spring (stiffness (1-alpha) K_el, yield (1-alpha) F_y), return map.
#pragma once

#include "solver/materials/hysteresis.h"

namespace isopound {

class BilinearMaterial final : public UniaxialMaterial {
 public:
  // elastic_stiffness K_el > 0, 0 <= alpha < 1, yield_force F_y > 0.
  BilinearMaterial(double elastic_stiffness, double alpha, double yield_force);

  void set_trial(double d) override;
  double force() const override { return alpha_k_ * d_ + fh_; }
  double tangent() const override { return tangent_; }
  double internal() const override { return fh_ / fh_yield_; }  // z = F_h / ((1-alpha) F_y)
  double stored_energy() const override;
  double deformation() const override { return d_; }
  void commit() override;
  void revert() override;
  std::unique_ptr<UniaxialMaterial> clone() const override {
    return std::make_unique<BilinearMaterial>(*this);
  }

 private:
  double alpha_k_;   // alpha K_el, N/m
  double k_h_;       // (1 - alpha) K_el, N/m
  double fh_yield_;  // (1 - alpha) F_y, N
  double d_ = 0.0, fh_ = 0.0, tangent_;
  double d_commit_ = 0.0, fh_commit_ = 0.0;
};

}  // namespace isopound
