// Newmark average-acceleration stepper (gamma = 1/2, beta = 1/4) with Newton-Raphson on the
// nonlinear elements. Sees only M, C, K, the influence matrix and Element residual/tangent/commit.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "solver/core/compressed_rows.h"
#include "solver/core/element_batches.h"
#include "solver/core/model.h"
#include "solver/core/small_llt.h"

namespace isopound {

struct NewtonSettings {
  // Converged when max_i |R_i| / length_i <= tolerance * F_ref + round-off allowance, F_ref =
  // heaviest level's weight (max_i (M iota_x)_i g), length_i = Dof::length (1 for a
  // translation); never on a small correction alone.
  double tolerance = 1e-9;
  int max_iterations = 25;
  // Eliminate the linear DOFs once per step size when it pays (see NewmarkStepper); false: always
  // factor the whole matrix (a diagnostic: the results agree to round-off).
  bool block_elimination = true;
};

struct StepOutcome {
  bool converged = false;
  int iterations = 0;
};

// One step from the committed state (u0, v0, a0) at t to the trial state at t + h:
//   u1 = u0 + h v0 + h^2/4 (a0 + a1),  v1 = v0 + h/2 (a0 + a1),
//   M a1 + C v1 + K u1 + f_nl(u1, v1) = -M iota ag1   (iota: n x 2, ag1 = (a_x, a_y)).
// Solved for du = u1 - u0 with K_hat = K + (2/h) C + (4/h^2) M + df_nl/du + (2/h) df_nl/dv,
// factored by Cholesky (LDL^T fallback), or by LU when an element's tangent may be
// non-symmetric (Element::symmetric_tangent()): SmallLu up to 16 unknowns, Eigen's beyond.
// The linear matrices multiply through CompressedRows (their zeros left out); M, C and K are
// read once, at construction.
// Nothing is allocated per step once each distinct h has been seen (K_hat is cached per h).
//
// Block elimination. When the elements declare their DOFs (Element::add_dofs) and leave at least
// kMinLinearDofs of them untouched (a superstructure above the bearings), those linear DOFs s
// are eliminated once per h: with a the element DOFs,
//   [K_ss K_sa; K_as K_aa + E] [x_s; x_a] = [r_s; r_a]  (E: the elements' tangent)
//   (S0 + E) x_a = r_a - K_as K_ss^-1 r_s,  S0 = K_aa - K_as K_ss^-1 K_sa,
//   x_s = K_ss^-1 r_s - (K_ss^-1 K_sa) x_a,
// so a Newton iteration factors only the small (S0 + E) by LU. The same equations as the full
// factorisation, in another order: results agree to round-off.
class NewmarkStepper {
 public:
  // Throws std::invalid_argument if M is not symmetric positive definite (e.g. a DOF without
  // mass): an input error.
  NewmarkStepper(Model& model, const NewtonSettings& settings);

  // Committed state at rest; a0 from equilibrium with ground acceleration ag0.
  void start(GroundAcceleration ag0);
  // Committed state (u0, v0); a0 from the equation of motion with ground acceleration ag0.
  void start(const Eigen::VectorXd& u0, const Eigen::VectorXd& v0, GroundAcceleration ag0);
  // Makes room for `count` step sizes (and the one-off step), so that the first step of each
  // allocates nothing: the analysis's regular steps are H / 2^k, k <= max_halvings.
  void reserve_step_sizes(int count);
  // `cache`: keep K_hat for this h (the regular steps); false for one-off steps cut at an event.
  // `freeze`: elements keep their contact status through the trial (a step cut at an event).
  StepOutcome try_step(double h, GroundAcceleration ag1, bool cache = true, bool freeze = false);
  // After elements changed status at an event (settle_event): a0 from equilibrium at the
  // committed (u, v) with ground acceleration ag, elements re-evaluated and committed.
  void restart(GroundAcceleration ag);
  void accept();  // trial becomes committed (elements commit)
  void reject();  // elements revert; committed state unchanged

  // Local truncation error of the last trial step: e = h^2/12 (a1 - a0) (Zienkiewicz-Xie),
  // measured as max_i |(K_s e)_i| / force_scale_i with K_s the stiffness tangent.
  double error_norm(const Eigen::VectorXd& force_scale);

  const Eigen::VectorXd& u() const { return u0_; }
  const Eigen::VectorXd& v() const { return v0_; }
  const Eigen::VectorXd& a() const { return a0_; }
  // K u, M v and C v at the committed state (each step needs them: the next load, energies).
  // C v is formed when first asked after a step (a small model's step and a sweep reading no
  // energy or shear never ask): the same product whenever it is formed.
  const Eigen::VectorXd& k_u() const { return k_u0_; }
  const Eigen::VectorXd& m_v() const { return m_v0_; }
  const Eigen::VectorXd& c_v() const {
    if (!c_v0_current_) {
      damping_rows_.multiply(v0_, c_v0_);
      c_v0_current_ = true;
    }
    return c_v0_;
  }
  // The model's elements by batches (the analysis records their outputs and energy through it).
  const ElementBatches& batches() const { return batches_; }
  const Eigen::VectorXd& trial_u() const { return u1_; }
  const Eigen::VectorXd& trial_v() const { return v1_; }
  const Eigen::VectorXd& trial_a() const { return a1_; }
  const Eigen::VectorXd& residual() const { return r_; }
  double last_step() const { return h_; }
  // True when the Newton matrix is factored by LU (some element's tangent is non-symmetric).
  bool uses_lu() const { return use_lu_; }
  // True when the Newton matrix is solved by eliminating the linear DOFs (see above).
  bool uses_block_elimination() const { return use_blocks_; }

 private:
  // K_hat and, with the block elimination, its linear-block terms for step h.
  struct EffectiveLinear {
    double h = 0.0;
    Eigen::MatrixXd k_hat;        // K + 2/h C + 4/h^2 M
    Eigen::MatrixXd k_ss_inv;     // K_ss^-1 (linear DOFs)
    Eigen::MatrixXd k_ss_inv_sa;  // K_ss^-1 K_sa
    Eigen::MatrixXd k_as;         // K_as
    Eigen::MatrixXd k_sa;         // K_sa
    Eigen::MatrixXd schur;        // S0 = K_aa - K_as K_ss^-1 K_sa
    // The matrices the iterations multiply by (the same products, without the zeros).
    CompressedRows k_hat_rows, k_ss_inv_rows, k_as_rows, k_ss_inv_sa_rows;
    bool blocks = false;  // the block terms are set (else: the full factorisation)
    // Small models whose elements all act on one DOF (single_element_dof_: a single isolator to
    // the ground, every 2D isolated building without contacts): K_hat's inverse, when K_hat is
    // positive definite (k_hat_inverted). The tangent differs from K_hat in that DOF's diagonal
    // entry alone and is solved from it by solve_diagonal_update, without a factorisation.
    Eigen::MatrixXd k_hat_inverse;
    CompressedRows k_hat_inverse_rows;  // the same matrix, for its product
    bool k_hat_inverted = false;
  };
  const EffectiveLinear& effective_linear(double h, bool cache);
  // try_step for kSize DOFs (0: any number).
  template <int kSize>
  StepOutcome try_step_sized(double h, GroundAcceleration ag1, bool cache, bool freeze);
  void fill_effective_linear(double h, EffectiveLinear& e);
  // du_ = (K_hat + element tangent)^-1 r_ by block elimination (the tangent in k_elements_).
  void solve_blocks(const EffectiveLinear& e);
  // x = a^-1 b by LU with partial pivoting: SmallLu up to its size (a is overwritten by the
  // factors; the callers rebuild it every iteration), eigen_lu beyond.
  void solve_lu(Eigen::MatrixXd& a, Eigen::PartialPivLU<Eigen::MatrixXd>& eigen_lu,
                const Eigen::VectorXd& b, Eigen::VectorXd& x);
  // du_ = k_tangent_^-1 r_: from K_hat's inverse when the elements act on one DOF
  // (EffectiveLinear::k_hat_inverted), else by Cholesky, SmallLlt up to its size (Eigen's LLT
  // factor, the solve by the pivots' reciprocals), llt_ beyond; false
  // (k_tangent_ unchanged) when not positive definite.
  template <int kSize>  // kSize > 0: the DOF count, known at compile time (0: any)
  bool solve_llt(const EffectiveLinear& linear);
  template <int kSize>
  double error_norm_sized(const Eigen::VectorXd& force_scale);

  Model& model_;
  NewtonSettings settings_;
  double force_ref_;
  Eigen::VectorXd u0_, v0_, a0_, u1_, v1_, a1_;
  Eigen::VectorXd k_u0_, m_v0_;   // K u0 and M v0
  mutable Eigen::VectorXd c_v0_;  // C v0, when c_v0_current_ (see c_v())
  mutable bool c_v0_current_ = false;
  void committed_products();
  Eigen::VectorXd p_hat_, r_, du_, work_;
  Eigen::MatrixXd m_iota_;  // M iota, n x 2
  // M, K and C for their products.
  CompressedRows mass_rows_, stiffness_rows_, damping_rows_;
  Eigen::VectorXd residual_weight_;  // 1 / Dof::length
  bool use_lu_ = false;
  Eigen::VectorXd delta_;  // u1 - u0 of the trial
  Eigen::MatrixXd k_tangent_;
  // Factorisations are only ever computed in place, never copied (an unused Eigen
  // factorisation holds uninitialised state).
  Eigen::LLT<Eigen::MatrixXd> llt_;
  // Small models: the last kRememberedFactors matrices SmallLlt factored, with their factors. A
  // tangent that comes back (a bilinear isolator's takes two values, at a few step sizes) is
  // recognised bit for bit and its factor reused: the same matrix has the same factor.
  struct RememberedFactor {
    Eigen::MatrixXd matrix, factor;
    std::array<double, SmallLlt::kMaxSize> inverse_pivots{};
    bool set = false;
  };
  static constexpr int kRememberedFactors = 4;
  std::vector<RememberedFactor> factors_;
  int next_factor_ = 0;  // the entry the next new factor replaces
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;  // beyond SmallLu::kMaxSize
  Eigen::LLT<Eigen::MatrixXd> mass_llt_;
  std::vector<EffectiveLinear> k_hat_cache_;
  EffectiveLinear k_hat_uncached_;
  // Block elimination (see above): element DOFs a and linear DOFs s, in index order.
  static constexpr int kMinLinearDofs = 8;
  std::vector<Element*> eventful_;  // Element::has_events(): they get begin_step
  ElementBatches batches_;          // the hot element calls, by runs of one batch key
  bool use_blocks_ = false;
  bool stiffness_products_ = false;  // error_norm from Element::add_stiffness_product
  std::vector<int> element_dofs_, linear_dofs_;
  // >= 0: every element acts on this DOF alone (a small symmetric model): see k_hat_inverted.
  int single_element_dof_ = -1;
  Eigen::MatrixXd k_hat_factor_;  // scratch: K_hat's Cholesky factor while its inverse is formed
  std::array<double, SmallLlt::kMaxSize> k_hat_inverse_pivots_{};
  Eigen::MatrixXd k_elements_;                     // the elements' tangent (nonzero only on a x a)
  Eigen::MatrixXd schur_;                          // S0 + E
  Eigen::PartialPivLU<Eigen::MatrixXd> schur_lu_;  // beyond SmallLu::kMaxSize
  // SmallLu's row swaps (of the full matrix or of the Schur complement).
  std::vector<int> pivots_;
  Eigen::VectorXd r_s_, r_a_, y_s_, x_a_;
  Eigen::LLT<Eigen::MatrixXd> k_ss_llt_;
  double h_ = 0.0;
};

}  // namespace isopound
