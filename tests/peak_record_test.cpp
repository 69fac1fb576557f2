// Peak recording shortcuts: PeakBands and ProbeRecorder must give exactly (bit for bit) the peaks
// of calling update_peak on every value of every probe, while skipping most of the work once
// the peaks are set.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "solver/core/peak.h"
#include "solver/core/probe_record.h"

namespace isopound {
namespace {

void expect_same(const Peak& a, const Peak& b, const std::string& what) {
  EXPECT_EQ(a.value, b.value) << what;
  EXPECT_EQ(a.time, b.time) << what;
  EXPECT_EQ(a.positive, b.positive) << what;
  EXPECT_EQ(a.time_positive, b.time_positive) << what;
  EXPECT_EQ(a.negative, b.negative) << what;
  EXPECT_EQ(a.time_negative, b.time_negative) << what;
}

// A signal that rises, then decays (most late values set no peak), with noise and one NaN.
double signal(std::mt19937& rng, int step, int k) {
  std::normal_distribution<double> noise(0.0, 1.0);
  const double envelope = step < 200 ? step / 200.0 : std::exp(-(step - 200) / 150.0);
  if (step == 333 && k == 1) return std::numeric_limits<double>::quiet_NaN();
  return (1.0 + 0.1 * k) * envelope * noise(rng);
}

TEST(PeakBands, SameAsUpdatingEveryPeak) {
  const int n = 37;  // odd: the paired test and its scalar tail
  std::vector<Peak> fast(n), direct(n);
  std::vector<Peak*> pointers;
  for (Peak& p : fast) pointers.push_back(&p);
  PeakBands bands(pointers);
  std::mt19937 rng(7);
  std::vector<double> values(n);
  for (int step = 0; step < 1000; ++step) {
    // One value changes per step, so that every raise, however small, is the only one.
    const int k_new = step % n;
    // A third of them creep outwards by 1e-6 a visit, alternately up and down: tiny raises.
    values[k_new] =
        k_new % 3 == 0 ? (step % 2 ? 1.0 : -1.0) * (1.0 + 1e-6 * step) : signal(rng, step, k_new);
    const double t = 0.01 * step;
    bands.record(values.data(), t);
    for (int k = 0; k < n; ++k) update_peak(direct[k], values[k], t);
  }
  for (int k = 0; k < n; ++k) expect_same(fast[k], direct[k], "value " + std::to_string(k));
}

// Probes as a 3D building makes them (a floor's points, a storey's columns), plus probes of
// independent coefficients over the same DOFs (full rank) and one with a repeated DOF.
std::vector<PlanProbe> probes() {
  std::vector<PlanProbe> list;
  const auto point = [&](int upper, int lower, double x, double y, bool acceleration) {
    PlanProbe p;
    p.quantity = acceleration ? PlanProbe::Quantity::kAbsoluteAcceleration
                              : PlanProbe::Quantity::kDisplacement;
    p.x_terms = {{upper, 1.0}, {upper + 2, -y}};
    p.y_terms = {{upper + 1, 1.0}, {upper + 2, x}};
    if (lower >= 0) {
      p.x_terms.insert(p.x_terms.end(), {{lower, -1.0}, {lower + 2, y}});
      p.y_terms.insert(p.y_terms.end(), {{lower + 1, -1.0}, {lower + 2, -x}});
      p.length = 3.2;
    }
    list.push_back(p);
  };
  for (const double x : {-8.25, 0.6, 8.25})
    for (const double y : {-8.25, 0.6, 8.25})
      for (const bool acceleration : {false, true}) point(0, -1, x, y, acceleration);
  for (const double x : {-8.25, -2.75, 2.75, 8.25})
    for (const double y : {-8.25, -2.75, 2.75, 8.25}) point(3, 0, x, y, false);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> c(-2.0, 2.0);
  for (int k = 0; k < 4; ++k) {
    PlanProbe p;
    p.x_terms = {{6, c(rng)}, {7, c(rng)}, {8, c(rng)}};
    p.y_terms = {{7, c(rng)}};
    list.push_back(p);
  }
  PlanProbe repeated;
  repeated.x_terms = {{6, 1.0}, {6, -0.5}, {8, 2.0}};
  repeated.y_terms = {{8, 1.0}, {6, 1.0}};
  list.push_back(repeated);
  return list;
}

// The reference: every probe evaluated and recorded at every step.
void record_every_probe(const std::vector<PlanProbe>& list, const std::vector<double>& u,
                        const std::vector<double>& a, double t, std::vector<ProbePeaks>& direct) {
  for (std::size_t p = 0; p < list.size(); ++p) {
    const PlanProbe& probe = list[p];
    const double* q =
        probe.quantity == PlanProbe::Quantity::kAbsoluteAcceleration ? a.data() : u.data();
    double x = 0.0, y = 0.0;
    for (const auto& [d, c] : probe.x_terms) x += c * q[d];
    for (const auto& [d, c] : probe.y_terms) y += c * q[d];
    const double r = std::sqrt(x * x + y * y);
    update_peak(direct[p].x, x, t);
    update_peak(direct[p].y, y, t);
    update_peak(direct[p].resultant, r, t);
    if (probe.length > 0) update_peak(direct[p].ratio, r / probe.length, t);
  }
}

void expect_same_peaks(const std::vector<ProbePeaks>& fast, const std::vector<ProbePeaks>& direct) {
  for (std::size_t p = 0; p < fast.size(); ++p) {
    const std::string what = "probe " + std::to_string(p);
    expect_same(fast[p].x, direct[p].x, what + " x");
    expect_same(fast[p].y, direct[p].y, what + " y");
    expect_same(fast[p].resultant, direct[p].resultant, what + " resultant");
    expect_same(fast[p].ratio, direct[p].ratio, what + " ratio");
  }
}

TEST(ProbeRecorder, SameAsEvaluatingEveryProbeAndSkipsMostOnceSet) {
  const std::vector<PlanProbe> list = probes();
  ProbeRecorder recorder(list);
  std::vector<ProbePeaks> fast(list.size()), direct(list.size());
  std::mt19937 rng(11);
  const int n_dofs = 9, steps = 1500;
  std::vector<double> u(n_dofs), a(n_dofs);
  for (int step = 0; step < steps; ++step) {
    for (int k = 0; k < n_dofs; ++k) {
      // The storey's DOFs 3..5 move almost with 0..2: drifts are small differences.
      u[k] = k >= 3 && k < 6 ? u[k - 3] + 0.01 * signal(rng, step, k) : signal(rng, step, k);
      a[k] = signal(rng, step, k + 9);
    }
    const double t = 0.005 * step;
    recorder.record(u.data(), a.data(), t, fast);
    record_every_probe(list, u, a, t, direct);
  }
  expect_same_peaks(fast, direct);
  // After the peak (step 200) the decaying signals raise nothing: most evaluations are skipped.
  EXPECT_LT(recorder.evaluations(), static_cast<long>(list.size()) * steps / 2);
}

// Probes swaying slowly about a permanent offset (a base after a residual drift, short steps):
// no value is ever negative, so the symmetric bound |x| <= min(x_max, -x_min) = 0 skips nothing,
// and only the change since the members' last evaluation can. The peaks stay bit for bit those
// of every probe evaluated, through slow raises (a growing sway) and a jump.
TEST(ProbeRecorder, SkipsAGroupSwayingAboutAnOffsetUntilItNearsAPeak) {
  const std::vector<PlanProbe> list = probes();
  ProbeRecorder recorder(list);
  std::vector<ProbePeaks> fast(list.size()), direct(list.size());
  const int n_dofs = 9, steps = 4000;
  std::vector<double> u(n_dofs), a(n_dofs);
  for (int step = 0; step < steps; ++step) {
    const double t = 0.001 * step;
    // Sway growing for 1 s, then decaying; one jump at step 3000.
    const double amplitude = (t < 1.0 ? 0.05 * (1.0 + t) : 0.1 * std::exp(-(t - 1.0) / 0.5)) +
                             (step == 3000 ? 0.5 : 0.0);
    for (int k = 0; k < n_dofs; ++k) {
      const double offset = k % 3 == 2 ? 0.02 : 1.0 + 0.1 * k;
      const double sway = amplitude * std::sin(2.0 * t + 0.3 * k);
      u[k] = k >= 3 && k < 6 ? u[k - 3] + 0.1 * offset + 0.01 * sway : offset + sway;
      a[k] = 2.0 * offset + 3.0 * sway;
    }
    recorder.record(u.data(), a.data(), t, fast);
    record_every_probe(list, u, a, t, direct);
  }
  expect_same_peaks(fast, direct);
  // Evaluated while the sway grows (1000 of the 4000 steps) and briefly near the jump; skipped
  // while it decays about the offset.
  EXPECT_LT(recorder.evaluations(), static_cast<long>(list.size()) * steps * 2 / 5);
}

}  // namespace
}  // namespace isopound
