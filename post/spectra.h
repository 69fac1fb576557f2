// Elastic response spectra of ground motions: SDOF u'' + 2 xi w u' + w^2 u = -a_g(t) solved exactly
// for piecewise-linear a_g (Nigam-Jennings recurrence); SD = max|u|, PSA = w^2 SD; RotD50/RotD100.
#pragma once

#include <string>
#include <vector>

#include "solver/excitation/ground_motion.h"

namespace isopound::post {

struct SpectrumOptions {
  double damping = 0.05;  // critical damping ratio xi
  // The peak is taken at the record samples, each record step split into `oversample` equal
  // sub-steps (the piecewise-linear record is unchanged, so the recurrence stays exact; more
  // sub-steps only sample the continuous peak more finely). 1 = the usual convention.
  int oversample = 1;
};

// Default periods: 0 (PGA) and 120 log-spaced periods from 0.02 s to 10 s.
std::vector<double> default_periods();

struct Spectrum {
  std::string name;
  std::vector<double> period;  // s (0 = zero period: SD 0, PSA = PGA)
  std::vector<double> sd;      // m
  std::vector<double> psa;     // m/s^2
};

// The displacement history u(t_k) of the SDOF (period T > 0) from rest at every (sub)sample
// t_k = k dt / oversample. Exact for the piecewise-linear record.
std::vector<double> sdof_displacement(const GroundMotion& motion, double period,
                                      const SpectrumOptions& options);

Spectrum response_spectrum(const GroundMotion& motion, const std::vector<double>& periods,
                           const SpectrumOptions& options = {});

// An acceleration history at the times it was computed, joined by straight lines: a run's
// analysis steps (step-accelerations.csv), of any length. Times ascending; a repeated time is a
// jump (the value before, then the value after).
struct Accelerogram {
  std::string name;
  std::vector<double> time;          // s
  std::vector<double> acceleration;  // m/s^2
};

// The SDOF from rest over an accelerogram, exact for its straight lines: each step h is split
// into max(oversample, ceil(kSamplesPerPeriod h / T)) equal sub-steps, so that the peak is
// sampled at least kSamplesPerPeriod times per period (its error below 1 − cos(π/60) = 0.14 %).
// Steps with ωh < 0.01 (impacts cut steps to microseconds) take one classical Runge–Kutta step
// instead of the recurrence, whose closed form cancels there (local error (ωh)^5/120 < 1e-12).
// u at t_0 and at the end of every sub-step.
inline constexpr double kSamplesPerPeriod = 60.0;
std::vector<double> sdof_displacement(const Accelerogram& history, double period,
                                      const SpectrumOptions& options);
Spectrum response_spectrum(const Accelerogram& history, const std::vector<double>& periods,
                           const SpectrumOptions& options = {});

// Statistics of a set of spectra (same periods) in log space, per period, since spectral ordinates
// are about lognormal and a band must stay positive: median = exp(mean of ln x), sigma_ln = the
// sample standard deviation of ln x, and the band median exp(-/+ sigma_ln) = exp(mean ln -/+
// sigma_ln). A period where an ordinate is 0 (SD at T = 0) has median 0, sigma_ln 0 and band 0.
// One spectrum: sigma_ln 0.
struct SpectrumStatistics {
  std::vector<double> period;
  std::vector<double> median_psa, sigma_ln_psa, lower_psa, upper_psa;  // m/s^2 (sigma_ln: -)
  std::vector<double> median_sd, sigma_ln_sd, lower_sd, upper_sd;      // m
};
SpectrumStatistics spectrum_statistics(const std::vector<Spectrum>& spectra);

// Orientation-independent spectra of a horizontal pair (Boore 2010): the two components rotated
// by theta = 0, 1, ..., 179 deg, u_theta(t) = u_1(t) cos(theta) + u_2(t) sin(theta) (exact for a
// linear SDOF); RotD100 = max over theta of max_t |u_theta|, RotD50 = the median over theta
// (mean of the 90th and 91st sorted values). The shorter record is padded with zeros. The two
// records must have the same time step (std::invalid_argument otherwise).
struct RotDSpectrum {
  std::string name;
  std::vector<double> period;
  std::vector<double> sd50, sd100;    // m
  std::vector<double> psa50, psa100;  // m/s^2
};
RotDSpectrum rotd_spectrum(const GroundMotion& first, const GroundMotion& second,
                           const std::vector<double>& periods, const SpectrumOptions& options = {});
// The same for two accelerograms at the same times (a plan point's x and y; std::invalid_argument
// otherwise).
RotDSpectrum rotd_spectrum(const Accelerogram& first, const Accelerogram& second,
                           const std::vector<double>& periods, const SpectrumOptions& options = {});

// Each component's spectrum and the pair's RotD, equal bit for bit to response_spectrum of each
// and rotd_spectrum, from one SDOF history per component and period (half the work of the three).
// Records of different lengths: the three computed apart (RotD pads the shorter one with zeros).
struct PairSpectra {
  Spectrum first, second;
  RotDSpectrum rotd;
};
PairSpectra pair_spectra(const GroundMotion& first, const GroundMotion& second,
                         const std::vector<double>& periods, const SpectrumOptions& options = {});
PairSpectra pair_spectra(const Accelerogram& first, const Accelerogram& second,
                         const std::vector<double>& periods, const SpectrumOptions& options = {});

}  // namespace isopound::post
