// A uniaxial law between two DOFs or between a DOF and the ground: deformation
// d = u[j] - u[i] (d = u[j] when i is the ground), force F(d) pulls the DOFs together.
#pragma once

#include <memory>
#include <string>

#include "solver/core/element.h"
#include "solver/materials/hysteresis.h"

namespace isopound {

inline constexpr int kGround = -1;

class UniaxialLink : public Element {
 public:
  // dof_i may be kGround. The link owns its material.
  UniaxialLink(std::string label, int dof_i, int dof_j, std::unique_ptr<UniaxialMaterial> law);

  bool has_events() const override { return false; }
  bool add_dofs(std::vector<int>& dofs) const override {
    dofs.push_back(j_);
    if (i_ != kGround) dofs.push_back(i_);
    return true;
  }
  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) override;
  void add_force(Eigen::VectorXd& f) const override;
  void add_tangent(Eigen::MatrixXd& K, double velocity_factor) const override;
  bool has_stiffness_product() const override { return true; }
  void add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const override;
  double power(const Eigen::VectorXd& v) const override;
  double stored_energy() const override { return law_->stored_energy(); }
  void commit() override { law_->commit(); }
  void revert() override { law_->revert(); }

  int output_count() const override { return 3; }
  std::string output_name(int i) const override;
  std::string output_unit(int i) const override;
  double output(int i) const override;
  void outputs(double* out) const override {
    out[0] = law_->force();
    out[1] = law_->deformation();
    out[2] = law_->internal();
  }
  const std::string& label() const override { return label_; }

  const UniaxialMaterial& law() const { return *law_; }

 private:
  std::string label_;
  int i_, j_;
  std::unique_ptr<UniaxialMaterial> law_;
};

}  // namespace isopound
