// Smooth Bouc-Wen isolator (THEORY eq. 2.1-2.2): F = alpha K_el d + (1-alpha) F_y z,
// dz/dd = (1/u_y) [A - (beta + gamma sgn(dd z)) |z|^n], integrated implicitly per increment.
#pragma once

#include "solver/materials/hysteresis.h"

namespace isopound {

struct BoucWenParameters {
  double elastic_stiffness = 0.0;   // K_el = F_y / u_y, N/m
  double alpha = 0.0;               // post-yield to elastic stiffness ratio
  double yield_force = 0.0;         // F_y, N
  double yield_displacement = 0.0;  // u_y, m
  double A = 1.0, beta = 0.5, gamma = 0.5, n = 2.0;
};

// z is a function of the deformation path only (rate independent), so over a monotonic
// increment dd it is an ODE in x = d/u_y. Each increment is split where z crosses 0 (the
// branch of sgn(dd z) changes there) and integrated with the trapezoidal rule in x (second
// order, implicit, solved by a safeguarded local Newton). Sub-increments keep
// h |dPhi/dz| <= 1/4, which makes the trapezoidal map monotone, so |z| never overshoots its
// saturation value (A/(beta+gamma))^(1/n) even for n = 100. Sub-increments have a fixed size
// plus a remainder, so z is continuous in dd; the consistent tangent is that of the remainder.
class BoucWenMaterial final : public UniaxialMaterial {
 public:
  explicit BoucWenMaterial(const BoucWenParameters& p);

  void set_trial(double d) override;
  double force() const override;
  double tangent() const override;
  double internal() const override { return z_; }
  double stored_energy() const override;
  double deformation() const override { return d_; }
  void commit() override;
  void revert() override;
  std::unique_ptr<UniaxialMaterial> clone() const override {
    return std::make_unique<BoucWenMaterial>(*this);
  }

  // z and dz/dx after a signed increment dx = dd/u_y from z0 (exposed for tests).
  struct ZUpdate {
    double z;
    double dz_dx;
  };
  ZUpdate integrate(double z0, double dx) const;

 private:
  double abs_pow_n(double z) const;  // |z|^n
  // Signed-length integration of dz/dx = A - c |z|^n from z_start over `length`.
  ZUpdate integrate_branch(double z_start, double length, double c) const;
  double distance_to_zero(double z0) const;  // x to unload from z0 to 0
  // One trapezoidal sub-increment of signed size h on the branch c, from z with phi(z) known.
  double trapezoid_step(double z, double phi_z, double h, double c, double bound_pow_n) const;
  // Sub-increment size on branch c from z_start; sets the bound |z|^n on the path.
  double subincrement(double z_start, double c, double& bound_pow_n) const;
  static double subincrement_size(double max_slope);  // for the largest |dPhi/dz|
  double dphi(double z, double c) const;              // dPhi/dz = -c n |z|^(n-1) sgn z

  BoucWenParameters p_;
  double z_saturation_;        // (A / (beta + gamma))^(1/n)
  double z_saturation_pow_n_;  // z_saturation_^n = A / (beta + gamma)
  int integer_n_;              // n if n is a small integer, else 0
  struct Branch {
    double c = 0.0;      // beta + gamma (loading) or beta - gamma (unloading)
    double h_sub = 0.0;  // sub-increment within saturation
  };
  Branch loading_, unloading_;
  double d_ = 0.0, z_ = 0.0, dz_dx_;
  double d_commit_ = 0.0, z_commit_ = 0.0, dz_dx_commit_;
};

}  // namespace isopound
