// Bearing link: kinematics d = T u, T = [[1, 0, -y], [0, 1, x]] over (ux, uy, theta); forces
// f = T^T F and tangent T^T (K + c K_v) T scattered to the DOFs present (-1: absent, zero motion).
#include "solver/elements/bearing_link.h"

#include <stdexcept>

namespace isopound {

namespace {
constexpr const char* kPlanarNames[] = {"force", "deformation", "z"};
constexpr const char* kPlanNames[] = {"force",         "deformation",   "z",   "force_x", "force_y",
                                      "deformation_x", "deformation_y", "z_x", "z_y"};
constexpr const char* kPlanUnits[] = {"N", "m", "-", "N", "N", "m", "m", "-", "-"};
}  // namespace

BearingLink::BearingLink(std::string label, DiaphragmDofs dofs, Eigen::Vector2d p_OB,
                         std::unique_ptr<BiaxialMaterial> law)
    : label_(std::move(label)),
      dofs_(dofs),
      p_OB_(p_OB),
      law_(std::move(law)),
      coupled_(dynamic_cast<CoupledBoucWenMaterial*>(law_.get())),
      planar_(dofs.uy < 0 && dofs.theta < 0),
      consecutive_(dofs.ux >= 0 && dofs.uy == dofs.ux + 1 && dofs.theta == dofs.ux + 2) {
  if (!law_) throw std::invalid_argument("bearing '" + label_ + "': no law");
  if (dofs.ux < 0 && dofs.uy < 0 && dofs.theta < 0)
    throw std::invalid_argument("bearing '" + label_ + "': no diaphragm DOF");
}

Eigen::Vector2d BearingLink::deformation_of(const Eigen::VectorXd& u) const {
  Eigen::Vector2d d = Eigen::Vector2d::Zero();
  if (dofs_.ux >= 0) d[0] += u[dofs_.ux];
  if (dofs_.uy >= 0) d[1] += u[dofs_.uy];
  if (dofs_.theta >= 0) {
    const double theta = u[dofs_.theta];
    d[0] -= p_OB_.y() * theta;
    d[1] += p_OB_.x() * theta;
  }
  return d;
}

void BearingLink::set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  const Eigen::Vector2d d = deformation_of(u);
  // The coupled Bouc-Wen law is rate independent: no rate to compute.
  if (coupled_)
    coupled_->set_trial(d, Eigen::Vector2d::Zero());
  else
    law_->set_trial(d, deformation_of(v));
}

double BearingLink::stored_energy() const {
  return with_law([](const auto& law) { return law.stored_energy(); });
}

void BearingLink::commit() {
  with_law([](auto& law) { law.commit(); });
}

void BearingLink::revert() {
  with_law([](auto& law) { law.revert(); });
}

void BearingLink::add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  // T^T k T x: the bearing's deformation for x, through its tangent, back onto the DOFs.
  const Eigen::Vector2d F =
      with_law([](const auto& law) { return law.tangent(); }) * deformation_of(x);
  scatter(F, y);
}

void BearingLink::scatter(const Eigen::Vector2d& F, Eigen::VectorXd& f) const {
  if (dofs_.ux >= 0) f[dofs_.ux] += F[0];
  if (dofs_.uy >= 0) f[dofs_.uy] += F[1];
  if (dofs_.theta >= 0) f[dofs_.theta] += p_OB_.x() * F[1] - p_OB_.y() * F[0];
}

void BearingLink::add_force(Eigen::VectorXd& f) const {
  scatter(with_law([](const auto& law) { return law.force(); }), f);
}

void BearingLink::add_tangent(Eigen::MatrixXd& K, double velocity_factor) const {
  const Eigen::Matrix2d k = with_law([&](const auto& law) {
    Eigen::Matrix2d tangent = law.tangent();
    if (velocity_factor != 0.0) tangent += velocity_factor * law.rate_tangent();
    return tangent;
  });
  if (consecutive_) {
    // (ux, uy, theta) = (i, i + 1, i + 2): T^T k T written out (T = [[1, 0, -y], [0, 1, x]]),
    // added column by column to the contiguous 3x3 block.
    const double x = p_OB_.x(), y = p_OB_.y();
    const double k02 = x * k(0, 1) - y * k(0, 0), k12 = x * k(1, 1) - y * k(1, 0);
    const double k20 = x * k(1, 0) - y * k(0, 0), k21 = x * k(1, 1) - y * k(0, 1);
    const double k22 = x * k21 - y * k20;  // (T^T k) T, as Eigen associates it
    double* c0 = &K(dofs_.ux, dofs_.ux);
    double* c1 = &K(dofs_.ux, dofs_.ux + 1);
    double* c2 = &K(dofs_.ux, dofs_.ux + 2);
    c0[0] += k(0, 0);
    c0[1] += k(1, 0);
    c0[2] += k20;
    c1[0] += k(0, 1);
    c1[1] += k(1, 1);
    c1[2] += k21;
    c2[0] += k02;
    c2[1] += k12;
    c2[2] += k22;
    return;
  }
  // Columns of T for (ux, uy, theta).
  const int dof[3] = {dofs_.ux, dofs_.uy, dofs_.theta};
  Eigen::Matrix<double, 2, 3> T;
  T << 1.0, 0.0, -p_OB_.y(), 0.0, 1.0, p_OB_.x();
  const Eigen::Matrix3d kt = T.transpose() * k * T;
  for (int a = 0; a < 3; ++a) {
    if (dof[a] < 0) continue;
    for (int b = 0; b < 3; ++b)
      if (dof[b] >= 0) K(dof[a], dof[b]) += kt(a, b);
  }
}

double BearingLink::power(const Eigen::VectorXd& v) const {
  return with_law([](const auto& law) { return law.force(); }).dot(deformation_of(v));
}

std::string BearingLink::output_name(int i) const {
  return planar_ ? kPlanarNames[i] : kPlanNames[i];
}

std::string BearingLink::output_unit(int i) const {
  return kPlanUnits[i];
}

void BearingLink::outputs(double* out) const {
  Eigen::Vector2d F, d, z;
  with_law([&](const auto& law) {
    F = law.force();
    d = law.deformation();
    z = law.internal();
  });
  if (planar_) {
    out[0] = F[0];
    out[1] = d[0];
    out[2] = z[0];
    return;
  }
  out[0] = F.norm();
  out[1] = d.norm();
  out[2] = z.norm();
  out[3] = F[0];
  out[4] = F[1];
  out[5] = d[0];
  out[6] = d[1];
  out[7] = z[0];
  out[8] = z[1];
}

double BearingLink::output(int i) const {
  double values[9];
  outputs(values);
  return values[i];
}

}  // namespace isopound
