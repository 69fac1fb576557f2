// Yielding storey laws under prescribed drift histories (issue 23): bilinear corners in closed
// form, Bouc-Wen against an independent RK4 integration of its ODE written here, and the
// peak-oriented (IMK) backbone points and one deterioration cycle computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/materials/peak_oriented.h"
#include "solver/structures/story_hysteresis.h"

namespace isopound {
namespace {

// A one-storey building whose storey has the given law (k = 600 MN/m, h = 3.2 m).
BuildingConfig one_storey(StoryHysteresisConfig h) {
  BuildingConfig b;
  FloorConfig f;
  f.mass = 340e3;
  f.stiffness = 600e6;
  f.height = 3.2;
  f.hysteresis = h;
  b.floors = {f};
  return b;
}

double force_at(UniaxialMaterial& law, double d) {
  law.set_trial(d);
  law.commit();
  return law.force();
}

TEST(StoryLaws, YieldDriftFromEachKey) {
  StoryHysteresisConfig h;
  h.law.model = HysteresisModel::kBilinear;
  h.yield_by = StoryHysteresisConfig::YieldBy::kDriftRatio;
  h.yield_value = 0.005;
  EXPECT_DOUBLE_EQ(story_yield_drift(one_storey(h), 0), 0.016);
  h.yield_by = StoryHysteresisConfig::YieldBy::kShear;
  h.yield_value = 3e6;
  EXPECT_DOUBLE_EQ(story_yield_drift(one_storey(h), 0), 3e6 / 600e6);
  h.yield_by = StoryHysteresisConfig::YieldBy::kShearCoefficient;
  h.yield_value = 0.15;
  EXPECT_DOUBLE_EQ(story_yield_drift(one_storey(h), 0), 0.15 * 9.81 * 340e3 / 600e6);
}

TEST(StoryLaws, BilinearCornersInClosedForm) {
  StoryHysteresisConfig h;
  h.law.model = HysteresisModel::kBilinear;
  h.yield_value = 0.005;  // d_y = 1.6 cm
  h.post_yield_ratio = 0.05;
  const auto law = make_story_material(one_storey(h), 0);
  const double k = 600e6, dy = 0.016, a = 0.05, fy = k * dy;
  // Elastic to yield, hardening to 3 d_y, elastic unloading over 2 d_y, reverse hardening.
  EXPECT_NEAR(force_at(*law, 0.5 * dy), 0.5 * fy, 1e-9 * fy);
  EXPECT_NEAR(force_at(*law, dy), fy, 1e-9 * fy);
  const double f3 = fy + a * k * 2 * dy;
  EXPECT_NEAR(force_at(*law, 3 * dy), f3, 1e-9 * fy);
  EXPECT_NEAR(force_at(*law, 2 * dy), f3 - k * dy, 1e-9 * fy);
  EXPECT_NEAR(force_at(*law, dy), f3 - 2 * k * dy, 1e-9 * fy);  // the reverse yield corner
  EXPECT_NEAR(law->tangent(), k, 1e-9 * k);
  EXPECT_NEAR(force_at(*law, -dy), f3 - 2 * k * dy - a * k * 2 * dy, 1e-9 * fy);
  EXPECT_NEAR(law->tangent(), a * k, 1e-9 * k);
}

// dz/dt = (A d' - gamma |d'| |z|^(n-1) z - beta d' |z|^n) / d_y along d(t) = D sin(w t),
// integrated with classical RK4 at a fine step (independent of the law's trapezoidal scheme).
TEST(StoryLaws, BoucWenMatchesRk4OfItsOde) {
  StoryHysteresisConfig h;
  h.law.model = HysteresisModel::kBoucWen;
  h.yield_value = 0.005;
  h.post_yield_ratio = 0.05;
  h.law.bouc_wen = {2, 1, 0.3, 0.7};
  const auto law = make_story_material(one_storey(h), 0);
  const double k = 600e6, dy = 0.016, a = 0.05;
  const double amplitude = 4 * dy, w = 2 * std::numbers::pi;
  const auto rate = [&](double t) { return amplitude * w * std::cos(w * t); };
  const auto dz = [&](double t, double z) {
    const double v = rate(t);
    const BoucWenShape& s = h.law.bouc_wen;
    return (s.A * v - s.gamma * std::abs(v) * std::abs(z) * z - s.beta * v * z * z) / dy;
  };
  const int steps = 20000;  // 2 cycles
  const double dt = 2.0 / steps;
  double z = 0.0, max_error = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double t = i * dt;
    const double k1 = dz(t, z), k2 = dz(t + dt / 2, z + dt / 2 * k1);
    const double k3 = dz(t + dt / 2, z + dt / 2 * k2), k4 = dz(t + dt, z + dt * k3);
    z += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    const double d = amplitude * std::sin(w * (t + dt));
    const double reference = k * (a * d + (1 - a) * dy * z);
    max_error = std::max(max_error, std::abs(force_at(*law, d) - reference));
  }
  // The law's trapezoidal rule has a local error O((dd/d_y)^3): with dd <= 2 pi D / 10^4 the
  // accumulated error stays far below 1e-4 F_y; a wrong beta/gamma sign or branch gives ~0.1 F_y.
  EXPECT_LT(max_error, 1e-4 * k * dy);
  EXPECT_GT(std::abs(z), 0.9);  // the loop did yield
}

PeakOrientedParameters imk(double lambda) {
  PeakOrientedParameters p;
  p.elastic_stiffness = 1.0;
  p.yield_deformation = 1.0;
  p.post_yield_ratio = 0.1;
  p.capping_deformation = 3.0;
  p.post_capping_ratio = 0.2;
  p.residual_strength_ratio = 0.3;
  p.deterioration = lambda;
  return p;
}

TEST(StoryLaws, PeakOrientedBackbonePoints) {
  PeakOrientedMaterial law(imk(0.0));
  // Yield (1, 1), capping (3, 1.2), post-capping slope -0.2, residual 0.3 from d = 7.5 on.
  EXPECT_NEAR(force_at(law, 0.5), 0.5, 1e-12);
  EXPECT_NEAR(force_at(law, 1.0), 1.0, 1e-12);
  EXPECT_NEAR(force_at(law, 2.0), 1.1, 1e-12);
  EXPECT_NEAR(law.tangent(), 0.1, 1e-12);
  EXPECT_NEAR(force_at(law, 3.0), 1.2, 1e-12);
  EXPECT_NEAR(force_at(law, 5.0), 1.2 - 0.2 * 2.0, 1e-12);
  EXPECT_NEAR(law.tangent(), -0.2, 1e-12);
  EXPECT_NEAR(force_at(law, 7.5), 0.3, 1e-12);
  EXPECT_NEAR(force_at(law, 9.0), 0.3, 1e-12);
  EXPECT_NEAR(law.tangent(), 0.0, 1e-12);
  // The negative side is symmetric, reached through unloading and peak-oriented reloading
  // towards (-1, -1) from the zero-force point 9 - 0.3 = 8.7.
  EXPECT_NEAR(force_at(law, 8.0), -0.7 / 9.7, 1e-12);
  EXPECT_NEAR(law.tangent(), 1.0 / 9.7, 1e-12);
  EXPECT_NEAR(force_at(law, -1.0), -1.0, 1e-12);
  EXPECT_NEAR(force_at(law, -3.0), -1.2, 1e-12);
  // Without deterioration, no energy is lost at rest: the work is the area enclosed.
  EXPECT_GT(law.dissipated_energy(), 0.0);
}

// One excursion by hand (k = d_y = F_y = 1, lambda = 10, E_t = 10): load to d = 2 (F = 1.1),
// unload with K_u = 1 to F = 0 at d = 0.9. E_1 = 0.5 + (1 + 1.1) / 2 - 1.1^2 / 2 = 0.945,
// beta_1 = E_1 / (E_t - E_1). The negative side then has F_y = 1 - beta, K_s = 0.1 (1 - beta),
// target -(1 + beta); reloading aims at (-(1 + beta), -B(1 + beta)), B(1 + beta) = (1 - beta)
// + 0.1 (1 - beta) ((1 + beta) - (1 - beta)); K_u becomes 1 - beta.
TEST(StoryLaws, PeakOrientedOneDeteriorationCycleByHand) {
  PeakOrientedMaterial law(imk(10.0));
  force_at(law, 1.0);
  EXPECT_NEAR(force_at(law, 2.0), 1.1, 1e-12);
  EXPECT_NEAR(force_at(law, 1.5), 0.6, 1e-12);  // unloading, K_u = 1
  const double e1 = 0.5 + 0.5 * (1.0 + 1.1) - 0.5 * 1.1 * 1.1;
  const double beta = e1 / (10.0 - e1);
  const double target = 1.0 + beta;
  const double target_force = (1 - beta) + 0.1 * (1 - beta) * (target - (1 - beta));
  const double reload_slope = target_force / (0.9 + target);
  EXPECT_NEAR(force_at(law, 0.4), -reload_slope * 0.5, 1e-12);
  EXPECT_NEAR(law.tangent(), reload_slope, 1e-12);
  EXPECT_NEAR(law.unloading_stiffness(), 1 - beta, 1e-12);
  EXPECT_NEAR(force_at(law, -target), -target_force, 1e-12);
  EXPECT_NEAR(law.backbone(-1, 2.0), (1 - beta) + 0.1 * (1 - beta) * (2.0 - (1 - beta)), 1e-12);
  EXPECT_NEAR(law.backbone(+1, 2.0), 1.1, 1e-12);  // the positive side not yet
  // Unloading from the negative target with the deteriorated K_u.
  EXPECT_NEAR(force_at(law, -target + 0.1), -target_force + 0.1 * (1 - beta), 1e-12);
  // The energy booked at the crossing is E_1: at zero force nothing is recoverable.
  PeakOrientedMaterial again(imk(10.0));
  force_at(again, 2.0);
  force_at(again, 0.9);
  EXPECT_NEAR(again.dissipated_energy(), e1, 1e-12);
}

TEST(StoryLaws, PeakOrientedRevertRestoresTheCommittedState) {
  PeakOrientedMaterial law(imk(10.0));
  force_at(law, 2.0);
  law.set_trial(-2.0);
  law.revert();
  EXPECT_NEAR(law.force(), 1.1, 1e-12);
  EXPECT_NEAR(force_at(law, 1.5), 0.6, 1e-12);
}

}  // namespace
}  // namespace isopound
