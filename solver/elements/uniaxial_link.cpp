// A uniaxial law between two DOFs (or a DOF and the ground): scatter of force and tangent.
// Force on DOF j is +F, on DOF i is -F (a spring resisting d = u_j - u_i).
#include "solver/elements/uniaxial_link.h"

namespace isopound {

UniaxialLink::UniaxialLink(std::string label, int dof_i, int dof_j,
                           std::unique_ptr<UniaxialMaterial> law)
    : label_(std::move(label)), i_(dof_i), j_(dof_j), law_(std::move(law)) {}

void UniaxialLink::set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd&) {
  law_->set_trial(i_ == kGround ? u[j_] : u[j_] - u[i_]);
}

void UniaxialLink::add_force(Eigen::VectorXd& f) const {
  const double F = law_->force();
  f[j_] += F;
  if (i_ != kGround) f[i_] -= F;
}

void UniaxialLink::add_tangent(Eigen::MatrixXd& K, double) const {
  const double k = law_->tangent();
  K(j_, j_) += k;
  if (i_ != kGround) {
    K(i_, i_) += k;
    K(i_, j_) -= k;
    K(j_, i_) -= k;
  }
}

void UniaxialLink::add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  const double k = law_->tangent();
  if (i_ == kGround) {
    y[j_] += k * x[j_];
    return;
  }
  const double kd = k * (x[j_] - x[i_]);
  y[j_] += kd;
  y[i_] -= kd;
}

double UniaxialLink::power(const Eigen::VectorXd& v) const {
  const double rate = i_ == kGround ? v[j_] : v[j_] - v[i_];
  return law_->force() * rate;
}

std::string UniaxialLink::output_name(int i) const {
  static const char* kNames[] = {"force", "deformation", "z"};
  return kNames[i];
}

std::string UniaxialLink::output_unit(int i) const {
  static const char* kUnits[] = {"N", "m", "-"};
  return kUnits[i];
}

double UniaxialLink::output(int i) const {
  double values[3];
  outputs(values);
  return values[i];
}

}  // namespace isopound
