// Linear SDOF (T = 2 s, xi = 0 and 5 %) through NewmarkStepper and run_analysis, checked against
// the closed-form damped free vibration and the exact Nigam-Jennings recurrence (error and order).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/core/analysis.h"
#include "solver/core/model.h"
#include "solver/core/newmark.h"
#include "solver/elements/uniaxial_link.h"
#include "solver/excitation/ground_motion.h"
#include "solver/materials/linear_material.h"
#include "solver/structures/config.h"

namespace isopound {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMass = 2.5e5;  // kg (any value: the response per unit mass is what matters)
constexpr double kPeriod = 2.0;  // s
constexpr double kOmega = 2.0 * kPi / kPeriod;
constexpr double kStiffness = kMass * kOmega * kOmega;
constexpr double kRatios[] = {0.0, 0.05};
constexpr const char* kLabel = "sdof";

// A 1-DOF model: the spring either in model.stiffness or as a UniaxialLink(ground, 0, k).
Model make_sdof(double xi, bool spring_as_element) {
  Model m;
  m.mass = Eigen::MatrixXd::Constant(1, 1, kMass);
  m.damping = Eigen::MatrixXd::Constant(1, 1, 2.0 * xi * kMass * kOmega);
  m.stiffness = Eigen::MatrixXd::Constant(1, 1, spring_as_element ? 0.0 : kStiffness);
  m.influence = Eigen::VectorXd::Ones(1);
  m.dofs.push_back({kLabel, 0, 0});
  if (spring_as_element)
    m.elements.push_back(std::make_unique<UniaxialLink>(
        "spring", kGround, 0, std::make_unique<LinearMaterial>(kStiffness)));
  return m;
}

// ---------------------------------------------------------------------------------------------
// References

// Closed-form free vibration of m u'' + c u' + k u = 0 (xi < 1).
struct FreeVibration {
  double xi, u0, v0;
  double omega_d() const { return kOmega * std::sqrt(1.0 - xi * xi); }
  double operator()(double t) const {
    const double wd = omega_d();
    return std::exp(-xi * kOmega * t) *
           (u0 * std::cos(wd * t) + (v0 + xi * kOmega * u0) / wd * std::sin(wd * t));
  }
  // Envelope amplitude sqrt(u0^2 + ((v0 + xi w u0)/wd)^2) e^{-xi w t}.
  double amplitude(double t) const {
    const double b = (v0 + xi * kOmega * u0) / omega_d();
    return std::sqrt(u0 * u0 + b * b) * std::exp(-xi * kOmega * t);
  }
};

// Nigam-Jennings (Chopra, Dynamics of Structures, table 5.2.1): exact response of
// m u'' + c u' + k u = p(t) for p linear between samples p_i, p_{i+1} a step dt apart.
struct NigamJennings {
  double A, B, C, D, Ap, Bp, Cp, Dp;

  NigamJennings(double xi, double dt) {
    const double w = kOmega, k = kStiffness;
    const double s1 = std::sqrt(1.0 - xi * xi);
    const double wd = w * s1;
    const double e = std::exp(-xi * w * dt);
    const double sn = std::sin(wd * dt), cs = std::cos(wd * dt);
    A = e * (xi / s1 * sn + cs);
    B = e * sn / wd;
    C = (2.0 * xi / (w * dt) + e * (((1.0 - 2.0 * xi * xi) / (wd * dt) - xi / s1) * sn -
                                    (1.0 + 2.0 * xi / (w * dt)) * cs)) /
        k;
    D = (1.0 - 2.0 * xi / (w * dt) +
         e * ((2.0 * xi * xi - 1.0) / (wd * dt) * sn + 2.0 * xi / (w * dt) * cs)) /
        k;
    Ap = -e * w / s1 * sn;
    Bp = e * (cs - xi / s1 * sn);
    Cp = (-1.0 / dt + e * ((w / s1 + xi / (dt * s1)) * sn + cs / dt)) / k;
    Dp = (1.0 - e * (xi / s1 * sn + cs)) / (k * dt);
  }

  // Displacements at every sample of p (from rest).
  std::vector<double> run(const std::vector<double>& p) const {
    std::vector<double> u(p.size(), 0.0);
    double ui = 0.0, vi = 0.0;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
      const double un = A * ui + B * vi + C * p[i] + D * p[i + 1];
      const double vn = Ap * ui + Bp * vi + Cp * p[i] + Dp * p[i + 1];
      ui = un;
      vi = vn;
      u[i + 1] = ui;
    }
    return u;
  }
};

// ---------------------------------------------------------------------------------------------
// The reference recurrence itself, against closed forms (so a typo in a coefficient cannot
// make the forced comparisons pass or fail for the wrong reason). Closed forms from rest:
//   step p0:  u = p0/k [1 - e^{-xi w t} (cos wd t + xi/sqrt(1-xi^2) sin wd t)]
//   ramp r t: u = r/k [t - 2 xi/w + e^{-xi w t} (2 xi/w cos wd t - (1 - 2 xi^2)/wd sin wd t)]
// Both are exactly linear between samples, so the recurrence must reproduce them to round-off:
// 1e-10 relative allows ~1e3 steps of accumulated double round-off with a wide margin.

TEST(LinearSdofReference, NigamJenningsIsExactForStepAndRamp) {
  for (double xi : kRatios) {
    SCOPED_TRACE("xi = " + std::to_string(xi));
    const double dt = 0.013;
    const NigamJennings nj(xi, dt);
    const double wd = kOmega * std::sqrt(1.0 - xi * xi);
    const int n = 1000;
    const double p0 = 3.0e5, r = 7.0e4;
    std::vector<double> step(n + 1, p0), ramp(n + 1);
    for (int i = 0; i <= n; ++i) ramp[i] = r * i * dt;
    const std::vector<double> us = nj.run(step), ur = nj.run(ramp);
    double es = 0.0, er = 0.0, ps = 0.0, pr = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double t = i * dt, e = std::exp(-xi * kOmega * t);
      const double xs =
          p0 / kStiffness *
          (1.0 - e * (std::cos(wd * t) + xi / std::sqrt(1 - xi * xi) * std::sin(wd * t)));
      const double xr = r / kStiffness *
                        (t - 2.0 * xi / kOmega +
                         e * (2.0 * xi / kOmega * std::cos(wd * t) -
                              (1.0 - 2.0 * xi * xi) / wd * std::sin(wd * t)));
      es = std::max(es, std::abs(us[i] - xs));
      er = std::max(er, std::abs(ur[i] - xr));
      ps = std::max(ps, std::abs(xs));
      pr = std::max(pr, std::abs(xr));
    }
    EXPECT_LE(es, 1e-10 * ps);
    EXPECT_LE(er, 1e-10 * pr);
  }
}

// ---------------------------------------------------------------------------------------------
// Free vibration through NewmarkStepper

constexpr double kU0 = 0.1, kV0 = 0.2;  // m, m/s
constexpr int kFreePeriods = 10;

struct FreeRun {
  std::vector<double> u;  // u at step n (t = n h), n = 0..N
  double h = 0.0;
};

FreeRun free_run(double xi, bool spring_as_element, int steps_per_period) {
  Model model = make_sdof(xi, spring_as_element);
  NewmarkStepper stepper(model, NewtonSettings{});
  FreeRun run;
  run.h = kPeriod / steps_per_period;
  const int n = kFreePeriods * steps_per_period;
  stepper.start(Eigen::VectorXd::Constant(1, kU0), Eigen::VectorXd::Constant(1, kV0), 0.0);
  run.u.push_back(stepper.u()[0]);
  for (int i = 0; i < n; ++i) {
    const StepOutcome out = stepper.try_step(run.h, 0.0);
    if (!out.converged) throw std::runtime_error("Newmark step did not converge");
    stepper.accept();
    run.u.push_back(stepper.u()[0]);
  }
  return run;
}

double free_error(double xi, const FreeRun& run) {
  const FreeVibration exact{xi, kU0, kV0};
  double err = 0.0;
  for (std::size_t i = 0; i < run.u.size(); ++i)
    err = std::max(err, std::abs(run.u[i] - exact(static_cast<double>(i) * run.h)));
  return err;
}

TEST(LinearSdofFreeVibration, SpringInStiffnessOrAsElementIsTheSame) {
  // Same linear algebra up to round-off (the element adds k to the Newton tangent that the
  // other way has in K_hat; one Newton correction solves the linear step exactly). Round-off
  // enters each step at a few eps relative and accumulates at most linearly (phase) over the
  // 2000 steps: measured 1.1e-11 of u0 undamped, 1.4e-12 at 5 %. 1e-10 of u0 keeps a
  // margin and is still 1e6 times below the discretisation error, so a different step law
  // (e.g. the element force lagging one step) cannot pass.
  for (double xi : kRatios) {
    SCOPED_TRACE("xi = " + std::to_string(xi));
    const FreeRun a = free_run(xi, false, 200), b = free_run(xi, true, 200);
    ASSERT_EQ(a.u.size(), b.u.size());
    double diff = 0.0;
    for (std::size_t i = 0; i < a.u.size(); ++i) diff = std::max(diff, std::abs(a.u[i] - b.u[i]));
    EXPECT_LE(diff, 1e-10 * kU0);
  }
}

// Leading-order global error of the trapezoidal rule (Newmark average acceleration): each
// eigenvalue lambda of the oscillator (|lambda| = w) becomes lambda (1 + (lambda h)^2/12 + ...),
// so after time t the error is about amplitude(t) * w t (w h)^2 / 12 (pure period elongation for
// xi = 0: the amplitude is conserved exactly). The bound is the max over the run of that product.
double predicted_free_error(double xi, double h, double t_end) {
  const FreeVibration exact{xi, kU0, kV0};
  double e = 0.0;
  for (double t = 0.0; t <= t_end + 1e-12; t += h)
    e = std::max(e, exact.amplitude(t) * kOmega * t * (kOmega * h) * (kOmega * h) / 12.0);
  return e;
}

TEST(LinearSdofFreeVibration, MatchesClosedFormAtTOver200) {
  for (double xi : kRatios) {
    for (bool as_element : {false, true}) {
      SCOPED_TRACE("xi = " + std::to_string(xi) + (as_element ? ", element" : ", K"));
      const FreeRun run = free_run(xi, as_element, 200);
      const FreeVibration exact{xi, kU0, kV0};
      double peak = 0.0;
      for (std::size_t i = 0; i < run.u.size(); ++i)
        peak = std::max(peak, std::abs(exact(static_cast<double>(i) * run.h)));
      const double err = free_error(xi, run);
      const double predicted = predicted_free_error(xi, run.h, kFreePeriods * kPeriod);
      std::printf(
          "[ sdof free ] xi=%.2f %s h=T/200: max err %.3e m = %.3e of peak (predicted %.3e)\n", xi,
          as_element ? "element" : "K      ", err, err / peak, predicted / peak);
      // 10 % over the leading-order error: the next term is O((w h)^4) ~ 1e-6 relative to it.
      EXPECT_LE(err, 1.1 * predicted);
      // And not suspiciously small either (a different, e.g. higher-order, scheme): the
      // leading term is attained within 10 % at the worst time.
      EXPECT_GE(err, 0.9 * predicted);
      // The brief's 2e-3-of-peak criterion holds for xi = 5 % (the decay limits the phase
      // error); for xi = 0 the theoretical error after 10 periods is 20 pi (w h)^2/12 = 5.2e-3
      // of the amplitude, so 2e-3 is unattainable at h = T/200 by any correct Newmark code.
      if (xi > 0) {
        EXPECT_LE(err, 2e-3 * peak);
      }
    }
  }
}

TEST(LinearSdofFreeVibration, SecondOrderConvergence) {
  // Global error C h^2 + O(h^4): with (w h)^2 <= 1e-3 the O(h^4) part moves log2 of the ratio
  // by ~1e-3, so [1.9, 2.1] is a safe but discriminating window (first order would give 1).
  for (double xi : kRatios) {
    for (bool as_element : {false, true}) {
      SCOPED_TRACE("xi = " + std::to_string(xi) + (as_element ? ", element" : ", K"));
      const double e200 = free_error(xi, free_run(xi, as_element, 200));
      const double e400 = free_error(xi, free_run(xi, as_element, 400));
      const double e800 = free_error(xi, free_run(xi, as_element, 800));
      const double p1 = std::log2(e200 / e400), p2 = std::log2(e400 / e800);
      std::printf("[ sdof free ] xi=%.2f %s errors %.3e %.3e %.3e orders %.4f %.4f\n", xi,
                  as_element ? "element" : "K      ", e200, e400, e800, p1, p2);
      EXPECT_GE(p1, 1.9);
      EXPECT_LE(p1, 2.1);
      EXPECT_GE(p2, 1.9);
      EXPECT_LE(p2, 2.1);
    }
  }
}

TEST(LinearSdofFreeVibration, TinyStepIsNotLessAccurateThanCoarseStep) {
  // One period at h = 5e-6 s (T/400000) against h = 1e-3 s (T/2000). The truncation error at
  // 5e-6 s is w T (w h)^2/12 = 1.3e-10 of the amplitude. Round-off of an incremental update
  // (unknown du = u1 - u0) is ~eps |v| per step in v, at most N 4 eps = 3.5e-10 relative over
  // the N = 4e5 steps even if it all adds up: 1e-9 of the amplitude bounds both (measured
  // 1.2e-10). A total-displacement update (p_hat ~ 4 M u0 / h^2) with a round-off allowance
  // 64 eps |p_hat| in the Newton test accepts the constant-acceleration predictor in most steps
  // (a1 = a0) and errs by 1.8e-4 here, 40 times worse than the 200 times larger step.
  for (bool as_element : {false, true}) {
    SCOPED_TRACE(as_element ? "element" : "K");
    auto one_period = [&](int steps) {
      Model model = make_sdof(0.0, as_element);
      NewmarkStepper stepper(model, NewtonSettings{});
      const double h = kPeriod / steps;
      stepper.start(Eigen::VectorXd::Constant(1, kU0), Eigen::VectorXd::Constant(1, kV0), 0.0);
      const FreeVibration exact{0.0, kU0, kV0};
      double err = 0.0;
      long predictor_only = 0;
      for (int i = 1; i <= steps; ++i) {
        const StepOutcome out = stepper.try_step(h, 0.0);
        EXPECT_TRUE(out.converged);
        if (out.iterations == 0) ++predictor_only;
        stepper.accept();
        err = std::max(err, std::abs(stepper.u()[0] - exact(i * h)));
      }
      const double amplitude = exact.amplitude(0.0);
      std::printf(
          "[ sdof tiny ] %s h=T/%d: max err %.3e of amplitude (truncation %.3e), "
          "predictor accepted without correction in %ld of %d steps\n",
          as_element ? "element" : "K      ", steps, err / amplitude,
          kOmega * kPeriod * std::pow(kOmega * h, 2) / 12.0, predictor_only, steps);
      return err;
    };
    const double coarse = one_period(2000), tiny = one_period(400000);
    EXPECT_LE(tiny, coarse);
    const double amplitude = FreeVibration{0.0, kU0, kV0}.amplitude(0.0);
    EXPECT_LE(tiny, 1e-9 * amplitude);
  }
}

// ---------------------------------------------------------------------------------------------
// Forced response through run_analysis

constexpr double kG = 9.81;
constexpr double kRecordDt = kPeriod / 200.0;  // 0.01 s
constexpr int kRecordSamples = 2401;           // 24 s = 12 periods

// 0.3 g sin(2 pi t / 1.3 s) plus a few arbitrary spikes (still piecewise linear: the exact
// reference sees the same samples).
GroundMotion forced_record() {
  GroundMotion gm;
  gm.name = "harmonic+spikes";
  gm.dt = kRecordDt;
  gm.acceleration.resize(kRecordSamples);
  for (int i = 0; i < kRecordSamples; ++i)
    gm.acceleration[i] = 0.3 * kG * std::sin(2.0 * kPi * i * kRecordDt / 1.3);
  gm.acceleration[137] += 2.1;
  gm.acceleration[138] -= 1.4;
  gm.acceleration[611] -= 3.3;
  gm.acceleration[1290] += 1.7;
  gm.acceleration[1291] += 0.9;
  return gm;
}

// Every other sample is the midpoint: the same piecewise-linear a_g(t).
GroundMotion resampled_half(const GroundMotion& gm) {
  GroundMotion out;
  out.name = gm.name + "/2";
  out.dt = gm.dt / 2.0;
  const std::size_t n = gm.acceleration.size();
  out.acceleration.resize(2 * n - 1);
  for (std::size_t i = 0; i < n; ++i) {
    out.acceleration[2 * i] = gm.acceleration[i];
    if (i + 1 < n)
      out.acceleration[2 * i + 1] = 0.5 * (gm.acceleration[i] + gm.acceleration[i + 1]);
  }
  return out;
}

// Displacement history column of the single DOF.
std::vector<double> displacement_history(const AnalysisResult& res) {
  const History& h = res.history;
  const auto it = std::find(h.columns.begin(), h.columns.end(), std::string(kLabel) + " u [m]");
  if (it == h.columns.end()) throw std::runtime_error("no displacement column");
  const std::size_t col = static_cast<std::size_t>(it - h.columns.begin());
  std::vector<double> u(h.rows());
  for (std::size_t r = 0; r < u.size(); ++r) u[r] = h.values[r * h.columns.size() + col];
  return u;
}

AnalysisResult run_fixed(double xi, bool as_element, const GroundMotion& gm, double dt) {
  Model model = make_sdof(xi, as_element);
  RunOptions opt;
  opt.analysis.stepping = AnalysisConfig::Stepping::kFixed;
  opt.analysis.dt = dt;
  opt.output.interval = 0.0;  // a row at every record sample
  return run_analysis(model, gm, opt);
}

// Max error at the original samples (every `stride`-th row of the history).
double forced_error(const std::vector<double>& num, const std::vector<double>& exact, int stride) {
  double err = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i)
    err = std::max(err, std::abs(num[i * stride] - exact[i]));
  return err;
}

TEST(LinearSdofForced, MatchesNigamJenningsWithSecondOrder) {
  const GroundMotion gm = forced_record();
  const GroundMotion gm2 = resampled_half(gm);
  for (double xi : kRatios) {
    const NigamJennings nj(xi, kRecordDt);
    std::vector<double> p(gm.acceleration.size());
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = -kMass * gm.acceleration[i];
    const std::vector<double> exact = nj.run(p);
    double peak = 0.0;
    for (double x : exact) peak = std::max(peak, std::abs(x));
    for (bool as_element : {false, true}) {
      SCOPED_TRACE("xi = " + std::to_string(xi) + (as_element ? ", element" : ", K"));
      const AnalysisResult r1 = run_fixed(xi, as_element, gm, kRecordDt);
      const std::vector<double> u1 = displacement_history(r1);
      ASSERT_EQ(u1.size(), exact.size());
      // Rows are at the samples: time column = i dt (to round-off of the step sum).
      for (std::size_t i = 0; i < u1.size(); i += 97)
        ASSERT_NEAR(r1.history.values[i * r1.history.columns.size()], i * kRecordDt, 1e-9);
      const AnalysisResult r2 = run_fixed(xi, as_element, gm2, kRecordDt / 2.0);
      const std::vector<double> u2 = displacement_history(r2);
      ASSERT_EQ(u2.size(), 2 * exact.size() - 1);
      // Same record sub-stepped twice per sample: the solver's own linear interpolation must
      // give the resampled record's response (only interpolation round-off differs).
      const AnalysisResult r3 = run_fixed(xi, as_element, gm, kRecordDt / 2.0);
      const std::vector<double> u3 = displacement_history(r3);
      ASSERT_EQ(u3.size(), exact.size());
      EXPECT_EQ(r3.stats.steps, 2 * static_cast<long>(exact.size() - 1));

      const double e1 = forced_error(u1, exact, 1);
      const double e2 = forced_error(u2, exact, 2);
      double d23 = 0.0;
      for (std::size_t i = 0; i < u3.size(); ++i) d23 = std::max(d23, std::abs(u3[i] - u2[2 * i]));
      const double order = std::log2(e1 / e2);
      std::printf(
          "[ sdof forced ] xi=%.2f %s peak %.4e m, err dt %.3e (%.3e of peak), "
          "dt/2 %.3e, order %.4f, substep-vs-resampled %.1e\n",
          xi, as_element ? "element" : "K      ", peak, e1, e1 / peak, e2, order, d23);
      // Error budget (trapezoidal rule, eigenvalue error lambda (lambda h)^2/12): the response
      // at the natural frequency accumulates a phase error w t (w h)^2/12 over its memory time
      // t (t_end = 24 s undamped, ~1/(xi w) = 6.4 s at 5 %); the forced part at 1.3 s errs by
      // (w_f h)^2/12 = 2e-4. Bound (w h)^2/12 (1 + w t): 6.3e-3 of the peak undamped (measured
      // 3.6e-3), 1.7e-3 at 5 % (measured 6.9e-4), where the 2e-3 criterion applies. A first-order
      // scheme or a mis-timed a_g (half a step) errs by ~1e-2 and fails both.
      const double wh = kOmega * kRecordDt, t_end = (kRecordSamples - 1) * kRecordDt;
      const double bound = xi > 0 ? 2e-3 : wh * wh / 12.0 * (1.0 + kOmega * t_end);
      EXPECT_LE(e1, bound * peak);
      EXPECT_GE(order, 1.9);
      EXPECT_LE(order, 2.1);
      EXPECT_LE(d23, 1e-9 * peak);
    }
  }
}

}  // namespace
}  // namespace isopound
