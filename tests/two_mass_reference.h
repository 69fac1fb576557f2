// Independent reference for tests: the free collision of two masses through one impact law.
// Re-implements the ten laws of THEORY section 4 from the equations (no library code) and
// integrates them with adaptive Dormand-Prince 5(4) and exactly located switch/separation events.
//
// Set-up and sign conventions (as in solver/impact_law.h): m1 moves at v0 > 0 towards m2, at
// rest; they touch at t = 0. delta = x1 - x2 > 0 is the penetration, rate = v1 - v2 > 0 while
// approaching, F > 0 pushes them apart: m1 x1'' = -F, m2 x2'' = +F (m2 = +inf: a fixed wall).
// The integration starts at delta = 0 with rate v0 (onset exact) and runs in two phases:
//   approach     until rate = 0 (located by bisection: max penetration, branch switch of the
//                laws 5, 6, 8, which are evaluated with the branch of the phase, not sign(rate));
//   restitution  until delta = 0, or for a no-tension law until F = 0 (permanent indentation
//                = delta there); after that the masses fly apart freely.
// A fifth state W = integral of F rate dt is the energy the contact takes from the relative
// motion (for a full collision, all of it is dissipated).
//
// Usage:
//   TwoMassResult r = reference_collision("jankowski", 0.7, 340e3, 500e3, 1.0, 2.5e9, 2.5e9);
//   r.restitution  // apparent e = separation speed / approach speed
// or with any force function double(double delta, double rate, bool approach):
//   integrate_two_mass(force, /*tension_allowed=*/true, m1, m2, v0);
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace isopound::test {

struct TwoMassResult {
  double restitution = 0.0;              // e_app = (v2 - v1) / v0 after separation
  double contact_duration = 0.0;         // s, from delta = 0 to separation
  double max_penetration = 0.0;          // m, at the end of the approach (rate = 0)
  double time_of_max_penetration = 0.0;  // s
  double max_force = 0.0;                // N, over the contact
  double time_of_max_force = 0.0;        // s
  double min_force = 0.0;                // N, over the contact; < 0: tension occurred
  double final_velocity_1 = 0.0;         // m/s, m1 after separation
  double final_velocity_2 = 0.0;         // m/s, m2 after separation (0 for a fixed wall)
  double permanent_indentation = 0.0;    // m, delta at separation (no-tension law; else 0)
  double dissipated_energy = 0.0;        // J, integral of F rate dt over the contact
  int steps = 0;                         // accepted Runge-Kutta steps
};

struct ReferenceOptions {
  double rtol = 1e-12;       // relative tolerance of each state component per step
  double time_scale = 1e-3;  // s; absolute tolerance of positions = rtol v0 time_scale
  int max_steps = 2'000'000;
};

// Stereomechanical velocities after impact (eq. 3.1-3.2); m2 = +inf for a fixed wall.
struct StereomechanicalResult {
  double v1;
  double v2;
};
inline StereomechanicalResult stereomechanical(double m1, double m2, double v1b, double v2b,
                                               double e) {
  if (std::isinf(m2)) return {v1b - (1.0 + e) * (v1b - v2b), v2b};
  return {v1b - (1.0 + e) * m2 * (v1b - v2b) / (m1 + m2),
          v2b + (1.0 + e) * m1 * (v1b - v2b) / (m1 + m2)};
}

// ---------------------------------------------------------------------------------------------
// The ten laws, written from THEORY section 4 (std::pow throughout, damping recomputed from
// its definition at each call: slow and plain on purpose).
// ---------------------------------------------------------------------------------------------
struct ReferenceLaw {
  std::string name;
  double k = 0.0, k_h = 0.0, n = 1.5;  // N/m, N/m^n
  double e = 1.0;                      // coefficient of restitution
  double m_eff = 0.0;                  // kg
  double v_imp = 0.0;                  // m/s
  bool xi_eq_3_11 = false;             // Mahmoud-Jankowski: eq. 3.11 instead of 3.12

  bool tension_allowed() const { return name != "modified_kelvin_voigt"; }

  // F(delta, rate) for delta >= 0 (0 for delta < 0); approach selects the branch of laws 5, 6, 8.
  double operator()(double delta, double rate, bool approach) const {
    if (delta < 0.0) return 0.0;
    const double pi = std::numbers::pi;
    if (name == "linear") return k * delta;
    if (name == "kelvin_voigt" || name == "modified_kelvin_voigt") {
      const double xi = -std::log(e) / std::sqrt(pi * pi + std::log(e) * std::log(e));
      const double c = 2.0 * xi * std::sqrt(k * m_eff);
      return k * delta + c * rate;
    }
    if (name == "ye") {
      const double xi_hat = 1.5 * k * (1.0 - e) / (e * v_imp);
      return k * delta + xi_hat * delta * rate;
    }
    if (name == "mahmoud_jankowski") {
      const double xi =
          xi_eq_3_11 ? (1.0 - e * e) / (pi * e) : (1.0 - e * e) / (e * (e * (pi - 2.0) + 2.0));
      const double c = 2.0 * xi * std::sqrt(k * m_eff);
      return approach ? k * delta + c * rate : k * delta;
    }
    if (name == "pant_wijeyewickrema") {
      const double xi_hat = 1.5 * k * (1.0 - e * e) / (e * e * v_imp);
      return approach ? k * delta + xi_hat * delta * rate : k * delta;
    }
    if (name == "hertz") return k_h * std::pow(delta, n);
    if (name == "jankowski") {
      const double xi_h =
          (9.0 * std::sqrt(5.0) / 2.0) * (1.0 - e * e) / (e * (e * (9.0 * pi - 16.0) + 16.0));
      const double c_h = 2.0 * xi_h * std::sqrt(k_h * std::sqrt(delta) * m_eff);
      return approach ? k_h * std::pow(delta, 1.5) + c_h * rate : k_h * std::pow(delta, 1.5);
    }
    if (name == "hertz_damp_muthukumar") {
      const double xi_h = 0.75 * k_h * (1.0 - e * e) / v_imp;
      return k_h * std::pow(delta, n) + xi_h * std::pow(delta, n) * rate;
    }
    if (name == "hertz_damp_ye") {
      const double xi_h = 1.6 * k_h * (1.0 - e) / (e * v_imp);
      return k_h * std::pow(delta, n) + xi_h * std::pow(delta, n) * rate;
    }
    throw std::invalid_argument("ReferenceLaw: unknown law '" + name + "'");
  }
};

inline double reference_effective_mass(double m1, double m2) {
  return std::isinf(m2) ? m1 : m1 * m2 / (m1 + m2);
}

inline ReferenceLaw make_reference_law(const std::string& law, double e, double m_eff, double v_imp,
                                       double k, double k_h, double n = 1.5,
                                       const std::string& xi_formula = "eq_3_12") {
  ReferenceLaw r;
  r.name = law;
  r.e = e;
  r.m_eff = m_eff;
  r.v_imp = v_imp;
  r.k = k;
  r.k_h = k_h;
  r.n = n;
  r.xi_eq_3_11 = xi_formula == "eq_3_11";
  (void)r(0.0, 0.0, true);  // throws for an unknown name
  return r;
}

// ---------------------------------------------------------------------------------------------
// The integrator.
// ---------------------------------------------------------------------------------------------
namespace two_mass_detail {

using State = std::array<double, 5>;  // x1, v1, x2, v2, W

template <class Force>
struct System {
  const Force& force;
  double inv_m1, inv_m2;  // inv_m2 = 0 for a fixed wall

  double force_at(const State& y, bool approach) const {
    return force(y[0] - y[2], y[1] - y[3], approach);
  }
  State rhs(const State& y, bool approach) const {
    const double f = force_at(y, approach);
    return {y[1], -f * inv_m1, y[3], f * inv_m2, f * (y[1] - y[3])};
  }
};

struct Step {
  State y;
  double error;  // weighted max norm; accept if <= 1
};

// One Dormand-Prince 5(4) step of size h from y (5th-order solution, embedded 4th-order error).
template <class Sys>
Step dormand_prince(const Sys& sys, const State& y, double h, bool approach, const State& atol,
                    double rtol) {
  constexpr double a21 = 1.0 / 5;
  constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                   a54 = -212.0 / 729;
  constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                   a65 = -5103.0 / 18656;
  constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                   b6 = 11.0 / 84;
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                   e6 = 22.0 / 525, e7 = -1.0 / 40;
  auto combine = [&](std::initializer_list<std::pair<double, const State*>> terms) {
    State out = y;
    for (const auto& [c, k] : terms)
      for (std::size_t i = 0; i < out.size(); ++i) out[i] += h * c * (*k)[i];
    return out;
  };
  const State k1 = sys.rhs(y, approach);
  const State k2 = sys.rhs(combine({{a21, &k1}}), approach);
  const State k3 = sys.rhs(combine({{a31, &k1}, {a32, &k2}}), approach);
  const State k4 = sys.rhs(combine({{a41, &k1}, {a42, &k2}, {a43, &k3}}), approach);
  const State k5 = sys.rhs(combine({{a51, &k1}, {a52, &k2}, {a53, &k3}, {a54, &k4}}), approach);
  const State k6 =
      sys.rhs(combine({{a61, &k1}, {a62, &k2}, {a63, &k3}, {a64, &k4}, {a65, &k5}}), approach);
  const State y5 = combine({{b1, &k1}, {b3, &k3}, {b4, &k4}, {b5, &k5}, {b6, &k6}});
  const State k7 = sys.rhs(y5, approach);
  double error = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double err =
        h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
    const double scale = atol[i] + rtol * std::max(std::abs(y[i]), std::abs(y5[i]));
    error = std::max(error, std::abs(err) / scale);
  }
  return {y5, error};
}

struct Segment {
  double t0;
  State y0;
  double h;
  bool approach;
};

}  // namespace two_mass_detail

// Free collision through any force function double(double delta, double rate, bool approach)
// (F for delta >= 0; it must return <= 0 for delta < 0 when tension_allowed is false).
template <class Force>
TwoMassResult integrate_two_mass(const Force& force, bool tension_allowed, double m1, double m2,
                                 double v0, const ReferenceOptions& options = {}) {
  using namespace two_mass_detail;
  if (!(m1 > 0.0 && std::isfinite(m1)) || !(m2 > 0.0) || !(v0 > 0.0))
    throw std::invalid_argument("integrate_two_mass: need m1 > 0 finite, m2 > 0, v0 > 0");
  const System<Force> sys{force, 1.0 / m1, std::isinf(m2) ? 0.0 : 1.0 / m2};
  const double m_eff = reference_effective_mass(m1, m2);
  const double rtol = options.rtol;
  const State atol{rtol * v0 * options.time_scale, rtol * v0, rtol * v0 * options.time_scale,
                   rtol * v0, rtol * 0.5 * m_eff * v0 * v0};

  std::vector<Segment> segments;
  State y{0.0, v0, 0.0, 0.0, 0.0};
  double t = 0.0;
  double h = 1e-6 * options.time_scale;
  int steps = 0;

  // Integrates until event(y) <= 0, locating the event by bisection on the step size.
  auto run_phase = [&](bool approach, auto event) {
    for (;;) {
      if (++steps > options.max_steps)
        throw std::runtime_error("integrate_two_mass: too many steps (no separation?)");
      const Step s = dormand_prince(sys, y, h, approach, atol, rtol);
      const double factor =
          s.error > 0.0 ? std::clamp(0.9 * std::pow(s.error, -0.2), 0.2, 5.0) : 5.0;
      if (s.error > 1.0) {
        h *= factor;
        continue;
      }
      if (event(s.y) > 0.0) {
        if (!approach && s.y[1] - s.y[3] > 0.0)
          throw std::runtime_error("integrate_two_mass: re-approach before separation");
        segments.push_back({t, y, h, approach});
        y = s.y;
        t += h;
        h *= factor;
        continue;
      }
      double lo = 0.0, hi = h;
      for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        if (event(dormand_prince(sys, y, mid, approach, atol, rtol).y) > 0.0)
          lo = mid;
        else
          hi = mid;
      }
      segments.push_back({t, y, hi, approach});
      y = dormand_prince(sys, y, hi, approach, atol, rtol).y;
      t += hi;
      return;
    }
  };

  TwoMassResult r;
  run_phase(true, [](const State& s) { return s[1] - s[3]; });
  r.max_penetration = y[0] - y[2];
  r.time_of_max_penetration = t;
  if (tension_allowed)
    run_phase(false, [](const State& s) { return s[0] - s[2]; });
  else
    run_phase(false,
              [&](const State& s) { return s[0] - s[2] > 0.0 ? sys.force_at(s, false) : -1.0; });

  r.contact_duration = t;
  r.final_velocity_1 = y[1];
  r.final_velocity_2 = y[3];
  r.restitution = (y[3] - y[1]) / v0;
  r.permanent_indentation = tension_allowed ? 0.0 : std::max(y[0] - y[2], 0.0);
  r.dissipated_energy = y[4];
  r.steps = steps;

  // Extreme forces: the best segment start (or the end), refined by golden section over the
  // segments on either side of it.
  auto extreme = [&](double sign, double& value, double& time) {
    value = sign * -std::numeric_limits<double>::infinity();
    std::size_t best = 0;
    for (std::size_t i = 0; i <= segments.size(); ++i) {
      const double f = i < segments.size() ? sys.force_at(segments[i].y0, segments[i].approach)
                                           : sys.force_at(y, segments.back().approach);
      if (sign * f > sign * value) {
        value = f;
        time = i < segments.size() ? segments[i].t0 : t;
        best = i;
      }
    }
    for (std::size_t i : {best - 1, best}) {
      if (i >= segments.size()) continue;  // also catches best - 1 for best = 0
      const Segment& seg = segments[i];
      auto phi = [&](double s) {
        return sign * sys.force_at(dormand_prince(sys, seg.y0, s, seg.approach, atol, rtol).y,
                                   seg.approach);
      };
      const double g = 0.5 * (std::sqrt(5.0) - 1.0);
      double a = 0.0, b = seg.h;
      double c = b - g * (b - a), d = a + g * (b - a);
      double fc = phi(c), fd = phi(d);
      for (int it = 0; it < 80; ++it) {
        if (fc > fd) {
          b = d, d = c, fd = fc;
          c = b - g * (b - a), fc = phi(c);
        } else {
          a = c, c = d, fc = fd;
          d = a + g * (b - a), fd = phi(d);
        }
      }
      const double s = 0.5 * (a + b);
      const double f = phi(s);
      if (f > sign * value) {
        value = sign * f;
        time = seg.t0 + s;
      }
    }
  };
  double t_min = 0.0;
  extreme(1.0, r.max_force, r.time_of_max_force);
  extreme(-1.0, r.min_force, t_min);
  return r;
}

// Free collision of m1 at v0 onto m2 at rest through one of the ten laws by name (THEORY
// section 4), v_imp = v0, m_eff = m1 m2 / (m1 + m2) (m2 = +inf: a fixed wall, m_eff = m1).
inline TwoMassResult reference_collision(const std::string& law, double e, double m1, double m2,
                                         double v0, double k, double k_h, double n = 1.5,
                                         const std::string& xi_formula = "eq_3_12",
                                         const ReferenceOptions& options = {}) {
  const ReferenceLaw f =
      make_reference_law(law, e, reference_effective_mass(m1, m2), v0, k, k_h, n, xi_formula);
  return integrate_two_mass(f, f.tension_allowed(), m1, m2, v0, options);
}

}  // namespace isopound::test
