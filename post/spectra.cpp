// Response spectra by the Nigam-Jennings recurrence (see spectra.h).
#include "post/spectra.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

namespace isopound::post {
namespace {

// Chopra, Dynamics of Structures, table 5.2.1, for unit mass (k = w^2): exact step of
// u'' + 2 xi w u' + w^2 u = p(t) with p linear from p_i to p_{i+1} over dt (xi < 1).
struct Recurrence {
  double A, B, C, D, Ap, Bp, Cp, Dp;
  Recurrence(double w, double xi, double dt) {
    const double k = w * w;
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
  // One step from (u, v) under p linear from p0 to p1.
  void advance(double& u, double& v, double p0, double p1) const {
    const double un = A * u + B * v + C * p0 + D * p1;
    v = Ap * u + Bp * v + Cp * p0 + Dp * p1;
    u = un;
  }
};

// One classical Runge–Kutta step of u'' = p(τ) − 2ξω u' − ω² u with p linear from p0 to p1 over h:
// for ωh < 0.01, where the recurrence's closed form loses its digits to cancellation.
void runge_kutta_step(double w, double xi, double h, double p0, double p1, double& u, double& v) {
  const auto acc = [&](double uu, double vv, double p) {
    return p - 2.0 * xi * w * vv - w * w * uu;
  };
  const double pm = 0.5 * (p0 + p1);
  const double k1u = v, k1v = acc(u, v, p0);
  const double k2u = v + 0.5 * h * k1v, k2v = acc(u + 0.5 * h * k1u, v + 0.5 * h * k1v, pm);
  const double k3u = v + 0.5 * h * k2v, k3v = acc(u + 0.5 * h * k2u, v + 0.5 * h * k2v, pm);
  const double k4u = v + h * k3v, k4v = acc(u + h * k3u, v + h * k3v, p1);
  u += h / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
  v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
}

// Per-angle peaks of a plan point's two SDOF histories, u_θ = u_1 cos θ + u_2 sin θ at θ = 0°, 1°,
// ..., 179° (peaks sorted on return): each the largest computed |u_1[k] c_θ + u_2[k] s_θ| over
// the samples k, bit for bit, with that product evaluated only where it can be the largest.
// - A sample no longer than the smallest peak so far, |u| <= min_θ peak(θ), cannot raise any
//   (|u_θ| <= |u|): skipped (about one comparison per sample once the peaks have grown).
// - The sample k* where |u_θ| is largest (the first, if several) is a local extreme of u_θ in time:
//   a·e_θ >= 0 >= b·e_θ for a maximum (−: a minimum), a = u_k − u_{k−1}, b = u_{k+1} − u_k, up
//   to the products' rounding, δ = 3ε(|u_k| + |u_{k±1}|). Those θ (mod 180°) are the arc between
//   the normals of a and b, as wide as the orbit turns in one sample (~6° at 60 samples per
//   period), widened by 1° plus asin(δ/|a|) + asin(δ/|b|). So each sample updates only the angles
//   of its arc; the first and last sample, a turn above 90° or a step |a|, |b| < 1000 δ update all.
// The previous loop over all 180 angles for every sample above the smallest peak cost 9 of the
// demo's 15 s of floor spectra (an elongated orbit keeps the smallest peak small).
void rotd_peaks(const std::vector<double>& u1, const std::vector<double>& u2,
                std::vector<double>& peaks) {
  static const auto [c, s] = [] {
    std::array<double, 180> cs{}, sn{};
    for (int d = 0; d < 180; ++d) {
      cs[d] = std::cos(d * std::numbers::pi / 180.0);
      sn[d] = std::sin(d * std::numbers::pi / 180.0);
    }
    return std::pair{cs, sn};
  }();
  constexpr double kDegree = std::numbers::pi / 180.0;
  constexpr double kRounding = 3.0 * std::numeric_limits<double>::epsilon();
  peaks.assign(180, 0.0);
  double smallest = 0.0;
  const std::size_t n = u1.size();
  double beta = 0.0;  // the direction of u_{k+1} − u_k, computed at sample beta_of
  std::size_t beta_of = n;
  const auto update = [&](std::size_t k, int d) {
    const double p = std::abs(u1[k] * c[d] + u2[k] * s[d]);
    if (p > peaks[d]) peaks[d] = p;
  };
  for (std::size_t k = 0; k < n; ++k) {
    const double r2 = u1[k] * u1[k] + u2[k] * u2[k];
    if (r2 <= smallest * smallest) continue;
    int first = 0, count = 180;  // the angles d = first, first + 1, ... (mod 180)
    if (k > 0 && k + 1 < n) {
      const double ax = u1[k] - u1[k - 1], ay = u2[k] - u2[k - 1];
      const double bx = u1[k + 1] - u1[k], by = u2[k + 1] - u2[k];
      // |x| + |y| >= the norm: δ only larger (the arc only wider).
      const double norm1 = std::abs(u1[k]) + std::abs(u2[k]);
      const double da = kRounding * (norm1 + std::abs(u1[k - 1]) + std::abs(u2[k - 1]));
      const double db = kRounding * (norm1 + std::abs(u1[k + 1]) + std::abs(u2[k + 1]));
      const double la = std::sqrt(ax * ax + ay * ay), lb = std::sqrt(bx * bx + by * by);
      if (la > 1000.0 * da && lb > 1000.0 * db) {
        // b of sample k is a of sample k + 1: its direction is kept for the next sample.
        const double alpha = beta_of == k - 1 ? beta : std::atan2(ay, ax);
        beta = std::atan2(by, bx);
        beta_of = k;
        double turn = beta - alpha;
        if (turn > std::numbers::pi) turn -= 2.0 * std::numbers::pi;
        if (turn <= -std::numbers::pi) turn += 2.0 * std::numbers::pi;
        if (std::abs(turn) < 0.5 * std::numbers::pi) {
          // The arc from the normal of a (α − 90°) to that of b (α + turn − 90°), in degrees; the
          // asin of a ratio below 1e-3 is that ratio to 2e-7 of itself (within the 1° added).
          const double widen = 1.0 + (1.01 * (da / la + db / lb)) / kDegree;
          const double from =
              (alpha - 0.5 * std::numbers::pi) / kDegree + std::min(0.0, turn / kDegree);
          const double lo = std::floor(from - widen);
          const double hi = std::ceil(from + std::abs(turn) / kDegree + widen);
          first = static_cast<int>(lo - 180.0 * std::floor(lo / 180.0));  // in [0, 180)
          count = std::min(180, static_cast<int>(hi - lo) + 1);
        }
      }
    }
    bool min_may_grow = false;
    for (int j = 0, d = first; j < count; ++j, d = d == 179 ? 0 : d + 1) {
      min_may_grow |= peaks[d] == smallest;
      update(k, d);
    }
    if (min_may_grow) smallest = *std::min_element(peaks.begin(), peaks.end());
  }
  std::sort(peaks.begin(), peaks.end());
}

// One ordinate of a component's spectrum from its samples u at period t: sd = the peak |u|,
// psa = w² sd; T = 0 (u: the accelerations themselves): sd 0 and psa = the peak |a|.
void add_ordinate(Spectrum& s, double t, const std::vector<double>& u) {
  double peak = 0.0;
  for (double x : u) peak = std::max(peak, std::abs(x));
  s.period.push_back(t);
  if (t == 0.0) {
    s.sd.push_back(0.0);
    s.psa.push_back(peak);
    return;
  }
  const double w = 2.0 * std::numbers::pi / t;
  s.sd.push_back(peak);
  s.psa.push_back(w * w * peak);
}

// The RotD spectrum of the pair `responses` gives at each period; with `first`, `second` also
// each component's own spectrum (add_ordinate) from the same histories: one SDOF history per
// component and period where three spectra would compute each twice.
RotDSpectrum rotd_of(
    std::string name, const std::vector<double>& periods,
    const std::function<void(double, std::vector<double>&, std::vector<double>&)>& responses,
    Spectrum* first = nullptr, Spectrum* second = nullptr) {
  RotDSpectrum s;
  s.name = std::move(name);
  std::vector<double> peaks, u1, u2;
  for (double t : periods) {
    s.period.push_back(t);
    responses(t, u1, u2);  // T = 0: the accelerations themselves
    rotd_peaks(u1, u2, peaks);
    if (first) add_ordinate(*first, t, u1);
    if (second) add_ordinate(*second, t, u2);
    const double p50 = 0.5 * (peaks[89] + peaks[90]), p100 = peaks[179];
    if (t == 0.0) {
      s.sd50.push_back(0.0);
      s.sd100.push_back(0.0);
      s.psa50.push_back(p50);
      s.psa100.push_back(p100);
    } else {
      const double w2 = std::pow(2.0 * std::numbers::pi / t, 2);
      s.sd50.push_back(p50);
      s.sd100.push_back(p100);
      s.psa50.push_back(w2 * p50);
      s.psa100.push_back(w2 * p100);
    }
  }
  return s;
}

// rotd_of for two histories of the same length and step (the caller checks), each period's pair
// of SDOF displacements (T = 0: the accelerations).
template <class History>
RotDSpectrum rotd_of_pair(const History& a, const History& b, const std::vector<double>& periods,
                          const SpectrumOptions& options, Spectrum* first = nullptr,
                          Spectrum* second = nullptr) {
  return rotd_of(
      a.name + "+" + b.name, periods,
      [&](double t, std::vector<double>& u1, std::vector<double>& u2) {
        u1 = t == 0.0 ? a.acceleration : sdof_displacement(a, t, options);
        u2 = t == 0.0 ? b.acceleration : sdof_displacement(b, t, options);
      },
      first, second);
}

void check_same_step(const GroundMotion& first, const GroundMotion& second) {
  if (std::abs(first.dt - second.dt) > 1e-9 * first.dt)
    throw std::invalid_argument("RotD pair " + first.name + ", " + second.name +
                                ": the records have different time steps");
}

void check_same_times(const Accelerogram& first, const Accelerogram& second) {
  if (first.time != second.time)
    throw std::invalid_argument("RotD pair " + first.name + ", " + second.name +
                                ": the two histories are not at the same times");
}

// The period and options of one SDOF, for a record or an accelerogram.
void check(double period, const SpectrumOptions& options) {
  if (!(period > 0.0)) throw std::invalid_argument("period must be > 0");
  if (!(options.damping >= 0.0 && options.damping < 1.0))
    throw std::invalid_argument("damping ratio must be in [0, 1)");
  if (options.oversample < 1) throw std::invalid_argument("oversample must be >= 1");
}

void check(const GroundMotion& motion, double period, const SpectrumOptions& options) {
  if (!(motion.dt > 0.0) || motion.acceleration.size() < 2)
    throw std::invalid_argument("record " + motion.name + ": needs dt > 0 and 2 samples or more");
  check(period, options);
}

// SD and PSA of a GroundMotion or an Accelerogram at each period; T = 0: SD 0 and PSA = the peak
// |a| (PGA).
template <class History>
Spectrum spectrum_of(const History& history, const std::vector<double>& periods,
                     const SpectrumOptions& options) {
  Spectrum s;
  s.name = history.name;
  for (double t : periods) {
    if (t == 0.0)
      add_ordinate(s, t, history.acceleration);
    else
      add_ordinate(s, t, sdof_displacement(history, t, options));
  }
  return s;
}

}  // namespace

std::vector<double> default_periods() {
  std::vector<double> t{0.0};
  const int n = 120;
  for (int i = 0; i < n; ++i) t.push_back(0.02 * std::pow(10.0 / 0.02, i / double(n - 1)));
  return t;
}

std::vector<double> sdof_displacement(const GroundMotion& motion, double period,
                                      const SpectrumOptions& options) {
  check(motion, period, options);
  const int m = options.oversample;
  const double h = motion.dt / m;
  const double w = 2.0 * std::numbers::pi / period;
  const Recurrence r(w, options.damping, h);
  const std::size_t n = motion.acceleration.size();
  std::vector<double> u((n - 1) * m + 1, 0.0);
  double ui = 0.0, vi = 0.0;
  std::size_t k = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double a0 = motion.acceleration[i], a1 = motion.acceleration[i + 1];
    for (int j = 0; j < m; ++j) {
      // p = -a_g, linear over the sub-step (the same straight line as over the record step).
      const double p0 = -(a0 + (a1 - a0) * j / m), p1 = -(a0 + (a1 - a0) * (j + 1) / m);
      r.advance(ui, vi, p0, p1);
      u[++k] = ui;
    }
  }
  return u;
}

Spectrum response_spectrum(const GroundMotion& motion, const std::vector<double>& periods,
                           const SpectrumOptions& options) {
  return spectrum_of(motion, periods, options);
}

SpectrumStatistics spectrum_statistics(const std::vector<Spectrum>& spectra) {
  SpectrumStatistics st;
  if (spectra.empty()) return st;
  st.period = spectra.front().period;
  const std::size_t n = spectra.size();
  const auto stats = [&](auto member, std::vector<double>& median, std::vector<double>& sigma,
                         std::vector<double>& lower, std::vector<double>& upper) {
    for (std::size_t i = 0; i < st.period.size(); ++i) {
      bool positive = true;
      double sum = 0.0;
      for (const Spectrum& s : spectra) {
        positive = positive && (s.*member)[i] > 0.0;
        if (positive) sum += std::log((s.*member)[i]);
      }
      if (!positive) {  // ln 0: no log statistics (SD at T = 0, identically 0)
        median.push_back(0.0), sigma.push_back(0.0), lower.push_back(0.0), upper.push_back(0.0);
        continue;
      }
      const double mu = sum / n;
      double ss = 0.0;
      for (const Spectrum& s : spectra) ss += std::pow(std::log((s.*member)[i]) - mu, 2);
      const double sg = n > 1 ? std::sqrt(ss / (n - 1)) : 0.0;
      median.push_back(std::exp(mu));
      sigma.push_back(sg);
      lower.push_back(std::exp(mu - sg));
      upper.push_back(std::exp(mu + sg));
    }
  };
  stats(&Spectrum::psa, st.median_psa, st.sigma_ln_psa, st.lower_psa, st.upper_psa);
  stats(&Spectrum::sd, st.median_sd, st.sigma_ln_sd, st.lower_sd, st.upper_sd);
  return st;
}

RotDSpectrum rotd_spectrum(const GroundMotion& first, const GroundMotion& second,
                           const std::vector<double>& periods, const SpectrumOptions& options) {
  check_same_step(first, second);
  GroundMotion a = first, b = second;
  const std::size_t n = std::max(a.acceleration.size(), b.acceleration.size());
  a.acceleration.resize(n, 0.0);
  b.acceleration.resize(n, 0.0);
  return rotd_of_pair(a, b, periods, options);
}

std::vector<double> sdof_displacement(const Accelerogram& g, double period,
                                      const SpectrumOptions& options) {
  if (g.time.size() != g.acceleration.size() || g.time.size() < 2)
    throw std::invalid_argument(g.name + ": needs as many times as accelerations, 2 or more");
  check(period, options);
  const double w = 2.0 * std::numbers::pi / period, xi = options.damping;
  std::vector<double> u{0.0};
  u.reserve(g.time.size());
  double ui = 0.0, vi = 0.0, h_cached = -1.0;
  std::optional<Recurrence> r;
  for (std::size_t i = 0; i + 1 < g.time.size(); ++i) {
    const double h = g.time[i + 1] - g.time[i];
    if (h < 0.0) throw std::invalid_argument(g.name + ": time goes back");
    if (h == 0.0) continue;  // a jump: the next step starts from the value after it
    const double a0 = g.acceleration[i], a1 = g.acceleration[i + 1];
    const int m = std::max(options.oversample,
                           static_cast<int>(std::ceil(kSamplesPerPeriod * h / period - 1e-9)));
    const double hs = h / m;
    const bool small = w * hs < 0.01;
    if (!small && hs != h_cached) r.emplace(w, xi, hs), h_cached = hs;
    for (int j = 0; j < m; ++j) {
      const double p0 = -(a0 + (a1 - a0) * j / m), p1 = -(a0 + (a1 - a0) * (j + 1) / m);
      if (small)
        runge_kutta_step(w, xi, hs, p0, p1, ui, vi);
      else
        r->advance(ui, vi, p0, p1);
      u.push_back(ui);
    }
  }
  return u;
}

Spectrum response_spectrum(const Accelerogram& g, const std::vector<double>& periods,
                           const SpectrumOptions& options) {
  return spectrum_of(g, periods, options);
}

RotDSpectrum rotd_spectrum(const Accelerogram& first, const Accelerogram& second,
                           const std::vector<double>& periods, const SpectrumOptions& options) {
  check_same_times(first, second);
  return rotd_of_pair(first, second, periods, options);
}

PairSpectra pair_spectra(const Accelerogram& first, const Accelerogram& second,
                         const std::vector<double>& periods, const SpectrumOptions& options) {
  check_same_times(first, second);
  PairSpectra p;
  p.first.name = first.name;
  p.second.name = second.name;
  p.rotd = rotd_of_pair(first, second, periods, options, &p.first, &p.second);
  return p;
}

PairSpectra pair_spectra(const GroundMotion& first, const GroundMotion& second,
                         const std::vector<double>& periods, const SpectrumOptions& options) {
  PairSpectra p;
  if (first.acceleration.size() != second.acceleration.size()) {
    // RotD pads the shorter record with zeros, which its own spectrum does not see.
    p.first = response_spectrum(first, periods, options);
    p.second = response_spectrum(second, periods, options);
    p.rotd = rotd_spectrum(first, second, periods, options);
    return p;
  }
  check_same_step(first, second);
  p.first.name = first.name;
  p.second.name = second.name;
  p.rotd = rotd_of_pair(first, second, periods, options, &p.first, &p.second);
  return p;
}

}  // namespace isopound::post
