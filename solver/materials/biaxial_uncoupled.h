// Uncoupled biaxial bearing: two independent uniaxial laws, F_x(d_x) and F_y(d_y) (THEORY
// section 2, "uncoupled": square interaction, the hysteretic force reaches the square's corner).
#pragma once

#include <memory>

#include "solver/materials/biaxial_material.h"
#include "solver/materials/hysteresis.h"

namespace isopound {

class UncoupledBiaxialMaterial final : public BiaxialMaterial {
 public:
  UncoupledBiaxialMaterial(std::unique_ptr<UniaxialMaterial> law_x,
                           std::unique_ptr<UniaxialMaterial> law_y);
  UncoupledBiaxialMaterial(const UncoupledBiaxialMaterial& other);

  void set_trial(const Eigen::Vector2d& d, const Eigen::Vector2d&) override {
    x_->set_trial(d[0]);
    y_->set_trial(d[1]);
  }
  Eigen::Vector2d force() const override { return {x_->force(), y_->force()}; }
  Eigen::Matrix2d tangent() const override {
    return Eigen::Vector2d(x_->tangent(), y_->tangent()).asDiagonal();
  }
  bool symmetric_tangent() const override { return true; }
  Eigen::Vector2d internal() const override { return {x_->internal(), y_->internal()}; }
  double stored_energy() const override { return x_->stored_energy() + y_->stored_energy(); }
  Eigen::Vector2d deformation() const override { return {x_->deformation(), y_->deformation()}; }
  void commit() override {
    x_->commit();
    y_->commit();
  }
  void revert() override {
    x_->revert();
    y_->revert();
  }
  std::unique_ptr<BiaxialMaterial> clone() const override {
    return std::make_unique<UncoupledBiaxialMaterial>(*this);
  }

 private:
  std::unique_ptr<UniaxialMaterial> x_, y_;
};

}  // namespace isopound
