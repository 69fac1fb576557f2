// Bearing elements of 3D buildings. With the bearings branch (ISOPOUND_HAVE_BEARING_LINK, set by
// CMake when solver/elements/bearing_link.cpp exists) the real BearingLink; until then a
// stand-in that supports the linear and the uncoupled laws (two uniaxial isolator laws).
#include "solver/structures/bearing_element.h"

#include <cmath>
#include <stdexcept>

#include "solver/core/constants.h"

namespace isopound {

IsolatorConfig as_isolator(const BearingConfig& c) {
  IsolatorConfig iso;
  switch (c.model) {
    case BearingConfig::Model::kLinear:
      iso.model = IsolatorConfig::Model::kLinear;
      break;
    case BearingConfig::Model::kBilinear:
      iso.model = IsolatorConfig::Model::kBilinear;
      break;
    default:
      iso.model = IsolatorConfig::Model::kBoucWen;
  }
  iso.period = c.period;
  iso.strength_ratio = c.strength_ratio;
  iso.yield_displacement = c.yield_displacement;
  iso.n = c.n;
  iso.A = c.A;
  iso.beta = c.beta;
  iso.gamma = c.gamma;
  iso.strength_is_yield_force = c.strength_is_yield_force;
  return iso;
}

BearingStiffness bearing_stiffness(const BearingConfig& c, double m) {
  if (c.model == BearingConfig::Model::kFrictionPendulum) {
    if (!(c.radius > 0) || !(c.yield_displacement > 0))
      throw std::invalid_argument("friction pendulum: need radius > 0 and uy > 0");
    const double w = m * kGravity;
    return {w / c.radius, c.mu_slow * w / c.yield_displacement + w / c.radius};
  }
  const IsolatorProperties p = isolator_properties(as_isolator(c), m);
  return {p.post_yield_stiffness,
          c.model == BearingConfig::Model::kLinear ? p.post_yield_stiffness : p.elastic_stiffness};
}

}  // namespace isopound

#ifdef ISOPOUND_HAVE_BEARING_LINK

namespace isopound {

std::unique_ptr<Element> make_bearing_element(const std::string& label, DiaphragmDofs dofs,
                                              const Eigen::Vector2d& p_OB,
                                              const BearingConfig& config, double carried_mass) {
  return std::make_unique<BearingLink>(label, dofs, p_OB,
                                       make_bearing_material(config, carried_mass));
}

}  // namespace isopound

#else  // stand-in until branch bearings is merged

namespace isopound {
namespace {

// Two independent uniaxial laws in x and y under a diaphragm at p: d = T q,
// T = [[1, 0, -y], [0, 1, x]], f = T^T F, tangent T^T diag(k_x, k_y) T (symmetric).
class UncoupledPlanBearing final : public Element {
 public:
  UncoupledPlanBearing(std::string label, DiaphragmDofs dofs, Eigen::Vector2d p,
                       std::unique_ptr<UniaxialMaterial> law)
      : label_(std::move(label)), dofs_(dofs), p_(p), x_(law->clone()), y_(std::move(law)) {}

  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd&) override {
    const Eigen::Vector2d d = deformation_of(u);
    x_->set_trial(d.x());
    if (dofs_.uy >= 0) y_->set_trial(d.y());
  }
  void add_force(Eigen::VectorXd& f) const override {
    scatter(f, {x_->force(), dofs_.uy >= 0 ? y_->force() : 0.0});
  }
  void add_tangent(Eigen::MatrixXd& K, double) const override {
    const int idx[3] = {dofs_.ux, dofs_.uy, dofs_.theta};
    Eigen::Matrix<double, 2, 3> T;
    T << 1, 0, -p_.y(), 0, 1, p_.x();
    const Eigen::Vector2d k(x_->tangent(), dofs_.uy >= 0 ? y_->tangent() : 0.0);
    const Eigen::Matrix3d kq = T.transpose() * k.asDiagonal() * T;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (idx[a] >= 0 && idx[b] >= 0) K(idx[a], idx[b]) += kq(a, b);
  }
  double power(const Eigen::VectorXd& v) const override {
    const Eigen::Vector2d r = deformation_of(v);
    return x_->force() * r.x() + (dofs_.uy >= 0 ? y_->force() * r.y() : 0.0);
  }
  double stored_energy() const override {
    return x_->stored_energy() + (dofs_.uy >= 0 ? y_->stored_energy() : 0.0);
  }
  void commit() override {
    x_->commit();
    y_->commit();
  }
  void revert() override {
    x_->revert();
    y_->revert();
  }
  int output_count() const override { return 8; }
  std::string output_name(int i) const override {
    static const char* kNames[] = {"force_x",       "force_y",     "force", "deformation_x",
                                   "deformation_y", "deformation", "z_x",   "z_y"};
    return kNames[i];
  }
  std::string output_unit(int i) const override {
    static const char* kUnits[] = {"N", "N", "N", "m", "m", "m", "-", "-"};
    return kUnits[i];
  }
  double output(int i) const override {
    double values[8];
    outputs(values);
    return values[i];
  }
  void outputs(double* out) const override {
    const double fy = dofs_.uy >= 0 ? y_->force() : 0.0;
    const double dy = dofs_.uy >= 0 ? y_->deformation() : 0.0;
    out[0] = x_->force();
    out[1] = fy;
    out[2] = std::sqrt(out[0] * out[0] + fy * fy);
    out[3] = x_->deformation();
    out[4] = dy;
    out[5] = std::sqrt(out[3] * out[3] + dy * dy);
    out[6] = x_->internal();
    out[7] = dofs_.uy >= 0 ? y_->internal() : 0.0;
  }
  const std::string& label() const override { return label_; }

 private:
  Eigen::Vector2d deformation_of(const Eigen::VectorXd& q) const {
    const double th = dofs_.theta >= 0 ? q[dofs_.theta] : 0.0;
    return {q[dofs_.ux] - p_.y() * th, (dofs_.uy >= 0 ? q[dofs_.uy] : 0.0) + p_.x() * th};
  }
  void scatter(Eigen::VectorXd& f, const Eigen::Vector2d& F) const {
    f[dofs_.ux] += F.x();
    if (dofs_.uy >= 0) f[dofs_.uy] += F.y();
    if (dofs_.theta >= 0) f[dofs_.theta] += -p_.y() * F.x() + p_.x() * F.y();
  }

  std::string label_;
  DiaphragmDofs dofs_;
  Eigen::Vector2d p_;
  std::unique_ptr<UniaxialMaterial> x_, y_;
};

}  // namespace

std::unique_ptr<Element> make_bearing_element(const std::string& label, DiaphragmDofs dofs,
                                              const Eigen::Vector2d& p_OB,
                                              const BearingConfig& config, double carried_mass) {
  using M = BearingConfig::Model;
  if (config.model == M::kBoucWenCoupled || config.model == M::kFrictionPendulum)
    throw std::invalid_argument(
        "bearing model " +
        std::string(config.model == M::kBoucWenCoupled ? "bouc_wen (coupled)"
                                                       : "friction_pendulum") +
        " is implemented on branch 'bearings', not yet merged; use bouc_wen_uncoupled, bilinear "
        "or linear");
  // kBilinear: the stand-in is two uniaxial bilinear laws (square yield surface).
  return std::make_unique<UncoupledPlanBearing>(
      label, dofs, p_OB, make_isolator_material(as_isolator(config), carried_mass));
}

}  // namespace isopound

#endif
