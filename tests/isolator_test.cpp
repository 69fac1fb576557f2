// Isolator laws vs hand values and closed forms: isolator_properties (thesis building); Bouc-Wen
// |z|<=1, tanh/1-exp/RK4 skeleton, order 2, tangent vs FD, loop energy; bilinear hand-drawn loop.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/materials/bilinear.h"
#include "solver/materials/bouc_wen.h"
#include "solver/materials/linear_material.h"
#include "solver/structures/config.h"
#include "solver/structures/isolator.h"

namespace isopound {
namespace {

// ---------------------------------------------------------------------------------------------
// Shared data and helpers
// ---------------------------------------------------------------------------------------------

// Thesis building: three floors of 340 t plus a 250 t base slab.
constexpr double kThesisMass = 3 * 340e3 + 250e3;  // 1.27e6 kg

IsolatorConfig thesis_config() {
  IsolatorConfig c;
  c.period = 2.0;
  c.strength_ratio = 0.05;
  c.yield_displacement = 0.01;
  return c;
}

// Thesis isolation system, values by hand (see IsolatorProperties.ThesisBuildingByHand):
// K_post = 1.27e6 pi^2, F_y = 0.05 * 1.27e6 * 9.81 + 0.01 K_post, K_el = F_y / 0.01.
constexpr double kThesisKpost = 12534397.589383485;  // N/m
constexpr double kThesisQ = 622935.0;                // N
constexpr double kThesisFy = 748278.9758938348;      // N
constexpr double kThesisKel = 74827897.58938348;     // N/m
constexpr double kThesisAlpha = 0.16750968546738715;
constexpr double kThesisUy = 0.01;  // m

BoucWenParameters thesis_bouc_wen(double n) {
  BoucWenParameters p;
  p.elastic_stiffness = kThesisKel;
  p.alpha = kThesisAlpha;
  p.yield_force = kThesisFy;
  p.yield_displacement = kThesisUy;
  p.A = 1.0;
  p.beta = 0.5;
  p.gamma = 0.5;
  p.n = n;
  return p;
}

// Moves `m` from its current (committed) deformation to `target` in equal increments of about
// `du`, committing each one, and calls visit(m) after every commit. Returns the work done,
// the trapezoidal sum of F dd along the path.
double drive(UniaxialMaterial& m, double target, double du,
             const std::function<void(const UniaxialMaterial&)>& visit = {}) {
  const double d0 = m.deformation();
  const int steps = std::max(1, static_cast<int>(std::lround(std::abs(target - d0) / du)));
  double work = 0.0;
  double f_prev = m.force();
  double d_prev = d0;
  for (int k = 1; k <= steps; ++k) {
    const double d = (k == steps) ? target : d0 + (target - d0) * k / steps;
    m.set_trial(d);
    m.commit();
    work += 0.5 * (f_prev + m.force()) * (d - d_prev);
    f_prev = m.force();
    d_prev = d;
    if (visit) visit(m);
  }
  return work;
}

// Reference skeleton curve z(x) of dz/dx = 1 - |z|^n, z(0) = 0 (A = 1, beta = gamma = 1/2,
// loading), by classical RK4 with inner steps h <= 1e-5. |dPhi/dz| <= n, so h n <= 1e-3 and
// the global RK4 error is O((h n)^4) ~ 1e-12 even for n = 100 (checked against tanh / 1-exp in
// BoucWenSkeleton.ReferenceIsAccurate). Returns z at x = k dx_out, k = 0..count.
std::vector<double> reference_skeleton(double n, double dx_out, int count) {
  const int sub = std::max(1, static_cast<int>(std::ceil(dx_out / 1e-5)));
  const double h = dx_out / sub;
  const auto phi = [n](double z) { return 1.0 - std::pow(std::abs(z), n); };
  std::vector<double> out{0.0};
  double z = 0.0;
  for (int k = 0; k < count; ++k) {
    for (int s = 0; s < sub; ++s) {
      const double k1 = phi(z);
      const double k2 = phi(z + 0.5 * h * k1);
      const double k3 = phi(z + 0.5 * h * k2);
      const double k4 = phi(z + h * k3);
      z += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    out.push_back(z);
  }
  return out;
}

// Loads a fresh Bouc-Wen material (thesis parameters, exponent n) from d = 0 with increments
// du = u_y / steps_per_uy and returns the largest |z - z_ref| over x = 0.1 k, k = 1..30.
double skeleton_error(double n, int steps_per_uy, const std::vector<double>& ref01) {
  BoucWenMaterial m(thesis_bouc_wen(n));
  double err = 0.0;
  for (int k = 1; k <= 30; ++k) {
    drive(m, 0.1 * k * kThesisUy, kThesisUy / steps_per_uy);
    err = std::max(err, std::abs(m.internal() - ref01[k]));
  }
  return err;
}

// ---------------------------------------------------------------------------------------------
// 1. isolator_properties
// ---------------------------------------------------------------------------------------------

// Hand values (m = 1.27e6 kg, Tb = 2 s, QW = 0.05, uy = 0.01 m, g = 9.81):
//   omega_b = 2 pi / 2 = pi,   K_post = 1.27e6 pi^2          = 1.2534397589e7 N/m
//   Q = 0.05 * 1.27e6 * 9.81                                  = 622935 N
//   F_y = Q + K_post u_y = 622935 + 125343.97589              = 748278.97589 N
//   K_el = F_y / u_y                                          = 7.4827897589e7 N/m
//   alpha = K_post / K_el = 1.2534397589e7 / 7.4827897589e7   = 0.16750968547
//   (1 - alpha) F_y = F_y - K_post u_y                        = Q
// Tolerance: relative 1e-10, the hand values carry 11+ significant digits; any formula slip
// (g, 2 pi, u_y factor) changes them by far more.
TEST(IsolatorProperties, ThesisBuildingByHand) {
  EXPECT_DOUBLE_EQ(kThesisMass, 1.27e6);
  const IsolatorProperties p = isolator_properties(thesis_config(), kThesisMass);
  EXPECT_NEAR(p.post_yield_stiffness, 1.2534397589e7, 1e-10 * 1.25e7);
  EXPECT_NEAR(p.yield_force, 748278.97589, 1e-10 * 7.5e5);
  EXPECT_NEAR(p.elastic_stiffness, 7.4827897589e7, 1e-10 * 7.5e7);
  EXPECT_NEAR(p.alpha, 0.16750968547, 1e-10);
  EXPECT_DOUBLE_EQ(p.yield_displacement, 0.01);
  EXPECT_NEAR(p.characteristic_strength, 622935.0, 1e-10 * 6.2e5);
  // Internal consistency, as THEORY section 2 defines the quantities.
  EXPECT_NEAR(p.alpha * p.elastic_stiffness, p.post_yield_stiffness, 1e-12 * 1.25e7);
  EXPECT_NEAR(p.elastic_stiffness * p.yield_displacement, p.yield_force, 1e-12 * 7.5e5);
}

// Option strength_is_yield_force: F_y = (Q/W) m g = 622935 N itself,
//   K_el = 622935 / 0.01 = 6.22935e7 N/m, alpha = 1.2534397589e7 / 6.22935e7 = 0.20121517637,
//   (1 - alpha) F_y = F_y - K_post u_y = 622935 - 125343.97589 = 497591.02411 N.
TEST(IsolatorProperties, StrengthIsYieldForceOption) {
  IsolatorConfig c = thesis_config();
  c.strength_is_yield_force = true;
  const IsolatorProperties p = isolator_properties(c, kThesisMass);
  EXPECT_NEAR(p.post_yield_stiffness, 1.2534397589e7, 1e-10 * 1.25e7);
  EXPECT_NEAR(p.yield_force, 622935.0, 1e-10 * 6.2e5);
  EXPECT_NEAR(p.elastic_stiffness, 6.22935e7, 1e-10 * 6.2e7);
  EXPECT_NEAR(p.alpha, 0.20121517637, 1e-10);
  EXPECT_NEAR(p.characteristic_strength, 497591.02411, 1e-10 * 5e5);
}

// alpha >= 1 means F_y <= K_post u_y: no hysteretic part. With the yield-force option that
// happens for QW <= omega_b^2 u_y / g = pi^2 * 0.01 / 9.81 = 0.01006; with the default
// convention only for Q = 0 (alpha = 1 exactly). The linear model does not use alpha.
TEST(IsolatorProperties, AlphaAtLeastOneRejected) {
  IsolatorConfig c = thesis_config();
  c.strength_is_yield_force = true;
  c.strength_ratio = 0.0102;  // alpha = 0.98634: still valid
  EXPECT_LT(isolator_properties(c, kThesisMass).alpha, 1.0);
  c.strength_ratio = 0.0100;  // alpha = 1.00608
  for (const auto model : {IsolatorConfig::Model::kBoucWen, IsolatorConfig::Model::kBilinear}) {
    c.model = model;
    EXPECT_THROW(isolator_properties(c, kThesisMass), std::invalid_argument);
    EXPECT_THROW(make_isolator_material(c, kThesisMass), std::invalid_argument);
  }
  IsolatorConfig d = thesis_config();
  d.strength_ratio = 0.0;  // default convention: F_y = K_post u_y, alpha = 1
  EXPECT_THROW(isolator_properties(d, kThesisMass), std::invalid_argument);
  d.model = IsolatorConfig::Model::kLinear;  // the linear law only needs K_post
  EXPECT_NO_THROW(isolator_properties(d, kThesisMass));
  // Nonsense inputs.
  EXPECT_THROW(isolator_properties(thesis_config(), 0.0), std::invalid_argument);
  IsolatorConfig e = thesis_config();
  e.period = 0.0;
  EXPECT_THROW(isolator_properties(e, kThesisMass), std::invalid_argument);
}

// make_isolator_material builds the chosen law from the properties: Bouc-Wen starts with
// tangent K_el and tends to F = K_post d + Q (z -> 1: at 30 u_y, 1 - tanh(30) ~ 1e-26);
// bilinear reaches F_y at u_y; linear is F = K_post d. Relative 1e-12: only rounding.
TEST(IsolatorProperties, MaterialsFromConfig) {
  IsolatorConfig c = thesis_config();
  auto bw = make_isolator_material(c, kThesisMass);
  ASSERT_NE(dynamic_cast<BoucWenMaterial*>(bw.get()), nullptr);
  EXPECT_NEAR(bw->tangent(), kThesisKel, 1e-12 * kThesisKel);
  drive(*bw, 0.3, kThesisUy / 10);
  EXPECT_NEAR(bw->force(), kThesisKpost * 0.3 + kThesisQ, 1e-12 * 4.4e6);

  c.model = IsolatorConfig::Model::kBilinear;
  auto bl = make_isolator_material(c, kThesisMass);
  ASSERT_NE(dynamic_cast<BilinearMaterial*>(bl.get()), nullptr);
  bl->set_trial(kThesisUy);
  EXPECT_NEAR(bl->force(), kThesisFy, 1e-12 * kThesisFy);

  c.model = IsolatorConfig::Model::kLinear;
  auto lin = make_isolator_material(c, kThesisMass);
  ASSERT_NE(dynamic_cast<LinearMaterial*>(lin.get()), nullptr);
  lin->set_trial(0.1);
  EXPECT_NEAR(lin->force(), kThesisKpost * 0.1, 1e-12 * kThesisKpost * 0.1);
}

// ---------------------------------------------------------------------------------------------
// 2. Bouc-Wen: |z| <= 1
// ---------------------------------------------------------------------------------------------

// Quasi-static cycles 0 -> +5 u_y -> -5 u_y -> ... (3 cycles) with du = u_y / 100. With
// A / (beta + gamma) = 1 the exact solution never leaves [-1, 1]; the implicit trapezoidal map
// is monotone, so the discrete one must not either (1e-12: rounding only). Also checks that
// the peaks come close to 1, else the bound would be trivially met.
TEST(BoucWenBounds, ZWithinOneQuasiStaticCycles) {
  for (const double n : {1.0, 2.0, 5.0, 25.0, 100.0}) {
    SCOPED_TRACE(n);
    BoucWenMaterial m(thesis_bouc_wen(n));
    double max_abs_z = 0.0;
    int violations = 0;
    double first_violation = 0.0;
    const auto visit = [&](const UniaxialMaterial& mm) {
      max_abs_z = std::max(max_abs_z, std::abs(mm.internal()));
      if (std::abs(mm.internal()) > 1.0 + 1e-12 && violations++ == 0)
        first_violation = mm.deformation();
    };
    drive(m, 5 * kThesisUy, kThesisUy / 100, visit);
    for (int cycle = 0; cycle < 3; ++cycle) {
      drive(m, -5 * kThesisUy, kThesisUy / 100, visit);
      drive(m, 5 * kThesisUy, kThesisUy / 100, visit);
    }
    EXPECT_EQ(violations, 0) << "|z| > 1 + 1e-12 first at d = " << first_violation;
    // Smallest peak: n = 1, z = 1 - exp(-(10 - z_peak)) ~ 1 - 1.2e-4.
    EXPECT_GT(max_abs_z, 0.999);
    std::printf("[ n = %5.1f ] 3 cycles of +-5 u_y, du = u_y/100: max |z| - 1 = %+.3e\n", n,
                max_abs_z - 1.0);
  }
}

// The same with random increments up to 10 u_y (many sub-increments, crossings of z = 0):
// the monotone trapezoidal map must keep |z| <= 1 whatever the increment size.
TEST(BoucWenBounds, ZWithinOneRandomLargeIncrements) {
  for (const double n : {1.0, 2.0, 5.0, 25.0, 100.0}) {
    SCOPED_TRACE(n);
    BoucWenMaterial m(thesis_bouc_wen(n));
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> step(-10.0, 10.0);
    double d = 0.0;
    double max_abs_z = 0.0;
    for (int i = 0; i < 1000; ++i) {
      d = std::clamp(d + step(rng) * kThesisUy, -20 * kThesisUy, 20 * kThesisUy);
      m.set_trial(d);
      ASSERT_LE(std::abs(m.internal()), 1.0 + 1e-12) << "step " << i;
      m.commit();
      max_abs_z = std::max(max_abs_z, std::abs(m.internal()));
    }
    EXPECT_GT(max_abs_z, 0.99);
  }
}

// ---------------------------------------------------------------------------------------------
// 3. Bouc-Wen: skeleton curve, order, unloading, crossing of z = 0
// ---------------------------------------------------------------------------------------------

// The RK4 reference itself against the closed forms (n = 2: tanh x, n = 1: 1 - exp(-x)).
TEST(BoucWenSkeleton, ReferenceIsAccurate) {
  const auto r2 = reference_skeleton(2.0, 0.1, 30);
  const auto r1 = reference_skeleton(1.0, 0.1, 30);
  for (int k = 0; k <= 30; ++k) {
    EXPECT_NEAR(r2[k], std::tanh(0.1 * k), 1e-13);
    EXPECT_NEAR(r1[k], 1.0 - std::exp(-0.1 * k), 1e-13);
  }
}

// Loading from z = 0 with du = u_y / 100 (h = 0.01 in x). Trapezoidal global error bound
// ~ h^2/12 * int |z'''| dx (the branch is contractive, dPhi/dz <= 0): for tanh |z'''| <= 2 and
// int |z'''| ~ 2, so ~ 2e-5; for larger n the curvature concentrates at the corner,
// |z'''| ~ n^2, int |z'''| ~ n -> ~ n h^2/12.
// Tolerances: 2e-5 (n <= 5), 3e-4 (n = 25), 1e-3 (n = 100); an O(h) scheme errs by ~1e-3 to 1e-2.
TEST(BoucWenSkeleton, MatchesClosedFormsAndReference) {
  struct Case {
    double n;
    double tol;
  };
  for (const Case c :
       {Case{1.0, 2e-5}, Case{2.0, 2e-5}, Case{5.0, 2e-5}, Case{25.0, 3e-4}, Case{100.0, 1e-3}}) {
    SCOPED_TRACE(c.n);
    std::vector<double> ref;
    if (c.n == 2.0) {
      for (int k = 0; k <= 30; ++k) ref.push_back(std::tanh(0.1 * k));
    } else if (c.n == 1.0) {
      for (int k = 0; k <= 30; ++k) ref.push_back(1.0 - std::exp(-0.1 * k));
    } else {
      ref = reference_skeleton(c.n, 0.1, 30);
    }
    const double err = skeleton_error(c.n, 100, ref);
    EXPECT_LT(err, c.tol);
    EXPECT_GT(err, 0.0);  // an exact match would mean the reference is not independent
    std::printf("[ n = %5.1f ] skeleton max |z - z_ref|, du = u_y/100: %.3e\n", c.n, err);
  }
}

// Second order: halving du divides the error by ~4. The ratio tends to 4 as h -> 0; at these
// h the next term (h^4) shifts it by well under 10 %, so accept [3.6, 4.4] (first order would
// give 2, a third-order scheme 8). The increments must be single trapezoidal steps: the material
// subdivides an increment once h max|dPhi/dz| = h n exceeds its bound (1/4 in bouc_wen.h), so
// n = 1, 2 use du = u_y/10, /20 (h n <= 0.2) and n = 5 uses u_y/40, /80 (h n <= 0.125).
TEST(BoucWenSkeleton, SecondOrderInIncrement) {
  struct Case {
    double n;
    int steps_per_uy;
  };
  for (const Case c : {Case{1.0, 10}, Case{2.0, 10}, Case{5.0, 40}}) {
    SCOPED_TRACE(c.n);
    const auto ref = reference_skeleton(c.n, 0.1, 30);
    const double e1 = skeleton_error(c.n, c.steps_per_uy, ref);
    const double e2 = skeleton_error(c.n, 2 * c.steps_per_uy, ref);
    std::printf("[ n = %3.1f ] skeleton max error du = u_y/%d: %.3e, u_y/%d: %.3e, ratio %.3f\n",
                c.n, c.steps_per_uy, e1, 2 * c.steps_per_uy, e2, e1 / e2);
    EXPECT_GT(e1 / e2, 3.6);
    EXPECT_LT(e1 / e2, 4.4);
  }
}

// With beta = gamma, unloading (dd z < 0) has dz/dx = A exactly, so z falls linearly by
// du / u_y per increment and the tangent is alpha K_el + (1 - alpha) F_y A / u_y = K_el. The
// trapezoidal rule is exact for a constant slope: 1e-13 (rounding of z ~ 1 over a few steps).
TEST(BoucWenUnloading, LinearWithSlopeAForBetaEqualGamma) {
  for (const double n : {1.0, 2.0, 5.0, 100.0}) {
    SCOPED_TRACE(n);
    BoucWenMaterial m(thesis_bouc_wen(n));
    drive(m, 3 * kThesisUy, kThesisUy / 50);
    const double z_peak = m.internal();
    ASSERT_GT(z_peak, 0.9);
    double d = m.deformation();
    double z_prev = z_peak;
    int steps = 0;
    while (z_prev > 0.1 + 1e-9 && steps < 10) {  // unload by 0.1 u_y while z stays >= 0
      d -= 0.1 * kThesisUy;
      m.set_trial(d);
      ASSERT_NEAR(m.internal(), z_prev - 0.1, 1e-13) << "step " << steps;
      ASSERT_NEAR(m.tangent(), kThesisKel, 1e-12 * kThesisKel) << "step " << steps;
      m.commit();
      z_prev = m.internal();
      ++steps;
    }
    EXPECT_GE(steps, 9);
    // One increment straight to the point where z = 0: exact too.
    m.set_trial(d - z_prev * kThesisUy);
    EXPECT_NEAR(m.internal(), 0.0, 1e-13);
  }
}

// Crossing z = 0 inside one increment. From z0 > 0, an increment dx = -1.5 unloads linearly to
// z = 0 after x* = z0 / A (beta = gamma) and then loads in the negative direction:
// z = -tanh(1.5 - z0) exactly (n = 2). Checks: the split is exact (integrate(z0, dx) ==
// integrate(0, dx + z0), 1e-14); the fine path (du = u_y/1000, error ~ h^2/12 * 2 ~ 2e-7)
// matches the closed form within 1e-6; the one big increment (sub-steps with h |dPhi/dz| <= 1/4
// per bouc_wen.h, |dPhi/dz| <= 2, so h <= 1/8: error <= h^2/12 * int |z'''| = 1.3e-3 * 1.54 ~ 2e-3,
// int |z'''| being the total variation of tanh'') within 5e-3. Without the split (whole increment
// on the unloading branch, or the loading branch from z0) z would be off by > 0.3.
TEST(BoucWenCrossing, OneIncrementVersusSplitAndFinePath) {
  BoucWenMaterial m(thesis_bouc_wen(2.0));
  drive(m, 0.4 * kThesisUy, kThesisUy / 1000);
  const double z0 = m.internal();
  ASSERT_NEAR(z0, std::tanh(0.4), 1e-6);
  const double d0 = m.deformation();
  const double exact = -std::tanh(1.5 - z0);

  const auto whole = m.integrate(z0, -1.5);
  const auto split = m.integrate(0.0, z0 - 1.5);
  EXPECT_NEAR(whole.z, split.z, 1e-14);
  EXPECT_NEAR(whole.dz_dx, split.dz_dx, 1e-14);

  auto big = m.clone();
  big->set_trial(d0 - 1.5 * kThesisUy);
  EXPECT_NEAR(big->internal(), whole.z, 1e-15);
  EXPECT_NEAR(big->internal(), exact, 5e-3);

  auto fine = m.clone();
  drive(*fine, d0 - 1.5 * kThesisUy, kThesisUy / 1000);
  EXPECT_NEAR(fine->internal(), exact, 1e-6);
  std::printf("crossing: z exact %.9f, one increment %.9f (err %.2e), fine path %.9f (err %.2e)\n",
              exact, big->internal(), std::abs(big->internal() - exact), fine->internal(),
              std::abs(fine->internal() - exact));
}

// Exact distance x* from z0 to z = 0 on the unloading branch for n = 2, A = 1, beta + gamma = 1:
// dz/dx = 1 - (beta - gamma) z^2 gives x* = sqrt(2) artanh(z0 / sqrt(2)) for beta - gamma = 1/2,
// sqrt(2) atan(z0 / sqrt(2)) for beta - gamma = -1/2.
double exact_distance_to_zero(double beta, double z0) {
  const double r = std::sqrt(2.0);
  return beta > 0.5 ? r * std::atanh(z0 / r) : r * std::atan(z0 / r);
}

// Where the material's z reaches 0 when unloading from z0 > 0 (bisection on the sign of z after
// one increment -x; z is monotone in x on the way down).
double material_distance_to_zero(const BoucWenMaterial& m, double z0) {
  double lo = 0.0, hi = 3.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (m.integrate(z0, -mid).z > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// beta != gamma: the unloading branch is no longer linear. The increment length x_c at which z
// reaches 0 must be the exact x* up to the integration error of the unloading branch:
// trapezoidal sub-steps with h |dPhi/dz| <= 1/4 (bouc_wen.h), |dPhi/dz| = 2 |beta - gamma| |z|
// <= 1, so h <= 1/4 and the error is <= h^2/12 * int |z'''| dx ~ 0.0052 * 2.5 ~ 1.3e-2
// (z''' = z'^2 + z^2 z' <= 3.75 over x* <= 1.2); allow 2e-2 (measured <= 6e-3). A wrong branch
// constant (beta + gamma for beta - gamma, or the linear x* = z0) is off by 0.16 to 0.4 at
// z0 = 0.9 (an exact quadrature of x* gives errors ~1e-9). Just past x_c, z must leave 0
// along the loading branch: z(x_c + 1e-6) = -1e-6 (slope A = 1 at z = 0, curvature ~1e-12);
// 1e-9 covers the bisection and Newton tolerances.
TEST(BoucWenCrossing, DistanceToZeroUnequalBetaGamma) {
  for (const double beta : {0.75, 0.25}) {
    BoucWenParameters p = thesis_bouc_wen(2.0);
    p.beta = beta;
    p.gamma = 1.0 - beta;
    const BoucWenMaterial m(p);
    for (const double z0 : {0.3, 0.6, 0.9, 0.99}) {
      SCOPED_TRACE(testing::Message() << "beta " << beta << " z0 " << z0);
      const double exact = exact_distance_to_zero(beta, z0);
      const double x_c = material_distance_to_zero(m, z0);
      std::printf("[ beta = %4.2f, z0 = %4.2f ] x* exact %.9f, material %.9f (err %+.1e)\n", beta,
                  z0, exact, x_c, x_c - exact);
      EXPECT_NEAR(x_c, exact, 2e-2);
      EXPECT_NEAR(m.integrate(z0, -(x_c + 1e-6)).z, -1e-6, 1e-9);
      EXPECT_NEAR(m.integrate(-z0, x_c + 1e-6).z, 1e-6, 1e-9);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Continuity of z (hence of F) in the trial deformation
// ---------------------------------------------------------------------------------------------

// Largest "excess jump" of z over one increment dx from z0, scanned on a grid of spacing
// delta: max over grid points of |z(dx + delta) - z(dx)| - delta * max(|w(dx)|, |w(dx + delta)|),
// w = dz/dx. For a continuous, smooth z this is <= delta^2 / 2 * max |z''|.
double max_excess_jump(const BoucWenMaterial& m, double z0, double dx_end, double delta,
                       double* where) {
  double worst = 0.0;
  const int count = static_cast<int>(std::lround(std::abs(dx_end) / delta));
  const double sign = dx_end > 0 ? 1.0 : -1.0;
  auto prev = m.integrate(z0, sign * delta);
  for (int k = 2; k <= count; ++k) {
    const auto cur = m.integrate(z0, sign * delta * k);
    const double excess =
        std::abs(cur.z - prev.z) - delta * std::max(std::abs(cur.dz_dx), std::abs(prev.dz_dx));
    if (excess > worst) {
      worst = excess;
      *where = sign * delta * k;
    }
    prev = cur;
  }
  return worst;
}

// F(d_trial) is the function the stepper's Newton iteration solves on; it must be continuous
// (a jump makes Newton chatter or stall when the solution sits at it). Scan the increment dx
// over (0, 3] from z0 = 0 (loading) and over [-3, 0) from z0 = 0.8 (unloading, crossing z = 0
// at -0.8) with delta = 1e-4. A smooth z leaves an excess <= delta^2/2 max|z''| <= 2.5e-8
// (|z''| = |Phi' Phi| <= n <= 5); allow 1e-7, i.e. a force jump of 1e-7 (1 - alpha) F_y.
TEST(BoucWenContinuity, ZContinuousInIncrement) {
  for (const double n : {1.0, 2.0, 5.0}) {
    const BoucWenMaterial m(thesis_bouc_wen(n));
    for (const double z0 : {0.0, 0.8}) {
      SCOPED_TRACE(testing::Message() << "n " << n << " z0 " << z0);
      double where = 0.0;
      const double jump = max_excess_jump(m, z0, z0 == 0.0 ? 3.0 : -3.0, 1e-4, &where);
      std::printf("[ n = %3.1f, z0 = %3.1f ] largest jump of z(dx): %.3e at dx = %.5f\n", n, z0,
                  jump, where);
      EXPECT_LT(jump, 1e-7) << "z(dx) jumps by " << jump << " near dx = " << where
                            << " (the sub-increment count changes there)";
    }
  }
}

// The same through the crossing point for beta != gamma (unloading branch not linear): the
// unloading branch must arrive at z = 0 exactly where the split restarts the loading branch.
// Scan dx from 0 to -(x* + 0.2) with delta = 1e-5: a smooth z leaves an excess
// <= delta^2/2 max|z''| ~ 1e-10 (|z''| = |Phi' Phi| <= 2); allow 1e-8.
TEST(BoucWenContinuity, ZContinuousAtCrossingUnequalBetaGamma) {
  for (const double beta : {0.75, 0.25}) {
    BoucWenParameters p = thesis_bouc_wen(2.0);
    p.beta = beta;
    p.gamma = 1.0 - beta;
    const BoucWenMaterial m(p);
    for (const double z0 : {0.3, 0.6, 0.9}) {
      SCOPED_TRACE(testing::Message() << "beta " << beta << " z0 " << z0);
      double where = 0.0;
      const double end = -(exact_distance_to_zero(beta, z0) + 0.2);
      const double jump = max_excess_jump(m, z0, end, 1e-5, &where);
      std::printf("[ beta = %4.2f, z0 = %3.1f ] largest jump of z(dx): %.3e at dx = %.5f\n", beta,
                  z0, jump, where);
      EXPECT_LT(jump, 1e-8) << "z(dx) jumps by " << jump << " near dx = " << where;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 4. Bouc-Wen n = 100 / 50 versus the sharp bilinear
// ---------------------------------------------------------------------------------------------

// Largest |F_bw - F_bl| on each leg of 0 -> +5 u_y -> -5 u_y -> +5 u_y (du = u_y / 1000).
std::vector<double> leg_gaps(double n) {
  BoucWenMaterial bw(thesis_bouc_wen(n));
  BilinearMaterial bl(kThesisKel, kThesisAlpha, kThesisFy);
  std::vector<double> gaps;
  for (const double target : {5.0, -5.0, 5.0}) {
    double gap = 0.0;
    const double d0 = bw.deformation();
    const double d1 = target * kThesisUy;
    const int steps = static_cast<int>(std::lround(std::abs(d1 - d0) / kThesisUy * 1000));
    for (int k = 1; k <= steps; ++k) {
      const double d = d0 + (d1 - d0) * k / steps;
      bw.set_trial(d);
      bl.set_trial(d);
      bw.commit();
      bl.commit();
      gap = std::max(gap, std::abs(bw.force() - bl.force()));
    }
    gaps.push_back(gap);
  }
  return gaps;
}

// Same K_el, alpha, F_y. beta = gamma: both unload with slope K_el, so the laws differ only on
// the loading branch, where z_bw lags the bilinear min(x, 1); the gap peaks at the corner x = 1:
// 1 - z(1) with x(z) = int_0^z dw / (1 - w^n); putting z = 1 - s/n, z^n ~ e^-s gives
// s = -ln(1 - e^-s), s = ln 2, so the force gap is (1 - alpha) F_y ln2 / n: 0.693 % of Q at
// n = 100 (0.577 % of F_y with alpha = 0.1675), 1.386 % of Q at n = 50. Checks: |gap| < 1 % F_y
// everywhere at n = 100; gap / Q in [0.5, 0.9] % (n = 100) and [1.2, 1.6] % (n = 50) on every
// leg; and within 1 % of the RK4 value 1 - z_ref(1) (du = u_y/1000: discretisation ~1e-6 of Q).
TEST(BoucWenVsBilinear, SharpLimitCornerGap) {
  const double q = (1.0 - kThesisAlpha) * kThesisFy;
  for (const double n : {100.0, 50.0}) {
    SCOPED_TRACE(n);
    const double ref_gap = 1.0 - reference_skeleton(n, 1.0, 1)[1];
    const auto gaps = leg_gaps(n);
    for (const double g : gaps) {
      std::printf(
          "[ n = %5.1f ] max |F_bw - F_bl| on a leg: %.4f %% of F_y, %.4f %% of Q "
          "(RK4 corner gap %.4f %% of Q, ln2/n = %.4f %%)\n",
          n, 100 * g / kThesisFy, 100 * g / q, 100 * ref_gap, 100 * std::log(2.0) / n);
      if (n == 100.0) {
        EXPECT_LT(g, 0.01 * kThesisFy);
        EXPECT_GT(g / q, 0.005);
        EXPECT_LT(g / q, 0.009);
      } else {
        EXPECT_GT(g / q, 0.012);
        EXPECT_LT(g / q, 0.016);
      }
      EXPECT_NEAR(g / q, ref_gap, 0.01 * ref_gap);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 5. Consistent tangent
// ---------------------------------------------------------------------------------------------

// For random committed states (reached by random committed increments) and random trial
// increments of three kinds - one sub-step (|dx| < 1/n), several sub-steps (|dx| > 1/n; per
// bouc_wen.h a sub-step keeps h |dPhi/dz| <= 1 and |dPhi/dz| <= n), and crossing z = 0 -
// tangent() must equal a finite difference of force(): Richardson-extrapolated central
// differences R(e) = (4 D(e/2) - D(e)) / 3, D(h) = (F(d + h) - F(d - h)) / 2h, e = 1e-5 u_y.
// Truncation O(e^4 |z^(5)|) ~ 1e-20 n^4 ~ 1e-12 K_el (n = 100). Rounding: z carries ~1e-15 per
// sub-step (local Newton tolerance), ~1e-13 after a few hundred sub-steps (n = 100), giving
// ~1e-13 / 1e-5 = 1e-8 K_el. The tangent is >= alpha K_el = 0.17 K_el, so relative 1e-6 is safe
// (a smaller e is swamped by that rounding). Where the FD window straddles a kink or jump of F
// (crossing point, change of the sub-step count) the difference is no derivative: detected by
// comparing with R(4e) (smooth: they agree to ~1e-8) and skipped; at most 2 % may be skipped.
TEST(BoucWenTangent, MatchesCentralDifference) {
  for (const double n : {1.0, 2.0, 5.0, 25.0, 100.0}) {
    SCOPED_TRACE(n);
    BoucWenMaterial m(thesis_bouc_wen(n));
    std::mt19937 rng(4321 + static_cast<unsigned>(n));
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    const double uy = kThesisUy;
    int count[3] = {0, 0, 0};
    double max_err[3] = {0.0, 0.0, 0.0};
    int skipped = 0;
    int failures = 0;
    std::string first_failure;
    const int samples = 450;  // 150 per kind
    for (int i = 0; i < samples; ++i) {
      // New committed state.
      m.set_trial(std::clamp(m.deformation() + (6.0 * uni(rng) - 3.0) * uy, -6 * uy, 6 * uy));
      m.commit();
      const double dc = m.deformation();
      const double zc = m.internal();
      // Trial increment.
      const int kind = i % 3;
      const double sign = uni(rng) < 0.5 ? -1.0 : 1.0;
      double dx;
      if (kind == 0) {
        dx = sign * (0.01 + 0.98 * uni(rng)) / n;
      } else if (kind == 1) {
        dx = sign * (1.5 / n + (5.5 - 1.5 / n) * uni(rng));  // 1.5 .. 5.5 n sub-steps
      } else {
        const double towards_zero = zc >= 0 ? -1.0 : 1.0;
        dx = towards_zero * (std::abs(zc) + 0.001 + 2.0 * uni(rng));
      }
      const double d = dc + dx * uy;
      m.set_trial(d);
      const double k = m.tangent();
      if (kind == 2) {
        ASSERT_TRUE(zc == 0.0 || m.internal() * zc < 0.0) << "sample " << i << ": no crossing";
      }
      const auto central = [&](double h) {
        m.set_trial(d + h);
        const double fp = m.force();
        m.set_trial(d - h);
        const double fm = m.force();
        return (fp - fm) / (2.0 * h);
      };
      const auto richardson = [&](double h) { return (4.0 * central(0.5 * h) - central(h)) / 3.0; };
      const double e = 1e-5 * uy;
      const double k_fd = richardson(e);
      const double k_wide = richardson(4.0 * e);
      if (std::abs(k_fd - k_wide) > 1e-7 * std::abs(k)) {
        ++skipped;
        continue;
      }
      ++count[kind];
      const double err = std::abs(k - k_fd) / std::abs(k);
      max_err[kind] = std::max(max_err[kind], err);
      if (!(err < 1e-6) && failures++ == 0) {
        first_failure = testing::PrintToString(std::vector<double>{
            static_cast<double>(i), static_cast<double>(kind), zc, dx, k, k_fd});
      }
    }
    EXPECT_EQ(failures, 0) << "relative tangent error > 1e-6; first {sample, kind, z_c, dx, K, "
                              "K_fd} = "
                           << first_failure;
    std::printf(
        "[ n = %5.1f ] tangent vs Richardson FD, max rel err: one sub-step %.1e (%d), "
        "several %.1e (%d), crossing %.1e (%d); %d skipped\n",
        n, max_err[0], count[0], max_err[1], count[1], max_err[2], count[2], skipped);
    EXPECT_LE(skipped, samples / 50);
    for (const int c : count) EXPECT_GE(c, samples / 3 - samples / 50);
  }
}

// Bilinear tangent: K_el inside the elastic range, alpha K_el on the yield surface (forces exactly
// piecewise linear: relative 1e-6 covers rounding of F / e). FD windows on a kink are skipped.
TEST(BilinearTangent, MatchesCentralDifference) {
  BilinearMaterial m(2e7, 0.1, 2e5);
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> uni(-0.03, 0.03);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    m.set_trial(m.deformation() + uni(rng));
    m.commit();
    const double d = m.deformation() + uni(rng);
    m.set_trial(d);
    const double k = m.tangent();
    m.set_trial(d + 1e-7);
    const double fp = m.force();
    m.set_trial(d - 1e-7);
    const double fm = m.force();
    const double k_fd = (fp - fm) / 2e-7;
    if (std::abs(k_fd - 2e7) > 1e-3 * 2e7 && std::abs(k_fd - 2e6) > 1e-3 * 2e6) continue;  // kink
    ++checked;
    EXPECT_NEAR(k, k_fd, 1e-6 * k) << "sample " << i;
  }
  EXPECT_GE(checked, 290);
}

// ---------------------------------------------------------------------------------------------
// 6. Trial / commit protocol
// ---------------------------------------------------------------------------------------------

struct Snapshot {
  double force, tangent, internal, stored, deformation;
};
Snapshot snap(const UniaxialMaterial& m) {
  return {m.force(), m.tangent(), m.internal(), m.stored_energy(), m.deformation()};
}
void expect_same(const Snapshot& a, const Snapshot& b, const char* what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.force, b.force);
  EXPECT_EQ(a.tangent, b.tangent);
  EXPECT_EQ(a.internal, b.internal);
  EXPECT_EQ(a.stored, b.stored);
  EXPECT_EQ(a.deformation, b.deformation);
}

// set_trial depends only on the committed state and the trial deformation: repeating a trial
// after other trials gives bit-identical results (deterministic code: exact equality). revert()
// returns to exactly the state right after commit() (force, tangent, z, stored energy,
// deformation). A clone copies trial and committed state and is independent afterwards.
void check_protocol(UniaxialMaterial& m, double uy) {
  drive(m, 2.5 * uy, uy / 20);  // yielded committed state
  const Snapshot committed = snap(m);

  m.set_trial(1.2 * uy);  // unloading trial
  const Snapshot first = snap(m);
  m.set_trial(4.0 * uy);   // loading trial
  m.set_trial(-3.0 * uy);  // reversal trial
  m.set_trial(1.2 * uy);
  expect_same(first, snap(m), "repeated trial");

  m.revert();
  expect_same(committed, snap(m), "revert");
  m.set_trial(committed.deformation);  // zero increment: same force and state
  EXPECT_EQ(m.force(), committed.force);
  EXPECT_EQ(m.internal(), committed.internal);

  // Clone: same state, then independent.
  m.set_trial(1.2 * uy);
  auto c = m.clone();
  expect_same(snap(m), snap(*c), "clone copies the trial state");
  c->set_trial(-2.0 * uy);
  const double clone_force = c->force();
  c->commit();
  c->set_trial(-4.0 * uy);
  expect_same(first, snap(m), "original's trial untouched by the clone");
  m.set_trial(2.5 * uy);  // back to the committed deformation, as a trial
  EXPECT_EQ(m.force(), committed.force);
  m.set_trial(-2.0 * uy);  // the same increment the clone committed
  EXPECT_EQ(m.force(), clone_force);
  m.revert();
  EXPECT_EQ(m.force(), committed.force) << "original's commit untouched by the clone";
  c->revert();
  EXPECT_EQ(c->force(), clone_force) << "clone's own commit";
}

TEST(BoucWenProtocol, TrialCommitRevertClone) {
  for (const double n : {1.0, 2.0, 100.0}) {
    SCOPED_TRACE(n);
    BoucWenMaterial m(thesis_bouc_wen(n));
    check_protocol(m, kThesisUy);
  }
}

TEST(BilinearProtocol, TrialCommitRevertClone) {
  BilinearMaterial m(kThesisKel, kThesisAlpha, kThesisFy);
  check_protocol(m, kThesisUy);
}

// ---------------------------------------------------------------------------------------------
// 7. Bilinear loop by hand
// ---------------------------------------------------------------------------------------------

// K_el = 2e7 N/m, alpha = 0.1, F_y = 2e5 N: u_y = 0.01 m, K_post = 2e6 N/m, hysteretic part
// F_h = F - alpha K_el d bounded by (1 - alpha) F_y = 1.8e5 N. Path 0 -> 0.05 -> -0.05 -> 0.05:
//   d = 0.005: 1e5 (elastic);  d = 0.01: F_y = 2e5 (yield);  d = 0.05: 2e5 + 2e6*0.04 = 2.8e5
//   unloading with K_el: d = 0.04: 2.8e5 - 2e7*0.01 = 8e4;
//   reverse yield after a force change of 2 F_y (elastic range 2 u_y): d = 0.03: -1.2e5
//   (= alpha K_el d - (1-alpha) F_y = 6e4 - 1.8e5), then slope K_post: d = 0: -1.8e5,
//   d = -0.05: -2.8e5; reloading symmetric: d = -0.04: -8e4, d = -0.03: +1.2e5, d = 0.05: 2.8e5.
// Exact piecewise-linear law: relative 1e-9 (rounding of the return map over 1e-4 m steps).
// The tangent is checked away from the kinks (k = 0 marks a kink: which side is rounding).
TEST(BilinearLoop, ForcesAtKeyPointsByHand) {
  BilinearMaterial m(2e7, 0.1, 2e5);
  struct Point {
    double d, f, k;
  };
  const std::vector<Point> path = {{0.005, 1e5, 2e7},   {0.01, 2e5, 0.0},     {0.03, 2.4e5, 2e6},
                                   {0.05, 2.8e5, 2e6},  {0.04, 8e4, 2e7},     {0.03, -1.2e5, 0.0},
                                   {0.0, -1.8e5, 2e6},  {-0.05, -2.8e5, 2e6}, {-0.04, -8e4, 2e7},
                                   {-0.03, 1.2e5, 0.0}, {0.05, 2.8e5, 2e6}};
  for (const Point& p : path) {
    SCOPED_TRACE(p.d);
    drive(m, p.d, 1e-4);
    EXPECT_NEAR(m.force(), p.f, 1e-9 * 2.8e5);
    // Tangent of the last increment: K_el strictly inside the elastic range, K_post on yield.
    if (p.k != 0.0) {
      EXPECT_NEAR(m.tangent(), p.k, 1e-9 * 2e7);
    }
    EXPECT_LE(std::abs(m.force() - 0.1 * 2e7 * m.deformation()), 1.8e5 * (1 + 1e-12));
    EXPECT_NEAR(m.internal(), (m.force() - 0.1 * 2e7 * m.deformation()) / 1.8e5, 1e-12);
  }
}

// Energy. The hysteretic spring is elastic-perfectly-plastic (stiffness (1-alpha) K_el, yield
// force (1-alpha) F_y, yield displacement u_y); its loop between +-u_max is a parallelogram of
// height 2 (1-alpha) F_y and horizontal width 2 (u_max - u_y), so per stabilised cycle
//   E_D = 4 (1 - alpha) F_y (u_max - u_y) = 4 * 1.8e5 * 0.04 = 28800 J
// (kinematic hardening: stabilised from the first cycle); alpha K_el d is conservative. First
// loading 0 -> 0.05: work = 1000 (0.5 F_y u_y) + 9600 (0.04 * mean(2e5, 2.8e5)) = 10600 J, stored
// 0.5 * 2e6 * 0.05^2 + 0.5 * 1.8e5^2 / 1.8e7 = 2500 + 900 = 3400 J, dissipated 7200 J =
// (1-alpha) F_y (u_max - u_y). Steps of 1e-5 m hit every kink, so the trapezoid sums are exact
// to rounding: relative 1e-9.
TEST(BilinearEnergy, DissipationEqualsHandLoopArea) {
  BilinearMaterial m(2e7, 0.1, 2e5);
  const double work_first = drive(m, 0.05, 1e-5);
  EXPECT_NEAR(work_first, 10600.0, 1e-9 * 10600.0);
  EXPECT_NEAR(m.stored_energy(), 3400.0, 1e-9 * 3400.0);
  EXPECT_NEAR(work_first - m.stored_energy(), 7200.0, 1e-9 * 7200.0);

  // Dissipation (work - stored) never decreases along the path.
  double w = work_first;
  double last = work_first - m.stored_energy();
  int decreases = 0;
  double d_prev = m.deformation();
  double f_prev = m.force();
  const auto track = [&](const UniaxialMaterial& mm) {
    w += 0.5 * (f_prev + mm.force()) * (mm.deformation() - d_prev);
    d_prev = mm.deformation();
    f_prev = mm.force();
    const double diss = w - mm.stored_energy();
    if (diss < last - 1e-9 * 28800.0) ++decreases;
    last = diss;
  };
  for (int cycle = 0; cycle < 2; ++cycle) {
    const double e0 = m.stored_energy();
    const double w_down = drive(m, -0.05, 1e-5, track);
    EXPECT_NEAR(w_down - (m.stored_energy() - e0), 14400.0, 1e-9 * 28800.0);  // half loop
    const double w_up = drive(m, 0.05, 1e-5, track);
    EXPECT_NEAR(w_down + w_up, 28800.0, 1e-9 * 28800.0);
    EXPECT_NEAR(m.stored_energy(), e0, 1e-9 * e0);
  }
  EXPECT_EQ(decreases, 0) << "dissipated energy decreased along the path";
  EXPECT_NEAR(last, 7200.0 + 2 * 28800.0, 1e-9 * 64800.0);
  // Elastic excursion 0.05 -> 0.04 -> 0.05: nothing dissipated, stored energy recovered.
  const double e0 = m.stored_energy();
  const double w_el = drive(m, 0.04, 1e-5) + drive(m, 0.05, 1e-5);
  EXPECT_NEAR(w_el, 0.0, 1e-9 * 3400.0);
  EXPECT_NEAR(m.stored_energy(), e0, 1e-9 * e0);
}

// ---------------------------------------------------------------------------------------------
// 8. Bouc-Wen energy
// ---------------------------------------------------------------------------------------------

// Loop area in the (x, z) plane of the stabilised cycle between +-x_m (A = 1, beta = gamma):
// the rising branch unloads linearly from -z_m to 0 (area -z_m^2/2) and then follows the
// skeleton over L = 2 x_m - z_m with z_m = z_skel(L); loop area = 2 (int_0^L z_skel - z_m^2/2).
//   n = 2: z_skel = tanh,        int = ln cosh L
//   n = 1: z_skel = 1 - e^{-x},  int = L - z_m
double loop_area_xz(double n, double x_m) {
  double z = 0.5;
  for (int i = 0; i < 200; ++i) {  // fixed point z = z_skel(2 x_m - z), a contraction here
    const double L = 2 * x_m - z;
    z = n == 2.0 ? std::tanh(L) : 1.0 - std::exp(-L);
  }
  const double L = 2 * x_m - z;
  const double integral = n == 2.0 ? std::log(std::cosh(L)) : L - z;
  return 2.0 * (integral - 0.5 * z * z);
}

// Work done minus change of stored energy is the dissipated energy. (a) First loading to x_m:
// n = 2: (1-alpha) F_y u_y (ln cosh x_m - tanh^2 x_m / 2); n = 1: (x_m - z_1) - z_1^2/2 with
// z_1 = 1 - e^{-x_m} (the stored z^2/2 is exactly what linear unloading gives back).
// (b) Stabilised cycle (after 3 cycles; z_m converges like e^{-2 L}): dissipated =
// (1-alpha) F_y u_y * loop_area_xz, and > 0. Work by trapezoid with du = u_y/100: z error
// ~1e-5 (skeleton test) and quadrature error O(du^2) give ~1e-5 relative; the brief asks 1 %,
// we check 0.1 %. Dissipation must never decrease (beyond 1e-6 of the loop: trapezoid error).
TEST(BoucWenEnergy, DissipationEqualsLoopArea) {
  for (const double n : {1.0, 2.0}) {
    SCOPED_TRACE(n);
    BoucWenMaterial m(thesis_bouc_wen(n));
    const double uy = kThesisUy;
    const double scale = (1.0 - kThesisAlpha) * kThesisFy * uy;  // J per unit (x, z) area
    const double x_m = 2.0;
    const double work_first = drive(m, x_m * uy, uy / 100);
    const double z1 = n == 2.0 ? std::tanh(x_m) : 1.0 - std::exp(-x_m);
    const double first_expected =
        scale * ((n == 2.0 ? std::log(std::cosh(x_m)) : x_m - z1) - 0.5 * z1 * z1);
    const double first = work_first - m.stored_energy();
    EXPECT_NEAR(first, first_expected, 1e-3 * first_expected);

    const double area = scale * loop_area_xz(n, x_m);
    double w = work_first;
    double last = first;
    int decreases = 0;
    double d_prev = m.deformation();
    double f_prev = m.force();
    const auto track = [&](const UniaxialMaterial& mm) {
      w += 0.5 * (f_prev + mm.force()) * (mm.deformation() - d_prev);
      d_prev = mm.deformation();
      f_prev = mm.force();
      const double diss = w - mm.stored_energy();
      if (diss < last - 1e-6 * area) ++decreases;
      last = diss;
    };
    for (int cycle = 0; cycle < 3; ++cycle) {
      drive(m, -x_m * uy, uy / 100, track);
      drive(m, x_m * uy, uy / 100, track);
    }
    EXPECT_EQ(decreases, 0) << "dissipated energy decreased along the path";
    const double e0 = m.stored_energy();
    const double w_down = drive(m, -x_m * uy, uy / 100);
    const double half = w_down - (m.stored_energy() - e0);
    const double w_cycle = w_down + drive(m, x_m * uy, uy / 100);
    const double dissipated = w_cycle - (m.stored_energy() - e0);
    EXPECT_GT(dissipated, 0.0);
    EXPECT_NEAR(dissipated, area, 1e-3 * area);
    EXPECT_NEAR(half, 0.5 * area, 1e-3 * area);  // symmetric loop: half per half cycle
    std::printf(
        "[ n = %3.1f ] cycle +-%.0f u_y: dissipated %.3f J, loop area %.3f J (rel %.1e); "
        "first loading %.3f J vs %.3f J (rel %.1e)\n",
        n, x_m, dissipated, area, std::abs(dissipated / area - 1), first, first_expected,
        std::abs(first / first_expected - 1));
  }
}

}  // namespace
}  // namespace isopound
