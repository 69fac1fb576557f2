// A column line between two floors: per direction, the HingedColumn's node at mid-height kept in
// balance (the chord's midpoint while the end hinges stay symmetric; a Newton correction
// otherwise), then condensed out of the tangent.
#include "solver/elements/column_line.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isopound {

namespace {
HingedColumnSection at_mid_height(HingedColumnSection s) {
  s.node = 0.5 * s.length;
  return s;
}

// sum c_i x[dof_i]: the drift (or its rate) along one direction.
double along(const ColumnLineSpec::Direction& dir, const Eigen::VectorXd& x) {
  double d = 0.0;
  for (int i = 0; i < dir.terms; ++i)
    d += dir.coefficient[static_cast<std::size_t>(i)] * x[dir.dof[static_cast<std::size_t>(i)]];
  return d;
}
}  // namespace

ColumnLine::ColumnLine(std::string label, const ColumnLineSpec& spec)
    : label_(std::move(label)),
      spec_(spec),
      // (A second direction unused in 2D copies the first: every axis is a valid column.)
      axes_{Axis(at_mid_height(spec.directions[0].column)),
            Axis(at_mid_height(spec.directions[spec.direction_count > 1 ? 1 : 0].column))},
      count_(spec.count) {
  if (spec.count < 1 || spec.direction_count < 1 || spec.direction_count > 2)
    throw std::invalid_argument(label_ + ": a column line needs count >= 1 and 1 or 2 directions");
  for (int d = 0; d < spec_.direction_count; ++d) {
    Axis& a = axes_[static_cast<std::size_t>(d)];
    if (spec_.directions[static_cast<std::size_t>(d)].terms < 1)
      throw std::invalid_argument(label_ + ": a column line's drift needs a floor");
    spec_.directions[static_cast<std::size_t>(d)].column = a.column.section();
    a.state = a.column.respond(ColumnDisplacements::Zero(), a.plastic_commit);
    a.stiffness = count_ * a.column.storey_stiffness();
  }
}

bool ColumnLine::add_dofs(std::vector<int>& dofs) const {
  for (int d = 0; d < spec_.direction_count; ++d) {
    const ColumnLineSpec::Direction& dir = spec_.directions[static_cast<std::size_t>(d)];
    dofs.insert(dofs.end(), dir.dof.begin(), dir.dof.begin() + dir.terms);
  }
  return true;
}

void ColumnLine::set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd&) {
  for (int d = 0; d < spec_.direction_count; ++d) {
    const ColumnLineSpec::Direction& dir = spec_.directions[static_cast<std::size_t>(d)];
    Axis& a = axes_[static_cast<std::size_t>(d)];
    const double drift = along(dir, u);
    // The column between its floors moved by (0, drift): only the drift deforms it.
    double u_node = 0.5 * drift;
    const double scale = a.column.storey_stiffness() * (std::abs(drift) + 1e-9);
    for (int it = 0; it < 20; ++it) {
      a.state = a.column.respond(ColumnDisplacements(0.0, u_node, drift), a.plastic_commit);
      const double g = a.state.force(1), slope = a.state.tangent(1, 1);
      if (std::abs(g) <= 1e-13 * scale || !(slope > 0)) break;
      u_node -= g / slope;
    }
    // The force on the upper end and its stiffness, node condensed (the lower end takes the
    // opposite: no load acts on the node).
    const Eigen::Matrix3d& t = a.state.tangent;
    a.force = count_ * a.state.force(2);
    a.stiffness = count_ * (t(1, 1) > 0 ? t(2, 2) - t(2, 1) * t(1, 2) / t(1, 1) : t(2, 2));
  }
}

void ColumnLine::add_force(Eigen::VectorXd& f) const {
  for (int d = 0; d < spec_.direction_count; ++d) {
    const ColumnLineSpec::Direction& dir = spec_.directions[static_cast<std::size_t>(d)];
    const double force = axes_[static_cast<std::size_t>(d)].force;
    for (int i = 0; i < dir.terms; ++i)
      f[dir.dof[static_cast<std::size_t>(i)]] +=
          dir.coefficient[static_cast<std::size_t>(i)] * force;
  }
}

void ColumnLine::add_tangent(Eigen::MatrixXd& K, double) const {
  for (int d = 0; d < spec_.direction_count; ++d) {
    const ColumnLineSpec::Direction& dir = spec_.directions[static_cast<std::size_t>(d)];
    const double k = axes_[static_cast<std::size_t>(d)].stiffness;
    for (int i = 0; i < dir.terms; ++i)
      for (int j = 0; j < dir.terms; ++j)
        K(dir.dof[static_cast<std::size_t>(i)], dir.dof[static_cast<std::size_t>(j)]) +=
            dir.coefficient[static_cast<std::size_t>(i)] *
            dir.coefficient[static_cast<std::size_t>(j)] * k;
  }
}

void ColumnLine::add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  for (int d = 0; d < spec_.direction_count; ++d) {
    const ColumnLineSpec::Direction& dir = spec_.directions[static_cast<std::size_t>(d)];
    const double drift = along(dir, x);
    const double f = axes_[static_cast<std::size_t>(d)].stiffness * drift;
    for (int i = 0; i < dir.terms; ++i)
      y[dir.dof[static_cast<std::size_t>(i)]] += dir.coefficient[static_cast<std::size_t>(i)] * f;
  }
}

double ColumnLine::power(const Eigen::VectorXd& v) const {
  double p = 0.0;
  for (int d = 0; d < spec_.direction_count; ++d) {
    const ColumnLineSpec::Direction& dir = spec_.directions[static_cast<std::size_t>(d)];
    const double rate = along(dir, v);
    p += axes_[static_cast<std::size_t>(d)].force * rate;
  }
  return p;
}

double ColumnLine::stored_energy() const {
  double e = 0.0;
  for (int d = 0; d < spec_.direction_count; ++d)
    e += count_ * axes_[static_cast<std::size_t>(d)].state.stored_energy;
  return e;
}

void ColumnLine::commit() {
  for (int d = 0; d < spec_.direction_count; ++d) {
    Axis& a = axes_[static_cast<std::size_t>(d)];
    a.energy += count_ * a.column.section().yield_moment *
                (a.state.plastic - a.plastic_commit).cwiseAbs().sum();
    a.plastic_commit = a.state.plastic;
  }
  if (spec_.shear_capacity > 0 && shear() >= spec_.shear_capacity) shear_failed_ = true;
  shear_failed_commit_ = shear_failed_;
}

void ColumnLine::revert() {
  shear_failed_ = shear_failed_commit_;
}

double ColumnLine::hinge_dissipated_energy() const {
  double e = 0.0;
  for (int d = 0; d < spec_.direction_count; ++d) {
    const Axis& a = axes_[static_cast<std::size_t>(d)];
    e += a.energy + count_ * a.column.section().yield_moment *
                        (a.state.plastic - a.plastic_commit).cwiseAbs().sum();
  }
  return e;
}

double ColumnLine::shear() const {
  double sq = 0.0;
  for (int d = 0; d < spec_.direction_count; ++d) {
    const ColumnState& s = axes_[static_cast<std::size_t>(d)].state;
    const double v = std::max(std::abs(s.shear_lower), std::abs(s.shear_upper));
    sq += v * v;
  }
  return std::sqrt(sq);
}

// The larger |moment| over directions at hinge 0 (bottom) or 2 (top), with its sign.
double ColumnLine::end_moment(int hinge) const {
  double m = 0.0;
  for (int d = 0; d < spec_.direction_count; ++d) {
    const double md = axes_[static_cast<std::size_t>(d)].state.moment(hinge);
    if (std::abs(md) > std::abs(m)) m = md;
  }
  return m;
}

double ColumnLine::ductility(int hinge) const {
  double mu = 0.0;
  for (int d = 0; d < spec_.direction_count; ++d) {
    const Axis& a = axes_[static_cast<std::size_t>(d)];
    const HingedColumnSection& s = a.column.section();
    const double theta_y = s.yield_moment * s.length / (6.0 * s.E * s.I);
    if (theta_y > 0) mu = std::max(mu, 1.0 + std::abs(a.state.plastic(hinge)) / theta_y);
  }
  return mu;
}

std::string ColumnLine::output_name(int i) const {
  static const char* kNames[kOutputs] = {
      "column_shear",     "shear_failed",  "moment_bottom",          "moment_top",
      "ductility_bottom", "ductility_top", "hinge_dissipated_energy"};
  return kNames[i];
}

Element::OutputKind ColumnLine::output_kind(int i) const {
  return i == 1 ? OutputKind::kState : OutputKind::kContinuous;  // shear_failed
}

std::string ColumnLine::output_unit(int i) const {
  static const char* kUnits[kOutputs] = {"N", "-", "N m", "N m", "-", "-", "J"};
  return kUnits[i];
}

double ColumnLine::output(int i) const {
  switch (i) {  // hinges (bottom, node, top): the ends are 0 and 2
    case 0:
      return shear();
    case 1:
      return shear_failed_ || (spec_.shear_capacity > 0 && shear() >= spec_.shear_capacity);
    case 2:
      return end_moment(0);
    case 3:
      return end_moment(2);
    case 4:
      return ductility(0);
    case 5:
      return ductility(2);
    default:
      return hinge_dissipated_energy();
  }
}

}  // namespace isopound
