// Coupled biaxial Bouc-Wen bearing (THEORY eq. 5.27-5.29, circular interaction):
// F = alpha K_el d + (1-alpha) F_y z, u_y dz = A dd - z |z|^(n-2) [gamma (|dd_x z_x| + |dd_y z_y|)
// + beta dd.z].
#pragma once

#include <Eigen/Dense>

#include "solver/materials/biaxial_material.h"
#include "solver/materials/bouc_wen.h"

namespace isopound {

// The same parameters in x and y (an isotropic bearing); n >= 1.
//
// z is rate independent, so within a step (a straight deformation path dd) it is an ODE in the
// arc length l = |dd|/u_y along the fixed direction e = dd/|dd|:
//   dz/dl = Phi(z) = A e - g(z) sum_i c_i e_i z_i,  g(z) = z |z|^(n-2),  c_i = beta + gamma s_i,
// with s_i = sgn(e_i z_i) constant until a component z_i crosses 0. The scheme is the uniaxial
// BoucWenMaterial's, component for component: the path is split where a component crosses 0
// (closed form, as Phi_i = A e_i there), each branch is integrated with implicit trapezoidal
// sub-increments of fixed size h_sub = 1/(4 n |w| z_b^(n-1)), w = (c_i e_i), plus a remainder
// (closed form z_1 = 2 b/(1 + sqrt(1 + 2 h w.b)) for n = 2, z_1 parallel to b). On a uniaxial
// path (dd_y = z_y = 0) every quantity reduces algebraically to the uniaxial scheme, so the
// force equals BoucWenMaterial's to round-off. The consistent tangent dz/dd is chain-ruled through
// every sub-increment, including the dependence of h_sub and of the split points on the
// direction e (the non-symmetric coupling).
class CoupledBoucWenMaterial final : public BiaxialMaterial {
 public:
  explicit CoupledBoucWenMaterial(const BoucWenParameters& p);

  void set_trial(const Eigen::Vector2d& d, const Eigen::Vector2d& rate) override;
  // Inline: the bearings' batches sum them in registers (BearingLink::add_force_batch).
  Eigen::Vector2d force() const override {
    return p_.alpha * p_.elastic_stiffness * d_ + (1.0 - p_.alpha) * p_.yield_force * z_;
  }
  Eigen::Matrix2d tangent() const override {
    return p_.alpha * p_.elastic_stiffness * Eigen::Matrix2d::Identity() +
           hysteretic_stiffness_ * dz_dx_;
  }
  bool symmetric_tangent() const override { return false; }
  Eigen::Vector2d internal() const override { return z_; }
  // As the uniaxial law: elastic spring plus the recoverable part of the hysteretic spring.
  double stored_energy() const override {
    return 0.5 * p_.alpha * p_.elastic_stiffness * d_.squaredNorm() +
           hysteretic_energy_ * z_.squaredNorm();
  }
  Eigen::Vector2d deformation() const override { return d_; }
  void commit() override;
  void revert() override;
  std::unique_ptr<BiaxialMaterial> clone() const override {
    return std::make_unique<CoupledBoucWenMaterial>(*this);
  }

  // z and dz/dx (x = d/u_y) after the straight increment dx from z0 (exposed for tests and for
  // laws that reuse this hysteretic variable).
  struct ZUpdate {
    Eigen::Vector2d z;
    Eigen::Matrix2d dz_dx;
  };
  // closed_form_n2 = false: never the n = 2 closed form (tests compare the two paths).
  ZUpdate integrate(const Eigen::Vector2d& z0, const Eigen::Vector2d& dx,
                    bool closed_form_n2 = true) const;

  // set_trial(d[i], 0) of law[i], i < n <= kTrialBatch, all at once (set_trial() is the case
  // n = 1): the n = 2 closed forms' square roots and divisions are taken together (independent,
  // so they overlap).
  static constexpr int kTrialBatch = 16;
  static void set_trials(CoupledBoucWenMaterial* const* law, const Eigen::Vector2d* d, int n);

 private:
  // Phi(z) = M(z) e, M = A I - g(z) (c o z)^T; its Jacobian dPhi/dz.
  Eigen::Matrix2d phi_matrix(const Eigen::Vector2d& z, const Eigen::Vector2d& c) const;
  Eigen::Matrix2d phi_jacobian(const Eigen::Vector2d& z, const Eigen::Vector2d& w) const;
  // Both at once, w = c o e; returns |z|.
  double phi_parts(const Eigen::Vector2d& z, const Eigen::Vector2d& c, const Eigen::Vector2d& w,
                   Eigen::Matrix2d& M, Eigen::Matrix2d& J) const;
  // The same with r = |z| already known.
  double phi_parts(const Eigen::Vector2d& z, double r, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& w, Eigen::Matrix2d& M, Eigen::Matrix2d& J) const;
  // One trapezoidal sub-increment of size h >= 0 along e from z (Phi(z) = phi_z).
  Eigen::Vector2d trapezoid_step(const Eigen::Vector2d& z, const Eigen::Vector2d& phi_z, double h,
                                 const Eigen::Vector2d& e, const Eigen::Vector2d& c) const;
  double pow_n_minus_2(double r) const;  // r^(n-2) for r > 0
  // integrate() for n = 2 when the increment is one remainder sub-increment on one branch (the
  // common case); false when the general path is needed.
  bool integrate_single_step_n2(const Eigen::Vector2d& z0, const Eigen::Vector2d& dx,
                                Eigen::Vector2d& z_out, Eigen::Matrix2d& dz_dx_out) const;
  // The closed form in two parts around q = sqrt(discriminant) and inv = 1 / (q (1 + q)):
  // n2_prepare() is false when the general path is needed (s is then meaningless).
  // Their arithmetic is written once, on numbers T: double for one law, or (n2_prepare_two,
  // n2_finish_two) two lanes of doubles for two laws, lane by lane the same operations.
  template <class T>
  struct N2Terms {
    T z0x, z0y, c0, c1, W0, W1, bx, by, z_sq, discriminant;
  };
  using N2Step = N2Terms<double>;
  template <class T>
  struct N2Parameters {
    T beta, gamma, A, z_saturation_sq, z_bound_sq;
  };
  N2Parameters<double> n2_parameters() const {
    return {p_.beta, p_.gamma, p_.A, z_saturation_sq_, z_bound_sq_};
  }
  // s from z0 and the increment dx (x = d/u_y); whether the closed form applies (T's comparison:
  // a bool or a lane mask). s is written either way.
  template <class T>
  static decltype(T() < T()) n2_setup(const N2Parameters<T>& p, T z0x, T z0y, T dx0, T dx1,
                                      N2Terms<T>& s);
  // z1 and S = dz/dx (S(0, 0), S(0, 1), S(1, 0), S(1, 1)) from s, before any rim projection.
  template <class T>
  static void n2_map(const T& A, const N2Terms<T>& s, const T& q, const T& inv, T& z1x, T& z1y,
                     T S[4]);
  bool n2_prepare(const Eigen::Vector2d& z0, const Eigen::Vector2d& dx, N2Step& s) const;
  void n2_finish(const N2Step& s, double q, double inv, Eigen::Vector2d& z_out,
                 Eigen::Matrix2d& dz_dx_out) const;
  // n2_finish()'s last part: z (and S = dz/dx) back onto the rim when the map left the disc.
  void n2_rim(const N2Step& s, Eigen::Vector2d& z, Eigen::Matrix2d& S) const;
#if defined(__GNUC__) && !defined(__clang__) && defined(__SSE2__)
#define ISOPOUND_PAIRED_N2 1
  // n2_prepare() and n2_finish() of two laws at once, in two lanes (bit for bit the same).
  static void n2_prepare_two(const CoupledBoucWenMaterial& a, const CoupledBoucWenMaterial& b,
                             const Eigen::Vector2d& dx_a, const Eigen::Vector2d& dx_b, N2Step& s_a,
                             N2Step& s_b, bool& fast_a, bool& fast_b);
  static void n2_finish_two(CoupledBoucWenMaterial& a, CoupledBoucWenMaterial& b, const N2Step& s_a,
                            const N2Step& s_b, double q_a, double q_b, double inv_a, double inv_b);
#endif

  // integrate()'s general path as a resumable state: path_start(), then path_step() until it
  // returns true; z and S (= dz/dx) are then the result.
  struct Path {
    Eigen::Vector2d e, z, c, w, phi0;
    Eigen::Matrix2d de_dx, S, M0, J0;
    Eigen::RowVector2d dL_dx, dh_sub_dx, dx_dx;
    double L, h_sub, remainder, x;  // x: distance in full sub-increments on this branch
    long full, k;
    int branch;
    bool unloading[2], keep_in_disc, s_is_zero;
  };
  void path_start(const Eigen::Vector2d& z0, const Eigen::Vector2d& dx, double length_sq,
                  Path& p) const;
  void branch_start(Path& p) const;
  // One sub-increment (to a component's zero, a full one or the remainder); true when done.
  bool path_step(Path& p) const;
  void advance(Path& p, double h, const Eigen::RowVector2d& dh_dx) const;

  BoucWenParameters p_;
  double z_saturation_, z_saturation_pow_n_;
  // For the n = 2 closed form, which tests squares: z_sat^2, (z_sat^n / z_sat)^2 (the path's
  // |z| bound below saturation) and (z_sat (1 + 1e-12))^2 (on the rim).
  double z_saturation_sq_, z_bound_sq_, rim_sq_;
  double inverse_yield_displacement_;
  double hysteretic_stiffness_;  // (1 - alpha) F_y / u_y, the factor of dz/dx in the tangent
  double hysteretic_energy_;     // (1 - alpha) F_y u_y / (2 A), the factor of |z|^2 in the energy
  Eigen::Vector2d d_ = Eigen::Vector2d::Zero(), z_ = Eigen::Vector2d::Zero();
  Eigen::Matrix2d dz_dx_;
  Eigen::Vector2d d_commit_ = Eigen::Vector2d::Zero(), z_commit_ = Eigen::Vector2d::Zero();
  Eigen::Matrix2d dz_dx_commit_;
};

}  // namespace isopound
