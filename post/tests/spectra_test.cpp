// Response spectra: the ordinate equals the peak of the solver's own linear SDOF analysis at the
// same period and damping; RotD100 >= RotD50 and RotD100 equals an independent 180-angle maximum.
#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "post/spectra.h"
#include "post_test_support.h"
#include "solver/core/analysis.h"
#include "solver/core/model.h"

namespace isopound::post {
namespace {

constexpr double kPi = std::numbers::pi;

// A synthetic accelerogram (m/s^2) written as a columns file and read back through the solver's
// record reader, so the spectrum sees exactly what an analysis would.
GroundMotion synthetic_record(const std::filesystem::path& dir, const std::string& name,
                              double phase, double dt = 0.01, double duration = 6.0) {
  const auto path = dir / (name + ".txt");
  std::ofstream out(path);
  out.precision(17);
  const int n = static_cast<int>(duration / dt);
  for (int i = 0; i <= n; ++i) {
    const double t = i * dt;
    const double env = std::sin(kPi * t / duration);
    out << env * (2.0 * std::sin(2 * kPi * 1.1 * t + phase) + 1.2 * std::sin(2 * kPi * 3.7 * t) +
                  0.7 * std::cos(2 * kPi * 0.45 * t + 2 * phase))
        << "\n";
  }
  out.close();
  RecordReadOptions o;
  o.format = RecordReadOptions::Format::kColumns;
  o.dt = dt;
  o.unit = AccelerationUnit::kMetrePerSecond2;
  return read_record(path.string(), o);
}

// Peak |u| of the solver's linear 1-DOF model (stiffness and damping matrices, no element) under
// the record, fixed Newmark step h: the solver's peak over all its steps.
double solver_peak(const GroundMotion& gm, double period, double xi, double h) {
  const double m = 1.0e5, w = 2 * kPi / period;
  Model model;
  model.mass = Eigen::MatrixXd::Constant(1, 1, m);
  model.damping = Eigen::MatrixXd::Constant(1, 1, 2 * xi * m * w);
  model.stiffness = Eigen::MatrixXd::Constant(1, 1, m * w * w);
  model.influence = Eigen::VectorXd::Ones(1);
  model.dofs.push_back({"sdof", 0, 0});
  RunOptions opt;
  opt.analysis.stepping = AnalysisConfig::Stepping::kFixed;
  opt.analysis.dt = h;
  opt.output.histories = false;
  return run_analysis(model, gm, opt).displacement[0].value;
}

TEST(PostSpectra, OrdinateEqualsSolverLinearSdofPeak) {
  const auto dir = test::scratch_dir("sdof");
  const GroundMotion gm = synthetic_record(dir, "synthetic", 0.3);
  const double xi = 0.05;
  for (double period : {0.5, 1.0, 2.5}) {
    SCOPED_TRACE("T = " + std::to_string(period));
    // Both sample the response every h = dt/N: the spectrum exactly (piecewise-linear record),
    // the solver with Newmark's O(h^2) error. The difference is the Newmark error alone.
    const int n_coarse = 40, n_fine = 80;
    SpectrumOptions so;
    so.damping = xi;
    so.oversample = n_coarse;
    const double sd_coarse = response_spectrum(gm, {period}, so).sd[0];
    so.oversample = n_fine;
    const double sd_fine = response_spectrum(gm, {period}, so).sd[0];
    const double e_coarse = solver_peak(gm, period, xi, gm.dt / n_coarse) - sd_coarse;
    const double e_fine = solver_peak(gm, period, xi, gm.dt / n_fine) - sd_fine;
    std::printf(
        "[ spectra ] T=%.2f SD %.6e m, solver - spectrum: h=dt/%d %.2e, h=dt/%d %.2e (rel %.2e)\n",
        period, sd_fine, n_coarse, e_coarse, n_fine, e_fine, std::abs(e_fine) / sd_fine);
    // Tolerance 1e-6 relative: average-acceleration Newmark has a relative period error
    // (w h)^2 / 12, at h = dt/80 and T = 0.5 s (w h)^2/12 = 3e-7 per cycle, carried into the peak
    // over the record's few cycles (measured: 6e-9, 2.2e-7, 1.8e-8 of the peak at T = 0.5, 1,
    // 2.5 s). The halving check shows the difference is that O(h^2) Newmark error (ratio 3.8-4.0
    // measured), not a defect of the recurrence or of the peak definition (which would not shrink).
    EXPECT_LT(std::abs(e_fine), 1e-6 * sd_fine);
    if (std::abs(e_fine) > 1e-9 * sd_fine) {
      EXPECT_NEAR(e_coarse / e_fine, 4.0, 1.0);
    }
    // PSA = w^2 SD.
    EXPECT_NEAR(response_spectrum(gm, {period}, so).psa[0], std::pow(2 * kPi / period, 2) * sd_fine,
                1e-12 * sd_fine * std::pow(2 * kPi / period, 2));
  }
  std::filesystem::remove_all(dir);
}

TEST(PostSpectra, ZeroPeriodIsPga) {
  const auto dir = test::scratch_dir("pga");
  const GroundMotion gm = synthetic_record(dir, "s", 0.1);
  double pga = 0;
  for (double a : gm.acceleration) pga = std::max(pga, std::abs(a));
  const Spectrum s = response_spectrum(gm, {0.0, 0.01});
  EXPECT_DOUBLE_EQ(s.psa[0], pga);
  // A very stiff oscillator follows the ground: PSA -> PGA (within 2 %).
  EXPECT_NEAR(s.psa[1], pga, 0.02 * pga);
  std::filesystem::remove_all(dir);
}

// Independent SDOF: the exact state transition of [u, v, p, p'] over a step by the matrix
// exponential (Eigen), with p linear in the step, for the rotated record at each angle.
double independent_peak(const std::vector<double>& a, double dt, double period, double xi) {
  const double w = 2 * kPi / period;
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A(0, 1) = 1;
  A(1, 0) = -w * w;
  A(1, 1) = -2 * xi * w;
  A(1, 2) = 1;  // + p(t), p = -a_g
  A(2, 3) = 1;  // p' constant over the step
  const Eigen::Matrix4d E = (A * dt).exp();
  Eigen::Vector4d x = Eigen::Vector4d::Zero();
  double peak = 0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    x(2) = -a[i];
    x(3) = -(a[i + 1] - a[i]) / dt;
    x = E * x;
    peak = std::max(peak, std::abs(x(0)));
  }
  return peak;
}

TEST(PostSpectra, RotD100IsTheMaximumOver180AnglesAndAtLeastRotD50) {
  const auto dir = test::scratch_dir("rotd");
  const GroundMotion g1 = synthetic_record(dir, "c1", 0.0, 0.02, 8.0);
  const GroundMotion g2 = synthetic_record(dir, "c2", 1.3, 0.02, 8.0);
  const std::vector<double> periods{0.3, 1.0, 3.0};
  const RotDSpectrum r = rotd_spectrum(g1, g2, periods);
  for (std::size_t k = 0; k < periods.size(); ++k) {
    SCOPED_TRACE("T = " + std::to_string(periods[k]));
    EXPECT_GE(r.sd100[k], r.sd50[k]);
    EXPECT_GE(r.psa100[k], r.psa50[k]);
    std::vector<double> peaks;
    for (int d = 0; d < 180; ++d) {
      const double c = std::cos(d * kPi / 180), s = std::sin(d * kPi / 180);
      std::vector<double> a(g1.acceleration.size());
      for (std::size_t i = 0; i < a.size(); ++i)
        a[i] = c * g1.acceleration[i] + s * g2.acceleration[i];
      peaks.push_back(independent_peak(a, g1.dt, periods[k], 0.05));
    }
    const double max = *std::max_element(peaks.begin(), peaks.end());
    std::sort(peaks.begin(), peaks.end());
    // Both are exact for the piecewise-linear record: equal to round-off (1e-9 relative allows
    // the ~400-step accumulation of two different exact propagators).
    EXPECT_NEAR(r.sd100[k], max, 1e-9 * max);
    EXPECT_NEAR(r.sd50[k], 0.5 * (peaks[89] + peaks[90]), 1e-9 * max);
    // Each component alone is one of the angles (0 and 90 deg): not above RotD100.
    const Spectrum s1 = response_spectrum(g1, {periods[k]}),
                   s2 = response_spectrum(g2, {periods[k]});
    EXPECT_LE(std::max(s1.sd[0], s2.sd[0]), r.sd100[k] * (1 + 1e-12));
  }
  std::filesystem::remove_all(dir);
}

// The per-angle peaks skip samples and angles that cannot hold a peak (spectra.cpp, rotd_peaks):
// at T = 0 the RotD ordinates are the peaks of the accelerations themselves, so they must equal,
// bit for bit, a plain loop over every sample and every angle with the same products. Orbits
// that stress the skipping: an ellipse growing and shrinking (many samples raise peaks), one
// almost a line (the smallest peak tiny), sharp reversals and corners (turns near and above
// 90°), repeated samples and steps of a few ulps (the arc's rounding margin), noise, and
// samples at every ±0 and tiny magnitude.
TEST(PostSpectra, RotDPeaksEqualEveryAngleOfEverySampleBitForBit) {
  std::uint64_t state = 12345;
  const auto uniform = [&] {  // in [0, 1): a fixed generator, the same on every platform
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  for (int orbit = 0; orbit < 60; ++orbit) {
    SCOPED_TRACE("orbit " + std::to_string(orbit));
    const int kind = orbit % 6;
    const int n = 200 + static_cast<int>(3000 * uniform());
    const double aspect = std::pow(10.0, -6.0 * uniform()), tilt = kPi * uniform();
    const double per_period = 4.0 + 80.0 * uniform();
    Accelerogram x{"x", {}, {}}, y{"y", {}, {}};
    for (int k = 0; k < n; ++k) {
      const double t = 2.0 * kPi * k / per_period;
      double a = std::cos(t), b = aspect * std::sin(t);
      const double grow = 0.2 + std::sin(kPi * k / n);  // up, then down
      a *= grow, b *= grow;
      if (kind == 1) a = std::copysign(std::pow(std::abs(a), 0.2), a), b *= 1e-9;  // near a line
      if (kind == 2) a = (k / 7) % 2 ? 1.0 - uniform() * 1e-15 : -1.0, b = uniform() * 1e-3;
      if (kind == 3 && k % 5 != 0)
        a = x.acceleration.empty() ? a : x.acceleration.back(),
        b = y.acceleration.empty() ? b : y.acceleration.back();
      if (kind == 3 && k % 11 == 0) a = std::nextafter(a, 2.0);
      if (kind == 4) a += 0.3 * (uniform() - 0.5), b += 0.3 * (uniform() - 0.5);
      if (kind == 5) a = k % 3 ? 0.0 : (k % 2 ? -0.0 : 1e-300 * uniform()), b = k % 4 ? b : -0.0;
      x.time.push_back(0.01 * k);
      y.time.push_back(0.01 * k);
      x.acceleration.push_back(std::cos(tilt) * a - std::sin(tilt) * b);
      y.acceleration.push_back(std::sin(tilt) * a + std::cos(tilt) * b);
    }
    std::vector<double> peaks(180, 0.0);
    for (int d = 0; d < 180; ++d) {
      const double c = std::cos(d * kPi / 180.0), s = std::sin(d * kPi / 180.0);
      for (int k = 0; k < n; ++k)
        peaks[d] = std::max(peaks[d], std::abs(x.acceleration[k] * c + y.acceleration[k] * s));
    }
    std::sort(peaks.begin(), peaks.end());
    const RotDSpectrum r = rotd_spectrum(x, y, {0.0});
    EXPECT_EQ(r.psa100[0], peaks[179]);
    EXPECT_EQ(r.psa50[0], 0.5 * (peaks[89] + peaks[90]));
  }
}

// An accelerogram at irregular times (a run's analysis steps) drawing the same straight lines as
// a uniform record: the record's samples, each 3rd interval split at 37 %, each 5th with two
// points 0.1 µs and 0.2 µs in (the Runge–Kutta branch, ωh ~ 1e-6), each 7th sample repeated (a
// zero-length step). At the record's sample times the SDOF displacement equals the uniform
// recurrence's: both exact for the same lines, so to round-off (1e-9 of the peak allows the
// ~600-step accumulation; Runge–Kutta's local error at ωh = 1e-6 is ~1e-32). Periods >= 0.75 s
// take one sub-step per step (60 h / T <= 1), so the outputs are at the steps' ends.
TEST(PostSpectra, AccelerogramAtIrregularStepsIntegratesTheSameStraightLines) {
  const auto dir = test::scratch_dir("accelerogram");
  const GroundMotion g = synthetic_record(dir, "c1", 0.4, 0.01, 6.0);
  Accelerogram a{"split", {}, {}};
  std::vector<std::size_t> at_sample;  // index in the output of each record sample
  std::size_t outputs = 0;
  const auto push = [&](double t, double v) {
    if (!a.time.empty() && t > a.time.back()) ++outputs;  // a zero-length step adds no output
    a.time.push_back(t);
    a.acceleration.push_back(v);
  };
  const std::size_t n = g.acceleration.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * g.dt, v = g.acceleration[i];
    push(t, v);
    at_sample.push_back(outputs);
    if (i % 7 == 0) push(t, v);
    if (i + 1 == n) break;
    const double slope = (g.acceleration[i + 1] - v) / g.dt;
    if (i % 5 == 0)
      for (double dt : {1e-7, 2e-7}) push(t + dt, v + slope * dt);
    if (i % 3 == 0) push(t + 0.37 * g.dt, v + slope * 0.37 * g.dt);
  }
  for (double period : {0.75, 1.5, 3.0}) {
    SCOPED_TRACE("T = " + std::to_string(period));
    const std::vector<double> uniform = sdof_displacement(g, period, {});
    const std::vector<double> irregular = sdof_displacement(a, period, {});
    ASSERT_EQ(irregular.size(), outputs + 1);
    double peak = 0.0, worst = 0.0;
    for (double u : uniform) peak = std::max(peak, std::abs(u));
    for (std::size_t i = 0; i < n; ++i)
      worst = std::max(worst, std::abs(irregular[at_sample[i]] - uniform[i]));
    EXPECT_LE(worst, 1e-9 * peak);
    std::printf(
        "[ spectra ] T %.2f s: irregular steps vs uniform, largest difference %.2e of "
        "the peak\n",
        period, worst / peak);
    // The peaks: the irregular steps sample the same motion at more points (the inserted ones),
    // so their peak is not lower, and higher by no more than the motion rises between two
    // samples 10 ms apart (about 1 − cos(π h / T) ~ 2e-4 here: 1e-3 bounds it).
    const Spectrum su = response_spectrum(g, {period}), si = response_spectrum(a, {period});
    EXPECT_GE(si.sd[0], su.sd[0] * (1 - 1e-9));  // the trajectories agree to 1e-9
    EXPECT_LE(si.sd[0], su.sd[0] * (1 + 1e-3));
  }
  std::filesystem::remove_all(dir);
}

// A long step under a constant acceleration a: the undamped SDOF u = −(a/ω²)(1 − cos ωt) peaks
// at 2a/ω² at t = T/2. One step of 1 s at T = 0.1 s is split into 60 sub-steps per period, so the
// peak is sampled where it is: SD = 2a/ω² to round-off, where the step's end alone (u(1 s) = 0)
// would give 0.
TEST(PostSpectra, AccelerogramPeakIsSampledWithinALongStep) {
  const double a = 3.0, period = 0.1, w = 2 * kPi / period;
  const Accelerogram g{"step", {0.0, 1.0}, {a, a}};
  SpectrumOptions o;
  o.damping = 0.0;
  const Spectrum s = response_spectrum(g, {0.0, period}, o);
  EXPECT_EQ(s.psa[0], a);
  EXPECT_NEAR(s.sd[1], 2 * a / (w * w), 1e-9 * 2 * a / (w * w));
  EXPECT_EQ(sdof_displacement(g, period, o).size(), 601u);  // 600 sub-steps
}

TEST(PostSpectra, StatisticsAreLogSpaceMedianAndSampleSigmaLn) {
  Spectrum a{"a", {1.0}, {1.0}, {2.0}}, b{"b", {1.0}, {4.0}, {8.0}};
  const SpectrumStatistics st = spectrum_statistics({a, b});
  EXPECT_DOUBLE_EQ(st.median_sd[0], 2.0);  // exp(mean(ln 1, ln 4))
  EXPECT_DOUBLE_EQ(st.sigma_ln_sd[0], std::log(4.0) / std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(st.median_psa[0], 4.0);
}

// `spectra --damping` is a damping ratio read like the model files' damping.ratio: '5 %', 5% and
// 0.05 (a bare number is SI) give the same CSV, byte for byte, which records the ratio in every
// row; a bare 5 (500 %) is refused with exit 2 and the hint of the plausibility table.
TEST(PostSpectra, DampingTakesAUnitAndTheCsvRecordsIt) {
  const auto dir = test::scratch_dir("spectra-damping");
  synthetic_record(dir, "rec", 0.3);
  const std::string record = (dir / "rec.txt").string() + " --unit m/s2 --dt '10 ms'";
  const std::string plain =
      test::same_text_for_every_five_percent("spectra " + record, dir, "spectra.csv");
  EXPECT_EQ(plain.substr(0, 23), "period_s,damping_ratio,");
  // Every row records the ratio; 2 % gives larger ordinates (summed over the periods).
  const auto psa_sum = [](const std::string& csv, const std::string& ratio) {
    std::istringstream in(csv);
    std::string row;
    std::getline(in, row);
    double sum = 0.0;
    while (std::getline(in, row)) {
      std::istringstream cells(row);
      std::string period, xi, psa;
      std::getline(cells, period, ',');
      std::getline(cells, xi, ',');
      std::getline(cells, psa, ',');
      EXPECT_EQ(xi, ratio) << row;
      sum += std::stod(psa);
    }
    return sum;
  };
  test::run_post("spectra " + record + " --damping '2 %' -o " + (dir / "two").string());
  EXPECT_GT(psa_sum(test::file_text(dir / "two" / "spectra.csv"), "0.02"),
            1.1 * psa_sum(plain, "0.05"));

  const auto bare =
      test::run_post("spectra " + record + " --damping 5 -o " + (dir / "never").string());
  EXPECT_EQ(bare.exit_code, 2) << bare.output;
  EXPECT_NE(bare.output.find("--damping"), std::string::npos) << bare.output;
  EXPECT_NE(bare.output.find("did you mean '5 %'?"), std::string::npos) << bare.output;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace isopound::post
