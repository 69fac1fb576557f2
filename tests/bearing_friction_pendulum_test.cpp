// Friction pendulum: the textbook parallelogram F = W u/R + mu W sign(v) under slow sinusoidal
// motion (through the law, and in a 2D time-history analysis), loop area 4 mu W u_0, energy
// balance.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "solver/core/analysis.h"
#include "solver/core/constants.h"
#include "solver/materials/friction_pendulum.h"
#include "solver/structures/building2d.h"
#include "solver/structures/isolator.h"
#include "test_support.h"

namespace isopound {
namespace {

using Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

// Prescribed slow motion u = u_0 sin(w t) (along x, then along a 40-degree line): v_max =
// u_0 w = 2e-4 m/s, so a v <= 0.006 and mu(v) exceeds mu_slow by at most 0.75 %. Away from the
// reversals the force is the parallelogram to 1 % of the friction force mu W (measured 0.72 %,
// the rise of mu); the loop area (work per cycle) is 4 mu_slow W u_0 to 1 % (measured +0.31 %
// plastic, +0.29 % smooth: the rise of mu adds, the rounded corners cut ~u_y/u_0). Plastic z
// turns over within 2 u_y, so points 4 u_y past a reversal are checked; the smooth (Bouc-Wen
// n = 2) z is within 1e-15 of 1 after 20 u_y.
TEST(FrictionPendulum, SlowSinusoidGivesTheTextbookParallelogram) {
  for (const bool smooth : {false, true}) {
    FrictionPendulumParameters p;
    p.weight = 1.27e6 / 16 * kGravity;
    p.radius = 2.2;
    p.mu_slow = 0.05;
    p.mu_fast = 0.11;
    p.rate_parameter = 30;
    p.yield_displacement = 5e-4;
    p.smooth = smooth;
    const double band = (smooth ? 20 : 4) * p.yield_displacement;
    const double u0 = 0.2, w = 1e-3;
    const int steps = 8000;  // per cycle
    for (const double angle : {0.0, 40.0 * kPi / 180}) {
      SCOPED_TRACE(testing::Message() << "smooth " << smooth << " angle " << angle);
      const Vector2d e(std::cos(angle), std::sin(angle));
      FrictionPendulumMaterial law(p);
      double work = 0.0, worst = 0.0, last_reversal = 0.0, previous_u = 0.0;
      Vector2d f0 = Vector2d::Zero();
      int checked = 0, sign = 1;
      const double T = 2 * kPi / w;
      for (int k = 1; k <= 2 * steps; ++k) {  // two cycles, the second one measured
        const double t = T * k / steps;
        const double u = u0 * std::sin(w * t), v = u0 * w * std::cos(w * t);
        law.set_trial(u * e, v * e);
        law.commit();
        const Vector2d f = law.force();
        if (k > steps) work += 0.5 * (f + f0).dot((u - previous_u) * e);
        f0 = f;
        const int s = (u - previous_u) >= 0 ? 1 : -1;
        if (s != sign) last_reversal = previous_u;
        sign = s;
        previous_u = u;
        if (std::abs(u - last_reversal) > band) {
          const double textbook = p.weight * u / p.radius + p.mu_slow * p.weight * s;
          worst = std::max(worst, std::abs(e.dot(f) - textbook));
          ++checked;
        }
        EXPECT_NEAR((f - e.dot(f) * e).norm(), 0.0, 1e-9 * p.weight);  // no force across
      }
      EXPECT_GT(checked, steps);  // most of the loop is checked
      EXPECT_LE(worst, 0.01 * p.mu_slow * p.weight);
      const double area = 4 * p.mu_slow * p.weight * u0;
      EXPECT_NEAR(work, area, 0.01 * area);
    }
  }
}

BuildingConfig fp_building(double mu_slow, double mu_fast) {
  BuildingConfig b;
  b.name = "fp";
  b.base_mass = 340e3;
  b.floors = {{340e3, 600e6, 3.2}, {250e3, 600e6, 3.2}};
  b.isolator.model = IsolatorConfig::Model::kFrictionPendulum;
  b.isolator.radius = 2.0;
  b.isolator.mu_slow = mu_slow;
  b.isolator.mu_fast = mu_fast;
  b.isolator.rate_parameter = 30;
  b.isolator.yield_displacement = 5e-4;
  b.isolation_damping_ratio = 0.0;
  return b;
}

int column(const History& h, const std::string& name) {
  for (std::size_t i = 0; i < h.columns.size(); ++i)
    if (h.columns[i] == name) return static_cast<int>(i);
  ADD_FAILURE() << "no column " << name;
  return 0;
}

// The same loop in a 2D analysis: a 2-storey building on a friction pendulum under a
// sinusoidal ground acceleration (T 4 s, 0.25 g, above mu g so that it slides). At every
// sample where the base slides (|z| = 1, |v| > 1 cm/s) the isolator force is
// W u/R + mu(|v|) W sign(v) to 1 % of mu W (it is that formula at the step's trial state; the
// tolerance covers nothing but output round-off), with W the building's weight. The energy
// balance closes to 1e-3 of the input (the rate-dependent friction is included in the work).
TEST(FrictionPendulum, TwoDimensionalAnalysisFollowsTheParallelogram) {
  for (const auto& [mu_slow, mu_fast] : {std::pair{0.05, 0.05}, std::pair{0.04, 0.10}}) {
    BuildingConfig b = fp_building(mu_slow, mu_fast);
    Model model = make_model(b);
    ASSERT_FALSE(model.elements.empty());
    GroundMotion motion;
    motion.name = "sine";
    motion.dt = 0.005;
    for (int k = 0; k <= 2400; ++k)
      motion.acceleration.push_back(0.25 * kGravity * std::sin(2 * kPi * k * motion.dt / 4.0));
    RunOptions options;
    options.output.interval = 0.0;
    const AnalysisResult r = run_analysis(model, motion, options);
    const History& h = r.history;
    const int f_col = column(h, "fp/isolator force [N]");
    const int d_col = column(h, "fp/isolator deformation [m]");
    const int z_col = column(h, "fp/isolator z [-]");
    const int v_col = column(h, "fp/base v [m/s]");
    const double W = model.total_mass() * kGravity;
    const double R = b.isolator.radius;
    double worst = 0.0, max_u = 0.0;
    int sliding = 0;
    for (std::size_t row = 0; row < h.rows(); ++row) {
      const double* x = &h.values[row * h.columns.size()];
      max_u = std::max(max_u, std::abs(x[d_col]));
      if (std::abs(x[z_col]) < 1.0 || std::abs(x[v_col]) < 0.01) continue;
      const double v = x[v_col];
      const double mu = mu_fast - (mu_fast - mu_slow) * std::exp(-30 * std::abs(v));
      const double textbook = W * x[d_col] / R + mu * W * (v > 0 ? 1 : -1);
      worst = std::max(worst, std::abs(x[f_col] - textbook));
      ++sliding;
    }
    EXPECT_GT(sliding, static_cast<int>(h.rows() / 2));
    EXPECT_GT(max_u, 0.05);  // it really slides back and forth
    EXPECT_LE(worst, 0.01 * mu_slow * W);
    EXPECT_LT(r.energy.relative_error, 1e-3);
    EXPECT_GT(r.energy.hysteretic, 0.0);
  }
}

// Isolation period and properties of the friction pendulum as a 2D isolator.
TEST(FrictionPendulum, IsolatorPropertiesArePendulumStiffnessAndFriction) {
  IsolatorConfig c;
  c.model = IsolatorConfig::Model::kFrictionPendulum;
  c.radius = 2.5;
  c.mu_slow = 0.06;
  c.yield_displacement = 5e-4;
  const double m = 1e6;
  const IsolatorProperties p = isolator_properties(c, m);
  EXPECT_DOUBLE_EQ(p.post_yield_stiffness, m * kGravity / 2.5);
  EXPECT_DOUBLE_EQ(p.characteristic_strength, 0.06 * m * kGravity);
  EXPECT_NEAR(isolation_period(c), 2 * kPi * std::sqrt(2.5 / kGravity), 1e-12);
  EXPECT_THROW(make_isolator_material(c, m), std::invalid_argument);
}

// `isopound run` on the shipped configs/3storey-friction-pendulum.yaml (RSN1084 SCS052): the
// peak isolator force lies between the parallelogram's corners at the peak displacement,
// W u_max/R + mu_slow W (at the turning point v = 0) and W u_max/R + mu_fast W (an upper bound
// at any velocity); the energy balance closes.
TEST(FrictionPendulum, ShippedConfigRunsWithIsopoundRun) {
  ISOPOUND_REQUIRE_RECORDS();
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() / ("isopound_fp_" + std::to_string(::getpid()));
  const test::CommandResult run = test::run_isopound(
      "run '" + (test::source_dir() / "configs" / "3storey-friction-pendulum.yaml").string() +
      "' -q --no-histories -o '" + out.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  fs::remove_all(out);
  const nlohmann::json* isolator = nullptr;
  for (const auto& e : j["elements"])
    if (e["label"] == "3-storey-fp/isolator") isolator = &e;
  ASSERT_NE(isolator, nullptr);
  const double W = (3 * 340e3 + 250e3) * kGravity, R = 2.24;
  const double u_max = (*isolator)["peak_deformation"]["value"];
  const double f_max = (*isolator)["peak_force"]["value"];
  EXPECT_GT(u_max, 0.1);
  EXPECT_GE(f_max, W * u_max / R + 0.04 * W * 0.99);
  EXPECT_LE(f_max, W * u_max / R + 0.10 * W);
  EXPECT_LT(j["energy"]["relative_error"].get<double>(), 1e-4);
}

}  // namespace
}  // namespace isopound
