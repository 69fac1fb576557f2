// A slab against a struck column line: the massless node found by a safeguarded Newton iteration
// (its force is monotone in its position: column and contact both stiffen it), then condensed
// out of the tangent.
#include "solver/elements/struck_column.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isopound {

StruckColumn::StruckColumn(std::string label, const StruckColumnSpec& spec, double gap,
                           std::unique_ptr<ImpactLaw> law, double effective_mass,
                           double steps_per_contact)
    : label_(std::move(label)),
      spec_(spec),
      column_(spec.column),
      count_(spec.count),
      contact_(label_, ContactBody{0, spec.side}, ContactBody{3, -spec.side}, gap, std::move(law),
               effective_mass, steps_per_contact),
      ul_(Eigen::VectorXd::Zero(4)),
      vl_(Eigen::VectorXd::Zero(4)),
      fl_(Eigen::VectorXd::Zero(4)),
      kl_(Eigen::MatrixXd::Zero(4, 4)),
      kc_(Eigen::MatrixXd::Zero(4, 4)) {
  if (spec.count < 1 || spec.slab < 0 || spec.upper < 0)
    throw std::invalid_argument(label_ + ": a struck column needs count >= 1, a slab and a floor");
  state_ = column_.respond(ColumnDisplacements::Zero(), plastic_commit_);
}

bool StruckColumn::add_dofs(std::vector<int>& dofs) const {
  dofs.push_back(spec_.slab);
  if (spec_.lower >= 0) dofs.push_back(spec_.lower);
  dofs.push_back(spec_.upper);
  return true;
}

void StruckColumn::begin_step(double h, bool freeze_status) {
  h_ = h;
  contact_.begin_step(h, freeze_status);
}

void StruckColumn::gather(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  ul_(0) = u[spec_.slab];
  vl_(0) = v[spec_.slab];
  ul_(1) = spec_.lower >= 0 ? u[spec_.lower] : 0.0;
  vl_(1) = spec_.lower >= 0 ? v[spec_.lower] : 0.0;
  ul_(2) = u[spec_.upper];
  vl_(2) = v[spec_.upper];
}

double StruckColumn::node_residual(double& slope) {
  ul_(3) = u_node_;
  state_ = column_.respond(ColumnDisplacements(ul_(1), ul_(3), ul_(2)), plastic_commit_);
  // No dashpot on the node: it follows the floors quasi-statically, v = du/d(floors) v_floors
  // (exact, as accurate as the floors' velocities). Behind a dashpot: backward Euler,
  // v = (u - u_0) / h (L-stable: Newmark's trapezoidal rule would leave a massless node
  // ringing behind it), or, in a restart or a step too short to resolve it, as set by the caller.
  const Eigen::Matrix3d& t = state_.tangent;
  if (!damped_commit_ && !hold_velocity_)
    v_node_ = t(1, 1) > 0 ? -(t(1, 0) * vl_(1) + t(1, 2) * vl_(2)) / t(1, 1) : 0.0;
  else if (by_difference())
    v_node_ = (u_node_ - u_node_commit_) / h_;
  vl_(3) = v_node_;
  contact_.set_trial(ul_, vl_);
  fl_.setZero();
  contact_.add_force(fl_);
  kl_.setZero();
  contact_.add_tangent(kl_, 0.0);
  kc_.setZero();
  contact_.add_tangent(kc_, 1.0);
  kc_ -= kl_;
  slope = count_ * t(1, 1) + kl_(3, 3) + (by_difference() ? kc_(3, 3) / h_ : 0.0);
  return count_ * state_.force(1) + fl_(3);
}

void StruckColumn::set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  gather(u, v);
  double slope = 0.0;
  if (!(h_ > kShortestDifference)) {
    // A restart (h = 0) or a step too short for a difference (cut at an event): the node
    // keeps its place and, massless behind a dashpot, takes at once the velocity of its
    // equilibrium (so a contact beginning behind a dashpot starts without a force jump).
    u_node_ = u_node_commit_ + (h_ > 0 ? h_ * v_node_commit_ : 0.0);
    v_node_ = v_node_commit_;
    double g = node_residual(slope);
    hold_velocity_ = true;
    for (int it = 0; it < 20 && kc_(3, 3) > 0; ++it) {
      if (std::abs(g) <= 1e-12 * (std::abs(fl_(3)) + 1.0)) break;
      v_node_ -= g / kc_(3, 3);
      g = node_residual(slope);
    }
    hold_velocity_ = false;
    return;
  }
  // Predictor: the node moves with the elastic shape of the column between its floors.
  const double psi = column_.shape_at_node();
  double lo = -1e300, hi = 1e300;
  u_node_ = offset_commit_ + (1.0 - psi) * ul_(1) + psi * ul_(2);
  for (int it = 0; it < 100; ++it) {
    const double g = node_residual(slope);
    if (g > 0) hi = std::min(hi, u_node_);
    if (g < 0) lo = std::max(lo, u_node_);
    if (g == 0) return;
    double next = slope > 0 ? u_node_ - g / slope : u_node_;
    // Outside the bracket (a kink between): bisect once both sides are known.
    if (!(next > lo && next < hi) && lo > -1e300 && hi < 1e300) next = 0.5 * (lo + hi);
    if (std::abs(next - u_node_) <= 1e-15 * (1.0 + std::abs(u_node_)) || next == u_node_) return;
    u_node_ = next;
  }
}

void StruckColumn::add_force(Eigen::VectorXd& f) const {
  f[spec_.slab] += fl_(0);
  if (spec_.lower >= 0) f[spec_.lower] += count_ * state_.force(0);
  f[spec_.upper] += count_ * state_.force(2);
}

void StruckColumn::condensed_tangent(double velocity_factor) const {
  // The contact's stiffness and damping apart: the slab's rate follows the stepper's factor,
  // the node's its own backward difference (1/h), or none when it is not a difference.
  kl_.setZero();
  contact_.add_tangent(kl_, 0.0);
  kc_.setZero();
  contact_.add_tangent(kc_, 1.0);
  kc_ -= kl_;
  const double node_factor = by_difference() && velocity_factor > 0 ? 1.0 / h_ : 0.0;
  for (int j = 0; j < 4; ++j) kl_.col(j) += kc_.col(j) * (j == 3 ? node_factor : velocity_factor);
  // The column on (lower, node, upper) = local (1, 3, 2).
  const int map[3] = {1, 3, 2};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) kl_(map[i], map[j]) += count_ * state_.tangent(i, j);
  const double knn = kl_(3, 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      k3_(i, j) = kl_(i, j) - (knn > 0 ? kl_(i, 3) * kl_(3, j) / knn : 0.0);
}

double StruckColumn::event_fraction() {
  const double theta = contact_.event_fraction();
  return theta < 1.0 && (1.0 - theta) * h_ <= kShortestDifference ? 1.0 - 1e-15 : theta;
}

double StruckColumn::step_limit() const {
  const double limit = contact_.step_limit();
  if (!damped_commit_) return limit;
  kl_.setZero();
  contact_.add_tangent(kl_, 0.0);
  kc_.setZero();
  contact_.add_tangent(kc_, 1.0);
  const double c = kc_(3, 3) - kl_(3, 3), k = kl_(3, 3) + count_ * state_.tangent(1, 1);
  // A relaxation far shorter than the contact's own steps (a node next to a floor, as good as
  // rigid) needs no resolving: BE is L-stable and the node quasi-static then. Steps of up to
  // kRelaxationSteps relaxation times keep the peaks as close to fixed 1e-5 s steps as steps of
  // one did (docs/floor-to-column.md).
  return c > 0 && k > 0 ? std::min(limit, std::max(kRelaxationSteps * c / k, 0.01 * limit)) : limit;
}

void StruckColumn::add_tangent(Eigen::MatrixXd& K, double velocity_factor) const {
  condensed_tangent(velocity_factor);
  const int dofs[3] = {spec_.slab, spec_.lower, spec_.upper};
  for (int i = 0; i < 3; ++i) {
    if (dofs[i] < 0) continue;
    for (int j = 0; j < 3; ++j)
      if (dofs[j] >= 0) K(dofs[i], dofs[j]) += k3_(i, j);
  }
}

void StruckColumn::add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  condensed_tangent(0.0);
  const int dofs[3] = {spec_.slab, spec_.lower, spec_.upper};
  for (int i = 0; i < 3; ++i) {
    if (dofs[i] < 0) continue;
    for (int j = 0; j < 3; ++j)
      if (dofs[j] >= 0) y[dofs[i]] += k3_(i, j) * x[dofs[j]];
  }
}

double StruckColumn::power(const Eigen::VectorXd& v) const {
  double p = v[spec_.slab] * fl_(0) + v[spec_.upper] * count_ * state_.force(2);
  if (spec_.lower >= 0) p += v[spec_.lower] * count_ * state_.force(0);
  return p;
}

double StruckColumn::stored_energy() const {
  return count_ * state_.stored_energy + contact_.stored_energy();
}

void StruckColumn::commit() {
  contact_.commit();
  hinge_energy_ +=
      count_ * spec_.column.yield_moment * (state_.plastic - plastic_commit_).cwiseAbs().sum();
  plastic_commit_ = state_.plastic;
  u_node_commit_ = u_node_;
  v_node_commit_ = v_node_;
  kl_.setZero();
  contact_.add_tangent(kl_, 0.0);
  kc_.setZero();
  contact_.add_tangent(kc_, 1.0);
  damped_commit_ = kc_(3, 3) > kl_(3, 3);
  const double psi = column_.shape_at_node();
  offset_commit_ = u_node_ - ((1.0 - psi) * ul_(1) + psi * ul_(2));
  if (spec_.shear_capacity > 0 && shear() >= spec_.shear_capacity) shear_failed_ = true;
  shear_failed_commit_ = shear_failed_;
}

void StruckColumn::revert() {
  contact_.revert();
  u_node_ = u_node_commit_;
  v_node_ = v_node_commit_;
  shear_failed_ = shear_failed_commit_;
}

double StruckColumn::local_drift() const {
  const double a = spec_.column.node / spec_.column.length;
  return u_node_ - ((1.0 - a) * ul_(1) + a * ul_(2));
}

double StruckColumn::shear() const {
  return std::max(std::abs(state_.shear_lower), std::abs(state_.shear_upper));
}

std::string StruckColumn::output_name(int i) const {
  const int c = contact_.output_count();
  if (i < c) return contact_.output_name(i);
  static const char* kNames[kColumnOutputs] = {
      "column_shear", "shear_failed",           "moment_bottom",  "moment_node",
      "moment_top",   "ductility_bottom",       "ductility_node", "ductility_top",
      "local_drift",  "hinge_dissipated_energy"};
  return kNames[i - c];
}

Element::OutputKind StruckColumn::output_kind(int i) const {
  const int c = contact_.output_count();
  if (i < c) return contact_.output_kind(i);
  return i == c + 1 ? OutputKind::kState : OutputKind::kContinuous;  // shear_failed
}

std::string StruckColumn::output_unit(int i) const {
  const int c = contact_.output_count();
  if (i < c) return contact_.output_unit(i);
  static const char* kUnits[kColumnOutputs] = {"N", "-", "N m", "N m", "N m",
                                               "-", "-", "-",   "m",   "J"};
  return kUnits[i - c];
}

double StruckColumn::output(int i) const {
  const int c = contact_.output_count();
  if (i < c) return contact_.output(i);
  const HingedColumnSection& s = spec_.column;
  const double theta_y = s.yield_moment * s.length / (6.0 * s.E * s.I);
  switch (i - c) {
    case 0:
      return shear();
    case 1:
      return shear_failed_ || (spec_.shear_capacity > 0 && shear() >= spec_.shear_capacity);
    case 2:
    case 3:
    case 4:
      return state_.moment(i - c - 2);
    case 5:
    case 6:
    case 7:
      return theta_y > 0 ? 1.0 + std::abs(state_.plastic(i - c - 5)) / theta_y : 0.0;
    case 8:
      return local_drift();
    default:
      return hinge_energy_ +
             count_ * s.yield_moment * (state_.plastic - plastic_commit_).cwiseAbs().sum();
  }
}

}  // namespace isopound
