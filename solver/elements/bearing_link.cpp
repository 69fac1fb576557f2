// Bearing link: kinematics d = T u, T = [[1, 0, -y], [0, 1, x]] over (ux, uy, theta); forces
// f = T^T F and tangent T^T (K + c K_v) T scattered to the DOFs present (-1: absent, zero motion).
#include "solver/elements/bearing_link.h"

#include <algorithm>
#include <stdexcept>

#include "solver/core/packed_math.h"

namespace isopound {

namespace {
constexpr const char* kPlanarNames[] = {"force", "deformation", "z"};
constexpr const char* kPlanNames[] = {"force",         "deformation",   "z",   "force_x", "force_y",
                                      "deformation_x", "deformation_y", "z_x", "z_y"};
constexpr const char* kPlanUnits[] = {"N", "m", "-", "N", "N", "m", "m", "-", "-"};
}  // namespace

BearingLink::BearingLink(std::string label, DiaphragmDofs dofs, Eigen::Vector2d p_OB,
                         std::unique_ptr<BiaxialMaterial> law, DiaphragmDofs lower)
    : label_(std::move(label)),
      dofs_(dofs),
      lower_(lower),
      has_lower_(lower.ux >= 0 || lower.uy >= 0 || lower.theta >= 0),
      p_OB_(p_OB),
      law_(std::move(law)),
      coupled_(dynamic_cast<CoupledBoucWenMaterial*>(law_.get())),
      planar_(dofs.uy < 0 && dofs.theta < 0),
      consecutive_(!has_lower_ && dofs.ux >= 0 && dofs.uy == dofs.ux + 1 &&
                   dofs.theta == dofs.ux + 2) {
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
  if (has_lower_) {
    Eigen::Vector2d d_lower = Eigen::Vector2d::Zero();
    if (lower_.ux >= 0) d_lower[0] += u[lower_.ux];
    if (lower_.uy >= 0) d_lower[1] += u[lower_.uy];
    if (lower_.theta >= 0) {
      const double theta = u[lower_.theta];
      d_lower[0] -= p_OB_.y() * theta;
      d_lower[1] += p_OB_.x() * theta;
    }
    d -= d_lower;
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

const void* BearingLink::batch_key() const {
  static const char coupled_bearings = 0;
  return coupled_ ? &coupled_bearings : nullptr;
}

// Every element of a batch has this key: a BearingLink with the coupled law (rate independent).
void BearingLink::set_trial_batch(Element* const* elements, int count, const Eigen::VectorXd& u,
                                  const Eigen::VectorXd&) {
  constexpr int kChunk = CoupledBoucWenMaterial::kTrialBatch;
  CoupledBoucWenMaterial* laws[kChunk];
  Eigen::Vector2d d[kChunk];
  for (int begin = 0; begin < count; begin += kChunk) {
    const int n = std::min(kChunk, count - begin);
    for (int i = 0; i < n; ++i) {
      const auto& link = static_cast<const BearingLink&>(*elements[begin + i]);
      laws[i] = link.coupled_;
      d[i] = link.deformation_of(u);
    }
    CoupledBoucWenMaterial::set_trials(laws, d, n);
  }
}

template <class Single, class Block>
void BearingLink::for_each_diaphragm_run(Element* const* elements, int count, Single&& single,
                                         Block&& block) {
  for (int i = 0; i < count;) {
    const auto& first = static_cast<const BearingLink&>(*elements[i]);
    if (!first.consecutive_) {
      single(first);
      ++i;
      continue;
    }
    int j = i + 1;
    while (j < count) {
      const auto& next = static_cast<const BearingLink&>(*elements[j]);
      if (!next.consecutive_ || next.dofs_.ux != first.dofs_.ux) break;
      ++j;
    }
    block(first.dofs_.ux, elements + i, j - i);
    i = j;
  }
}

template <class ForceOf>
void BearingLink::scatter_run(Element* const* run, int n, int ux, Eigen::VectorXd& f,
                              ForceOf&& force_of) {
  double f0 = f[ux], f1 = f[ux + 1], f2 = f[ux + 2];
  for (int i = 0; i < n; ++i) {
    const auto& link = static_cast<const BearingLink&>(*run[i]);
    const Eigen::Vector2d F = force_of(link);
    f0 += F[0];
    f1 += F[1];
    f2 += link.p_OB_.x() * F[1] - link.p_OB_.y() * F[0];
  }
  f[ux] = f0;
  f[ux + 1] = f1;
  f[ux + 2] = f2;
}

void BearingLink::add_force_batch(Element* const* elements, int count, Eigen::VectorXd& f) const {
  for_each_diaphragm_run(
      elements, count, [&](const BearingLink& link) { link.add_force(f); },
      [&](int ux, Element* const* run, int n) {
        scatter_run(run, n, ux, f, [](const BearingLink& link) { return link.coupled_->force(); });
      });
}

void BearingLink::add_tangent_batch(Element* const* elements, int count, Eigen::MatrixXd& K,
                                    double velocity_factor) const {
  for_each_diaphragm_run(
      elements, count, [&](const BearingLink& link) { link.add_tangent(K, velocity_factor); },
      [&](int ux, Element* const* run, int n) {
        double* column[3] = {&K(ux, ux), &K(ux, ux + 1), &K(ux, ux + 2)};
        double sum[9];
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 3; ++r) sum[3 * c + r] = column[c][r];
        for (int i = 0; i < n; ++i) {
          const auto& link = static_cast<const BearingLink&>(*run[i]);
          // The coupled law is rate independent: no rate tangent to add (adding its zeros
          // changes no bit, as the tangent has no -0 entries).
          double kt[9];
          link.diaphragm_tangent(link.coupled_->tangent(), kt);
          for (int e = 0; e < 9; ++e) sum[e] += kt[e];
        }
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 3; ++r) column[c][r] = sum[3 * c + r];
      });
}

void BearingLink::add_stiffness_product_batch(Element* const* elements, int count,
                                              const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  for_each_diaphragm_run(
      elements, count, [&](const BearingLink& link) { link.add_stiffness_product(x, y); },
      [&](int ux, Element* const* run, int n) {
        scatter_run(run, n, ux, y, [&](const BearingLink& link) -> Eigen::Vector2d {
          return link.coupled_->tangent() * link.deformation_of(x);
        });
      });
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
  if (has_lower_) {
    if (lower_.ux >= 0) f[lower_.ux] -= F[0];
    if (lower_.uy >= 0) f[lower_.uy] -= F[1];
    if (lower_.theta >= 0) f[lower_.theta] -= p_OB_.x() * F[1] - p_OB_.y() * F[0];
  }
}

void BearingLink::add_force(Eigen::VectorXd& f) const {
  scatter(with_law([](const auto& law) { return law.force(); }), f);
}

Eigen::Matrix2d BearingLink::law_tangent(double velocity_factor) const {
  return with_law([&](const auto& law) {
    Eigen::Matrix2d tangent = law.tangent();
    if (velocity_factor != 0.0) tangent += velocity_factor * law.rate_tangent();
    return tangent;
  });
}

void BearingLink::diaphragm_tangent(const Eigen::Matrix2d& k, double kt[9]) const {
  // T^T k T written out (T = [[1, 0, -y], [0, 1, x]]), column by column.
  const double x = p_OB_.x(), y = p_OB_.y();
  const double k02 = x * k(0, 1) - y * k(0, 0), k12 = x * k(1, 1) - y * k(1, 0);
  const double k20 = x * k(1, 0) - y * k(0, 0), k21 = x * k(1, 1) - y * k(0, 1);
  const double k22 = x * k21 - y * k20;  // (T^T k) T, as Eigen associates it
  kt[0] = k(0, 0);
  kt[1] = k(1, 0);
  kt[2] = k20;
  kt[3] = k(0, 1);
  kt[4] = k(1, 1);
  kt[5] = k21;
  kt[6] = k02;
  kt[7] = k12;
  kt[8] = k22;
}

void BearingLink::add_tangent(Eigen::MatrixXd& K, double velocity_factor) const {
  const Eigen::Matrix2d k = law_tangent(velocity_factor);
  if (consecutive_) {
    // (ux, uy, theta) = (i, i + 1, i + 2): added column by column to the contiguous 3x3 block.
    double kt[9];
    diaphragm_tangent(k, kt);
    for (int c = 0; c < 3; ++c) {
      double* column = &K(dofs_.ux, dofs_.ux + c);
      for (int r = 0; r < 3; ++r) column[r] += kt[3 * c + r];
    }
    return;
  }
  // Columns of T for (ux, uy, theta); with a lower diaphragm B = [T, -T] over both.
  const int dof[6] = {dofs_.ux, dofs_.uy, dofs_.theta, lower_.ux, lower_.uy, lower_.theta};
  Eigen::Matrix<double, 2, 3> T;
  T << 1.0, 0.0, -p_OB_.y(), 0.0, 1.0, p_OB_.x();
  const Eigen::Matrix3d kt = T.transpose() * k * T;
  const int n = has_lower_ ? 6 : 3;
  for (int a = 0; a < n; ++a) {
    if (dof[a] < 0) continue;
    for (int b = 0; b < n; ++b)
      if (dof[b] >= 0)
        K(dof[a], dof[b]) += (a < 3) == (b < 3) ? kt(a % 3, b % 3) : -kt(a % 3, b % 3);
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
  write_outputs(F, d, z, out);
}

void BearingLink::write_outputs(const Eigen::Vector2d& F, const Eigen::Vector2d& d,
                                const Eigen::Vector2d& z, double* out) const {
  write_outputs_squared(F, d, z, out);
  if (!planar_) sqrt_each(out, out, 3);
}

void BearingLink::write_outputs_squared(const Eigen::Vector2d& F, const Eigen::Vector2d& d,
                                        const Eigen::Vector2d& z, double* out) const {
  if (planar_) {
    out[0] = F[0];
    out[1] = d[0];
    out[2] = z[0];
    return;
  }
  out[0] = F.squaredNorm();
  out[1] = d.squaredNorm();
  out[2] = z.squaredNorm();
  out[3] = F[0];
  out[4] = F[1];
  out[5] = d[0];
  out[6] = d[1];
  out[7] = z[0];
  out[8] = z[1];
}

void BearingLink::outputs_batch(Element* const* elements, int count, double* out) const {
  // write_outputs() of each, with the resultants' square roots of up to kChunk bearings in
  // plan taken together (planar bearings have none).
  constexpr int kChunk = 16;
  double resultant[3 * kChunk];
  for (int begin = 0; begin < count; begin += kChunk) {
    const int n = std::min(kChunk, count - begin);
    double* const chunk_out = out;
    int r = 0;
    for (int i = 0; i < n; ++i) {
      const auto& link = static_cast<const BearingLink&>(*elements[begin + i]);
      const CoupledBoucWenMaterial& law = *link.coupled_;
      link.write_outputs_squared(law.force(), law.deformation(), law.internal(), out);
      if (!link.planar_)
        for (int k = 0; k < 3; ++k) resultant[r++] = out[k];
      out += link.output_count();
    }
    sqrt_each(resultant, resultant, r);
    double* o = chunk_out;
    r = 0;
    for (int i = 0; i < n; ++i) {
      const auto& link = static_cast<const BearingLink&>(*elements[begin + i]);
      if (!link.planar_)
        for (int k = 0; k < 3; ++k) o[k] = resultant[r++];
      o += link.output_count();
    }
  }
}

void BearingLink::add_energy_batch(Element* const* elements, int count, const Eigen::VectorXd& v,
                                   double& power, double& stored) const {
  for (int i = 0; i < count; ++i) {
    const auto& link = static_cast<const BearingLink&>(*elements[i]);
    power += link.coupled_->force().dot(link.deformation_of(v));
    stored += link.coupled_->stored_energy();
  }
}

double BearingLink::output(int i) const {
  double values[9];
  outputs(values);
  return values[i];
}

}  // namespace isopound
