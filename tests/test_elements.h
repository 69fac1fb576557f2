// Elements for the stepper's tests: a stateless base without outputs, and a linear pair.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "solver/core/element.h"

namespace isopound::test {

// No committed state, no stored energy, no outputs: a test element overrides what it exercises.
class QuietElement : public Element {
 public:
  explicit QuietElement(std::string label) : label_(std::move(label)) {}
  double stored_energy() const override { return 0.0; }
  void commit() override {}
  void revert() override {}
  int output_count() const override { return 0; }
  std::string output_name(int) const override { return ""; }
  std::string output_unit(int) const override { return ""; }
  double output(int) const override { return 0.0; }
  const std::string& label() const override { return label_; }

 private:
  std::string label_;
};

// f = A u on DOFs 0 and 1, declared non-symmetric (a circulatory coupling, as a coupled
// bearing's tangent). `declares`: whether it tells the stepper its DOFs (add_dofs).
class LinearPair final : public QuietElement {
 public:
  LinearPair(Eigen::Matrix2d A, bool declares) : QuietElement("pair"), A_(A), declares_(declares) {}
  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd&) override { u_ = u.head<2>(); }
  void add_force(Eigen::VectorXd& f) const override { f.head<2>() += A_ * u_; }
  void add_tangent(Eigen::MatrixXd& K, double) const override { K.topLeftCorner<2, 2>() += A_; }
  bool add_dofs(std::vector<int>& dofs) const override {
    dofs.insert(dofs.end(), {0, 1});
    return declares_;
  }
  bool symmetric_tangent() const override { return false; }
  double power(const Eigen::VectorXd& v) const override { return v.head<2>().dot(A_ * u_); }

 private:
  Eigen::Matrix2d A_;
  bool declares_;
  Eigen::Vector2d u_ = Eigen::Vector2d::Zero();
};

}  // namespace isopound::test
