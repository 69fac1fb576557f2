// Yielding column between two diaphragms: kinematics d_W = T(p) (q_upper - q_lower), section
// axes d_L = R^T d_W, per-axis normalisation x = d_L / d_y, shear V_L = V_y o F(x).
#include "solver/elements/column_link.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isopound {

namespace {
constexpr const char* kNames[] = {"shear",   "drift",   "ductility",        "shear_x",
                                  "shear_y", "drift_x", "drift_y",          "z_1",
                                  "z_2",     "yielded", "hysteretic_energy"};
constexpr const char* kUnits[] = {"N", "m", "-", "N", "N", "m", "m", "-", "-", "-", "J"};
constexpr int kOutputs = 11;
}  // namespace

ColumnLink::ColumnLink(std::string label, DiaphragmDofs upper, DiaphragmDofs lower,
                       const ColumnLinkGeometry& geometry,
                       std::unique_ptr<BiaxialMaterial> unit_law, double alpha)
    : label_(std::move(label)),
      dof_{upper.ux, upper.uy, upper.theta, lower.ux, lower.uy, lower.theta},
      sign_{1.0, 1.0, 1.0, -1.0, -1.0, -1.0},
      g_(geometry),
      law_(std::move(unit_law)),
      alpha_(alpha) {
  if (!law_) throw std::invalid_argument("column '" + label_ + "': no law");
  if (upper.ux < 0 || upper.uy < 0 || upper.theta < 0)
    throw std::invalid_argument("column '" + label_ + "': the upper diaphragm needs u, v, theta");
  if (!(g_.yield_drift.minCoeff() > 0) || !(g_.yield_shear.minCoeff() > 0))
    throw std::invalid_argument("column '" + label_ + "': yield drift and shear must be > 0");
  const bool lower_present = lower.ux >= 0 && lower.uy >= 0 && lower.theta >= 0;
  if (!lower_present && (lower.ux >= 0 || lower.uy >= 0 || lower.theta >= 0))
    throw std::invalid_argument("column '" + label_ + "': the lower diaphragm needs u, v, theta");
  dof_count_ = lower_present ? 6 : 3;
  coupled_ = dynamic_cast<CoupledBoucWenMaterial*>(law_.get());
  const double c = std::cos(g_.orientation), s = std::sin(g_.orientation);
  R_ << c, -s, s, c;
}

Eigen::Vector2d ColumnLink::deformation_of(const Eigen::VectorXd& u) const {
  Eigen::Vector2d d = Eigen::Vector2d::Zero();
  for (int side = 0; side < 2; ++side) {
    const int* dof = dof_ + 3 * side;
    const double sign = sign_[3 * side];
    if (dof[0] >= 0) d[0] += sign * u[dof[0]];
    if (dof[1] >= 0) d[1] += sign * u[dof[1]];
    if (dof[2] >= 0) {
      const double theta = sign * u[dof[2]];
      d[0] -= g_.p_O.y() * theta;
      d[1] += g_.p_O.x() * theta;
    }
  }
  return d;
}

void ColumnLink::set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd&) {
  // Both laws are rate independent: no rate.
  const Eigen::Vector2d d_L = R_.transpose() * deformation_of(u);
  law_->set_trial(d_L.cwiseQuotient(g_.yield_drift), Eigen::Vector2d::Zero());
}

Eigen::Vector2d ColumnLink::shear_W() const {
  return R_ * g_.yield_shear.cwiseProduct(law_->force());
}

Eigen::Matrix2d ColumnLink::tangent_W() const {
  const Eigen::Matrix2d k_L =
      g_.yield_shear.asDiagonal() * law_->tangent() * g_.yield_drift.cwiseInverse().asDiagonal();
  return R_ * k_L * R_.transpose();
}

void ColumnLink::scatter(const Eigen::Vector2d& F, Eigen::VectorXd& f) const {
  const double m = g_.p_O.x() * F[1] - g_.p_O.y() * F[0];
  const double generalised[3] = {F[0], F[1], m};
  for (int i = 0; i < dof_count_; ++i) f[dof_[i]] += sign_[i] * generalised[i % 3];
}

void ColumnLink::add_force(Eigen::VectorXd& f) const {
  scatter(shear_W(), f);
}

void ColumnLink::add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  scatter(tangent_W() * deformation_of(x), y);
}

Eigen::Matrix3d ColumnLink::diaphragm_tangent() const {
  Eigen::Matrix<double, 2, 3> T;
  T << 1.0, 0.0, -g_.p_O.y(), 0.0, 1.0, g_.p_O.x();
  return T.transpose() * tangent_W() * T;
}

void ColumnLink::add_tangent(Eigen::MatrixXd& K, double) const {
  const Eigen::Matrix3d kt = diaphragm_tangent();
  for (int a = 0; a < dof_count_; ++a)
    for (int b = 0; b < dof_count_; ++b)
      K(dof_[a], dof_[b]) += sign_[a] * sign_[b] * kt(a % 3, b % 3);
}

const void* ColumnLink::batch_key() const {
  static const char coupled_columns = 0, other_columns = 0;
  return coupled_ ? &coupled_columns : &other_columns;
}

template <class Block>
void ColumnLink::for_each_storey_run(Element* const* elements, int count, Block&& block) {
  const auto same_dofs = [](const ColumnLink& a, const ColumnLink& b) {
    bool same = true;
    for (int k = 0; k < 6; ++k) same &= a.dof_[k] == b.dof_[k];
    return same;
  };
  for (int i = 0; i < count;) {
    const auto& first = static_cast<const ColumnLink&>(*elements[i]);
    int j = i + 1;
    while (j < count && same_dofs(first, static_cast<const ColumnLink&>(*elements[j]))) ++j;
    block(first, elements + i, j - i);
    i = j;
  }
}

void ColumnLink::set_trial_batch(Element* const* elements, int count, const Eigen::VectorXd& u,
                                 const Eigen::VectorXd& v) {
  if (!coupled_) {  // the key says: no column of this batch has the coupled law
    for (int i = 0; i < count; ++i) elements[i]->set_trial(u, v);
    return;
  }
  constexpr int kChunk = CoupledBoucWenMaterial::kTrialBatch;
  CoupledBoucWenMaterial* laws[kChunk];
  Eigen::Vector2d x[kChunk];
  for (int begin = 0; begin < count; begin += kChunk) {
    const int n = std::min(kChunk, count - begin);
    for (int i = 0; i < n; ++i) {
      const auto& column = static_cast<const ColumnLink&>(*elements[begin + i]);
      laws[i] = column.coupled_;
      const Eigen::Vector2d d_L = column.R_.transpose() * column.deformation_of(u);  // as set_trial
      x[i] = d_L.cwiseQuotient(column.g_.yield_drift);
    }
    CoupledBoucWenMaterial::set_trials(laws, x, n);
  }
}

void ColumnLink::add_force_batch(Element* const* elements, int count, Eigen::VectorXd& f) const {
  for_each_storey_run(elements, count, [&](const ColumnLink& first, Element* const* run, int n) {
    double sum[6];
    for (int a = 0; a < first.dof_count_; ++a) sum[a] = f[first.dof_[a]];
    for (int i = 0; i < n; ++i) {
      const auto& column = static_cast<const ColumnLink&>(*run[i]);
      const Eigen::Vector2d F = column.shear_W();
      const double m = column.g_.p_O.x() * F[1] - column.g_.p_O.y() * F[0];
      const double generalised[3] = {F[0], F[1], m};
      for (int a = 0; a < first.dof_count_; ++a) sum[a] += column.sign_[a] * generalised[a % 3];
    }
    for (int a = 0; a < first.dof_count_; ++a) f[first.dof_[a]] = sum[a];
  });
}

void ColumnLink::add_tangent_batch(Element* const* elements, int count, Eigen::MatrixXd& K,
                                   double) const {
  for_each_storey_run(elements, count, [&](const ColumnLink& first, Element* const* run, int n) {
    const int m = first.dof_count_;
    double sum[6][6];
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b) sum[a][b] = K(first.dof_[a], first.dof_[b]);
    for (int i = 0; i < n; ++i) {
      const auto& column = static_cast<const ColumnLink&>(*run[i]);
      const Eigen::Matrix3d kt = column.diaphragm_tangent();
      for (int a = 0; a < m; ++a)
        for (int b = 0; b < m; ++b)
          sum[a][b] += column.sign_[a] * column.sign_[b] * kt(a % 3, b % 3);
    }
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b) K(first.dof_[a], first.dof_[b]) = sum[a][b];
  });
}

bool ColumnLink::add_dofs(std::vector<int>& dofs) const {
  for (const int d : dof_)
    if (d >= 0) dofs.push_back(d);
  return true;
}

bool ColumnLink::symmetric_tangent() const {
  // R diag(V_y) K diag(1/d_y) R^T is the law's K times a scalar, turned, when both axes have
  // the same yield drift and shear; otherwise it is non-symmetric in general.
  return law_->symmetric_tangent() && g_.yield_drift[0] == g_.yield_drift[1] &&
         g_.yield_shear[0] == g_.yield_shear[1];
}

double ColumnLink::power(const Eigen::VectorXd& v) const {
  return shear_W().dot(deformation_of(v));
}

double ColumnLink::stored_energy() const {
  const Eigen::Vector2d w = g_.yield_shear.cwiseProduct(g_.yield_drift);
  if (w[0] == w[1]) return w[0] * law_->stored_energy();
  const Eigen::Vector2d x = law_->deformation(), z = law_->internal();
  const double elastic = 0.5 * alpha_ * x.squaredNorm();
  const double hysteretic = law_->stored_energy() - elastic;
  const double z2 = z.squaredNorm();
  double e = 0.5 * alpha_ * (w[0] * x[0] * x[0] + w[1] * x[1] * x[1]);
  if (z2 > 0) e += hysteretic * (w[0] * z[0] * z[0] + w[1] * z[1] * z[1]) / z2;
  return e;
}

void ColumnLink::commit() {
  law_->commit();
  const Eigen::Vector2d force = g_.yield_shear.cwiseProduct(law_->force());
  const Eigen::Vector2d drift = g_.yield_drift.cwiseProduct(law_->deformation());
  work_commit_ += 0.5 * (force_commit_ + force).dot(drift - drift_commit_);
  force_commit_ = force;
  drift_commit_ = drift;
  if (law_->deformation().cwiseAbs().maxCoeff() >= 1.0) yielded_ = true;
}

void ColumnLink::revert() {
  law_->revert();
}

int ColumnLink::output_count() const {
  return kOutputs;
}

std::string ColumnLink::output_name(int i) const {
  return kNames[i];
}

Element::OutputKind ColumnLink::output_kind(int i) const {
  return i == 9 ? OutputKind::kState : OutputKind::kContinuous;  // yielded
}

std::string ColumnLink::output_unit(int i) const {
  return kUnits[i];
}

void ColumnLink::outputs(double* out) const {
  const Eigen::Vector2d x = law_->deformation(), z = law_->internal();
  const Eigen::Vector2d shear_L = g_.yield_shear.cwiseProduct(law_->force());
  const Eigen::Vector2d drift_L = g_.yield_drift.cwiseProduct(x);
  const Eigen::Vector2d shear = R_ * shear_L, drift = R_ * drift_L;
  out[0] = shear_L.norm();
  out[1] = drift_L.norm();
  out[2] = x.cwiseAbs().maxCoeff();
  out[3] = shear[0];
  out[4] = shear[1];
  out[5] = drift[0];
  out[6] = drift[1];
  out[7] = z[0];
  out[8] = z[1];
  out[9] = yielded_ ? 1.0 : 0.0;
  out[10] = hysteretic_energy();
}

double ColumnLink::output(int i) const {
  double values[kOutputs];
  outputs(values);
  return values[i];
}

}  // namespace isopound
