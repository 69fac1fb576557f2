// Newmark average-acceleration stepper with Newton-Raphson: effective linear matrix cached per
// step size, element tangents added each iteration, Cholesky (LDL^T fallback) or LU solve.
#include "solver/core/newmark.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "solver/core/constants.h"
#include "solver/core/diagonal_update.h"
#include "solver/core/sized_dispatch.h"
#include "solver/core/small_llt.h"
#include "solver/core/small_lu.h"

namespace isopound {

namespace {

// The step's vector arithmetic as plain loops over the DOFs: element for element the operations
// of the Eigen expressions they replace (a max is exact, whatever the order), without Eigen's
// dispatch, which costs more than the arithmetic on a 2D building's four or six DOFs.
// (A loop, not std::copy: a call to memcpy costs more than copying four doubles.)
// kCount > 0: the number of values, known at compile time (0: from's size).
template <int kCount = 0, class Dense>
void copy(const Dense& from, Dense& to) {
  const double* f = from.data();
  double* t = to.data();
  const Eigen::Index size = kCount > 0 ? kCount : from.size();
  for (Eigen::Index i = 0; i < size; ++i) t[i] = f[i];
}

// from[0..count) and to[0..count) equal bit for bit (as memcmp: -0 and +0 differ), word by word
// with an early exit when the count is known at compile time (kCount > 0): a call to memcmp costs
// more than finding that a new tangent differs in its first words.
template <int kCount>
bool same_bits(const double* a, const double* b, Eigen::Index count) {
  if constexpr (kCount == 0) {
    return std::memcmp(a, b, static_cast<std::size_t>(count) * sizeof(double)) == 0;
  } else {
    for (int i = 0; i < kCount; ++i)
      if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
    return true;
  }
}

// max_i term(i) over i < n of terms >= 0; NaN if a term is NaN (the callers test for it).
template <class Term>
double max_of(int n, Term&& term) {
  double m = 0.0;
  bool nan = false;
  for (int i = 0; i < n; ++i) {
    const double x = term(i);
    nan = nan || std::isnan(x);
    m = std::max(m, x);
  }
  return nan ? std::numeric_limits<double>::quiet_NaN() : m;
}

}  // namespace

NewmarkStepper::NewmarkStepper(Model& model, const NewtonSettings& settings)
    : model_(model),
      settings_(settings),
      llt_(model.size()),
      ldlt_(model.size()),
      batches_(model.elements) {
  const int n = model.size();
  for (Eigen::VectorXd* x : {&u0_, &v0_, &a0_, &k_u0_, &m_v0_, &c_v0_, &u1_, &v1_, &a1_, &p_hat_,
                             &r_, &du_, &work_, &delta_})
    x->setZero(n);
  m_iota_ = model.ground_load_matrix();
  force_ref_ = m_iota_.col(0).cwiseAbs().maxCoeff() * kGravity;
  residual_weight_.resize(n);
  for (int i = 0; i < n; ++i) residual_weight_[i] = 1.0 / model.dofs[i].length;
  for (const auto& e : model.elements) use_lu_ = use_lu_ || !e->symmetric_tangent();
  for (const auto& e : model.elements)
    if (e->has_events()) eventful_.push_back(e.get());
  k_tangent_.setZero(n, n);
  if (n <= SmallLlt::kMaxSize) {
    factors_.resize(kRememberedFactors);
    for (RememberedFactor& f : factors_) {
      f.matrix.setZero(n, n);
      f.factor.setZero(n, n);
    }
  }
  pivots_.resize(static_cast<std::size_t>(n));
  mass_rows_.assign(model.mass);
  stiffness_rows_.assign(model.stiffness);
  damping_rows_.assign(model.damping);
  // Block elimination when every element declares its DOFs and enough DOFs stay linear.
  bool declared = true;
  for (const auto& e : model.elements) declared = e->add_dofs(element_dofs_) && declared;
  std::sort(element_dofs_.begin(), element_dofs_.end());
  element_dofs_.erase(std::unique(element_dofs_.begin(), element_dofs_.end()), element_dofs_.end());
  for (int i = 0, k = 0; i < n; ++i) {
    if (k < static_cast<int>(element_dofs_.size()) && element_dofs_[k] == i)
      ++k;
    else
      linear_dofs_.push_back(i);
  }
  const int n_a = static_cast<int>(element_dofs_.size());
  const int n_s = static_cast<int>(linear_dofs_.size());
  use_blocks_ = settings.block_elimination && declared && n_a > 0 && n_s >= kMinLinearDofs;
  // Every element on one DOF (a single isolator to the ground) of a small symmetric model: the
  // tangent is K_hat but for that diagonal entry, solved from K_hat's inverse (formed with the
  // scratch factor below).
  if (declared && n_a == 1 && !use_blocks_ && !use_lu_ && n <= SmallLlt::kMaxSize) {
    single_element_dof_ = element_dofs_[0];
    k_hat_factor_.setZero(n, n);
  }
  // The error estimate takes the elements' stiffness products when all provide them (the
  // assembled tangent times e, to round-off): no n x n tangent to assemble after every step.
  stiffness_products_ = true;
  for (const auto& e : model.elements)
    stiffness_products_ = stiffness_products_ && e->has_stiffness_product();
  if (use_blocks_) {
    k_elements_.setZero(n, n);
    schur_.setZero(n_a, n_a);
    // Sized by a first in-place factorisation (never by assigning a sized but unfactorised
    // object: Eigen leaves its status uninitialised, and copying it is undefined behaviour).
    schur_lu_.compute(Eigen::MatrixXd::Identity(n_a, n_a));
    r_s_.setZero(n_s);
    y_s_.setZero(n_s);
    r_a_.setZero(n_a);
    x_a_.setZero(n_a);
    k_ss_llt_.compute(Eigen::MatrixXd::Identity(n_s, n_s));
  }
  // The accelerations come from M^-1: a mass matrix that is not symmetric positive definite
  // (a DOF without mass, a negative or NaN mass) is an input error, not a numerical accident.
  if (model.mass.rows() != n || model.mass.cols() != n)
    throw std::invalid_argument("mass matrix is " + std::to_string(model.mass.rows()) + "x" +
                                std::to_string(model.mass.cols()) + " for " + std::to_string(n) +
                                " DOFs");
  for (int i = 0; i < n; ++i)
    if (!(model.mass(i, i) > 0) || !std::isfinite(model.mass(i, i)))
      throw std::invalid_argument("DOF '" + model.dofs[i].label + "' has mass " +
                                  std::to_string(model.mass(i, i)) +
                                  " kg: every DOF needs a positive mass");
  if (!model.mass.isApprox(model.mass.transpose()))
    throw std::invalid_argument("mass matrix is not symmetric");
  mass_llt_.compute(model.mass);
  if (mass_llt_.info() != Eigen::Success)
    throw std::invalid_argument("mass matrix is not positive definite");
  // Condition: the smallest pivot of the factor against the largest (a singular M in all but
  // name would give accelerations of round-off).
  const Eigen::VectorXd pivots = Eigen::MatrixXd(mass_llt_.matrixL()).diagonal();
  if (pivots.minCoeff() <= 1e-7 * pivots.maxCoeff())
    throw std::invalid_argument("mass matrix is singular to working precision");
  if (use_lu_) lu_.compute(Eigen::MatrixXd::Identity(n, n));
}

void NewmarkStepper::start(GroundAcceleration ag0) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model_.size());
  start(zero, zero, ag0);
}

void NewmarkStepper::start(const Eigen::VectorXd& u0, const Eigen::VectorXd& v0,
                           GroundAcceleration ag0) {
  u0_ = u0;
  v0_ = v0;
  committed_products();
  restart(ag0);
}

void NewmarkStepper::restart(GroundAcceleration ag0) {
  u1_ = u0_;
  v1_ = v0_;
  delta_.setZero();
  for (auto& e : model_.elements) {
    if (e->has_events()) e->begin_step(0.0, true);  // zero length: no work, status kept
    e->set_trial(u0_, v0_);
  }
  // M a0 = -M iota ag0 - C v0 - K u0 - f_nl(u0, v0)
  work_ = -m_iota_.col(0) * ag0.x;
  if (ag0.y != 0.0) work_ -= m_iota_.col(1) * ag0.y;
  work_.noalias() -= model_.damping * v0_;
  work_.noalias() -= model_.stiffness * u0_;
  for (auto& e : model_.elements) {
    r_.setZero();
    e->add_force(r_);
    work_ -= r_;
  }
  a0_ = mass_llt_.solve(work_);
  a1_ = a0_;
  for (auto& e : model_.elements) e->commit();
}

void NewmarkStepper::fill_effective_linear(double h, EffectiveLinear& e) {
  e.h = h;
  e.k_hat = model_.stiffness;
  e.k_hat += (2.0 / h) * model_.damping;
  e.k_hat += (4.0 / (h * h)) * model_.mass;
  e.k_hat_rows.assign(e.k_hat);
  e.blocks = false;
  e.k_hat_inverted = false;
  if (single_element_dof_ >= 0) {
    const Eigen::Index n = e.k_hat.rows();
    k_hat_factor_ = e.k_hat;
    e.k_hat_inverted = SmallLlt::factor(k_hat_factor_, k_hat_inverse_pivots_.data());
    if (!e.k_hat_inverted) return;
    e.k_hat_inverse.resize(n, n);  // sized once (reserve_step_sizes)
    for (Eigen::Index j = 0; j < n; ++j) {
      du_.setZero();
      du_[j] = 1.0;
      SmallLlt::solve(k_hat_factor_, k_hat_inverse_pivots_.data(), du_);
      e.k_hat_inverse.col(j) = du_;
    }
    e.k_hat_inverse_rows.assign(e.k_hat_inverse);
  }
  if (!use_blocks_) return;
  // Blocks gathered by plain loops (Eigen's indexed views copy a std::vector index: allocations).
  const auto gather = [&](const std::vector<int>& rows, const std::vector<int>& cols,
                          Eigen::MatrixXd& block) {
    block.resize(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
    for (std::size_t j = 0; j < cols.size(); ++j)
      for (std::size_t i = 0; i < rows.size(); ++i) block(i, j) = e.k_hat(rows[i], cols[j]);
  };
  // K_ss is K_hat's linear block: positive definite with M (4/h^2 M dominates).
  gather(linear_dofs_, linear_dofs_, e.k_ss_inv);
  k_ss_llt_.compute(e.k_ss_inv);
  if (k_ss_llt_.info() != Eigen::Success) return;  // the full factorisation for this h
  e.k_ss_inv.setIdentity();
  k_ss_llt_.solveInPlace(e.k_ss_inv);
  gather(element_dofs_, linear_dofs_, e.k_as);
  gather(linear_dofs_, element_dofs_, e.k_sa);
  e.k_ss_inv_sa.noalias() = e.k_ss_inv * e.k_sa;
  gather(element_dofs_, element_dofs_, e.schur);
  e.schur.noalias() -= e.k_as * e.k_ss_inv_sa;
  e.k_ss_inv_rows.assign(e.k_ss_inv);
  e.k_as_rows.assign(e.k_as);
  e.k_ss_inv_sa_rows.assign(e.k_ss_inv_sa);
  e.blocks = true;
}

const NewmarkStepper::EffectiveLinear& NewmarkStepper::effective_linear(double h, bool cache) {
  for (const EffectiveLinear& e : k_hat_cache_)
    if (e.h == h) return e;
  if (!cache) {
    fill_effective_linear(h, k_hat_uncached_);
    return k_hat_uncached_;
  }
  for (EffectiveLinear& e : k_hat_cache_)
    if (e.h == 0.0) {  // a reserved entry
      fill_effective_linear(h, e);
      return e;
    }
  k_hat_cache_.emplace_back();
  fill_effective_linear(h, k_hat_cache_.back());
  return k_hat_cache_.back();
}

void NewmarkStepper::reserve_step_sizes(int count) {
  // Entries of h = 0 (never a step) with their matrices at full size: filling one later
  // allocates nothing.
  const Eigen::Index n = model_.size();
  const auto n_a = static_cast<Eigen::Index>(element_dofs_.size());
  const auto n_s = static_cast<Eigen::Index>(linear_dofs_.size());
  k_hat_cache_.reserve(k_hat_cache_.size() + static_cast<std::size_t>(count));
  for (EffectiveLinear* e = &k_hat_uncached_; count >= 0; --count) {
    e->k_hat.resize(n, n);
    e->k_hat_rows.reserve(n, n);
    if (single_element_dof_ >= 0) {
      e->k_hat_inverse.resize(n, n);
      e->k_hat_inverse_rows.reserve(n, n);
    }
    if (use_blocks_) {
      e->k_ss_inv_rows.reserve(n_s, n_s);
      e->k_as_rows.reserve(n_a, n_s);
      e->k_ss_inv_sa_rows.reserve(n_s, n_a);
      e->k_ss_inv.resize(n_s, n_s);
      e->k_as.resize(n_a, n_s);
      e->k_sa.resize(n_s, n_a);
      e->k_ss_inv_sa.resize(n_s, n_a);
      e->schur.resize(n_a, n_a);
    }
    if (count > 0) e = &k_hat_cache_.emplace_back();
  }
}

void NewmarkStepper::solve_blocks(const EffectiveLinear& e) {
  // Plain loops for the gathers: Eigen's indexed views copy a std::vector index (an allocation).
  const int n_a = static_cast<int>(element_dofs_.size());
  const int n_s = static_cast<int>(linear_dofs_.size());
  for (const int i : element_dofs_)
    for (const int j : element_dofs_) k_elements_(i, j) = 0.0;
  batches_.add_tangents(k_elements_, 2.0 / h_);
  for (int j = 0; j < n_a; ++j)
    for (int i = 0; i < n_a; ++i)
      schur_(i, j) = e.schur(i, j) + k_elements_(element_dofs_[i], element_dofs_[j]);
  for (int i = 0; i < n_s; ++i) r_s_[i] = r_[linear_dofs_[i]];
  for (int i = 0; i < n_a; ++i) r_a_[i] = r_[element_dofs_[i]];
  e.k_ss_inv_rows.multiply(r_s_, y_s_);  // K_ss^-1 r_s
  e.k_as_rows.subtract_product(y_s_, r_a_);
  solve_lu(schur_, schur_lu_, r_a_, x_a_);
  e.k_ss_inv_sa_rows.subtract_product(x_a_, y_s_);
  for (int i = 0; i < n_a; ++i) du_[element_dofs_[i]] = x_a_[i];
  for (int i = 0; i < n_s; ++i) du_[linear_dofs_[i]] = y_s_[i];
}

void NewmarkStepper::solve_lu(Eigen::MatrixXd& a, Eigen::PartialPivLU<Eigen::MatrixXd>& eigen_lu,
                              const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (a.rows() > SmallLu::kMaxSize) {
    eigen_lu.compute(a);
    x = eigen_lu.solve(b);
    return;
  }
  SmallLu::factor(a, pivots_.data());
  x = b;
  SmallLu::solve(a, pivots_.data(), x);
}

template <int kSize>
bool NewmarkStepper::solve_llt(const EffectiveLinear& linear) {
  if (linear.k_hat_inverted) {
    // The elements added to one diagonal entry of K_hat alone.
    const int j = single_element_dof_;
    if (solve_diagonal_update(linear.k_hat_inverse_rows, linear.k_hat_inverse, j,
                              k_tangent_(j, j) - linear.k_hat(j, j), r_, du_))
      return true;
  }
  if (k_tangent_.rows() <= SmallLlt::kMaxSize) {
    const RememberedFactor* known = nullptr;
    for (const RememberedFactor& f : factors_)
      if (f.set && same_bits<kSize * kSize>(f.matrix.data(), k_tangent_.data(), k_tangent_.size()))
        known = &f;
    if (!known) {
      RememberedFactor& f = factors_[static_cast<std::size_t>(next_factor_)];
      copy<kSize * kSize>(k_tangent_, f.factor);  // the same size every time
      f.set = SmallLlt::factor(f.factor, f.inverse_pivots.data());
      if (!f.set) return false;
      copy<kSize * kSize>(k_tangent_, f.matrix);
      next_factor_ = (next_factor_ + 1) % kRememberedFactors;
      known = &f;
    }
    copy<kSize>(r_, du_);
    SmallLlt::solve(known->factor, known->inverse_pivots.data(), du_);
    return true;
  }
  llt_.compute(k_tangent_);
  if (llt_.info() != Eigen::Success) return false;
  du_ = llt_.solve(r_);
  return true;
}

StepOutcome NewmarkStepper::try_step(double h, GroundAcceleration ag1, bool cache, bool freeze) {
  // A small model's DOF count as a template argument: the loops unroll, without the vectoriser's
  // alias and remainder tests, which cost more than four or six elements. The same operations.
  return dispatch_size(u0_.size(), [&]<int kN>() {
    constexpr int kSize = kN == 1 ? 0 : kN;  // one DOF: the run-time path, as before
    return try_step_sized<kSize>(h, ag1, cache, freeze);
  });
}

template <int kSize>
StepOutcome NewmarkStepper::try_step_sized(double h, GroundAcceleration ag1, bool cache,
                                           bool freeze) {
  h_ = h;
  const EffectiveLinear& linear = effective_linear(h, cache);
  for (Element* e : eventful_) e->begin_step(h, freeze);
  const int n = kSize > 0 ? kSize : static_cast<int>(u0_.size());
  const double c1 = 4.0 / (h * h), c2 = 4.0 / h;
  const double *u0 = u0_.data(), *v0 = v0_.data(), *a0 = a0_.data();
  double *u1 = u1_.data(), *v1 = v1_.data(), *delta = delta_.data(), *r = r_.data();
  double* p_hat = p_hat_.data();
  // Incremental form: the unknown is du = u1 - u0, so that a1 = 4/h^2 du - 4/h v0 - a0 carries
  // round-off relative to du, not to u0 (which would swamp the accelerations of short steps).
  //   R(du) = K_hat du + r0 + f_nl(u0 + du, v1),
  //   r0 = K u0 - M (4/h v0 + a0) - C v0 + M iota ag1.
  for (int i = 0; i < n; ++i) work_[i] = c2 * v0[i] + a0[i];
  copy<kSize>(k_u0_, p_hat_);
  mass_rows_.subtract_product(work_, p_hat_);
  // Subtracting C v0 as one product or accumulating it differ in rounding: small models keep
  // their arithmetic (results unchanged since issue 8); the block-eliminated ones reuse C v0.
  if (use_blocks_) {
    const double* c_v0 = c_v().data();
    for (int i = 0; i < n; ++i) p_hat[i] -= c_v0[i];
  } else {
    damping_rows_.subtract_product(v0_, p_hat_);
  }
  const double* iota_x = m_iota_.data();  // M iota by columns
  for (int i = 0; i < n; ++i) p_hat[i] += iota_x[i] * ag1.x;
  if (ag1.y != 0.0)
    for (int i = 0; i < n; ++i) p_hat[i] += iota_x[n + i] * ag1.y;
  const double tol_r = settings_.tolerance * force_ref_ +
                       64.0 * std::numeric_limits<double>::epsilon() *
                           (max_of(n, [&](int i) { return std::abs(p_hat[i]); }) +
                            c2 * max_of(n, [&](int i) { return std::abs(m_v0_[i]); }));

  const double half_h2 = 0.5 * h * h, c_v = 2.0 / h;
  for (int i = 0; i < n; ++i) delta[i] = h * v0[i] + half_h2 * a0[i];  // constant acceleration
  const double* weight = residual_weight_.data();
  StepOutcome out;
  for (int it = 0; it <= settings_.max_iterations; ++it) {
    for (int i = 0; i < n; ++i) {
      u1[i] = u0[i] + delta[i];
      v1[i] = c_v * delta[i] - v0[i];
    }
    batches_.set_trials(u1_, v1_);
    linear.k_hat_rows.multiply(delta_, r_);
    for (int i = 0; i < n; ++i) r[i] += p_hat[i];
    batches_.add_forces(r_);
    const double r_norm = max_of(n, [&](int i) { return std::abs(r[i]) * weight[i]; });
    if (!std::isfinite(r_norm)) break;
    out.iterations = it;
    // Only a small residual converges: a tiny correction alone may mean a stalled iteration.
    if (r_norm <= tol_r) {
      out.converged = true;
      break;
    }
    if (it == settings_.max_iterations) break;
    if (linear.blocks) {
      solve_blocks(linear);
    } else {
      copy<kSize * kSize>(linear.k_hat, k_tangent_);
      batches_.add_tangents(k_tangent_, c_v);
      if (use_lu_) {
        solve_lu(k_tangent_, lu_, r_, du_);
      } else if (!solve_llt<kSize>(linear)) {  // not positive definite: LDL^T
        ldlt_.compute(k_tangent_);
        du_ = ldlt_.solve(r_);
      }
    }
    for (int i = 0; i < n; ++i) delta[i] -= du_[i];
  }
  for (int i = 0; i < n; ++i) a1_[i] = c1 * delta[i] - c2 * v0[i] - a0[i];
  return out;
}

double NewmarkStepper::error_norm(const Eigen::VectorXd& force_scale) {
  return dispatch_size(u0_.size(), [&]<int kN>() {
    constexpr int kSize = kN == 1 ? 0 : kN;  // as try_step
    return error_norm_sized<kSize>(force_scale);
  });
}

template <int kSize>
double NewmarkStepper::error_norm_sized(const Eigen::VectorXd& force_scale) {
  // e = h^2/12 (a1 - a0); force error K_s e with K_s = K + element stiffness tangents.
  const int n = kSize > 0 ? kSize : static_cast<int>(work_.size());
  const double scale = h_ * h_ / 12.0;
  for (int i = 0; i < n; ++i) work_[i] = scale * (a1_[i] - a0_[i]);
  if (stiffness_products_) {
    // The elements' products, not their assembled tangents (the same to round-off).
    stiffness_rows_.multiply(work_, du_);
    batches_.add_stiffness_products(work_, du_);
    return max_of(n, [&](int i) { return std::abs(du_[i]) / force_scale[i]; });
  }
  copy<kSize * kSize>(model_.stiffness, k_tangent_);
  batches_.add_tangents(k_tangent_, 0.0);
  // max_i |(K_s e)_i| / force_scale_i, each row summed as Eigen's column-major product sums it
  // (from 0, in column order) without its dispatch: a small model's step is a few hundred flops.
  double norm = 0.0;
  for (int i = 0; i < n; ++i) {
    double row = 0.0;
    for (int j = 0; j < n; ++j) row += k_tangent_(i, j) * work_[j];
    const double x = std::abs(0.0 + row) / force_scale[i];
    if (std::isnan(x)) return x;
    norm = std::max(norm, x);
  }
  return norm;
}

void NewmarkStepper::accept() {
  for (auto& e : model_.elements) e->commit();
  copy(u1_, u0_);
  copy(v1_, v0_);
  copy(a1_, a0_);
  committed_products();
}

void NewmarkStepper::committed_products() {
  stiffness_rows_.multiply(u0_, k_u0_);
  mass_rows_.multiply(v0_, m_v0_);
  c_v0_current_ = false;  // C v0 when asked (c_v())
}

void NewmarkStepper::reject() {
  for (auto& e : model_.elements) e->revert();
  delta_.setZero();
  copy(u0_, u1_);
  copy(v0_, v1_);
  copy(a0_, a1_);
}

}  // namespace isopound
