// Peak-oriented IMK law: a monotonic increment is an elastic (K_u) unloading to the zero-force
// crossing (where an excursion ends and deterioration is applied), then the loading branch
// f = min(elastic, reloading line, backbone) of the side being loaded, integrated exactly.
#include "solver/materials/peak_oriented.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace isopound {

namespace {

constexpr double kMinUnloadingStiffnessRatio = 0.01;  // K_u >= 1 % of k

struct Line {
  double slope = 0.0, intercept = 0.0;
  double at(double x) const { return slope * x + intercept; }
};

// Value and slope of a piecewise-linear function composed of min/max of lines.
struct Piece {
  double value, slope;
};
Piece piece(const Line& l, double x) {
  return {l.at(x), l.slope};
}
Piece min_of(Piece a, Piece b) {
  if (a.value < b.value) return a;
  if (b.value < a.value) return b;
  return a.slope < b.slope ? a : b;  // equal: the one that stays lower to the right
}
Piece max_of(Piece a, Piece b) {
  if (a.value > b.value) return a;
  if (b.value > a.value) return b;
  return a.slope > b.slope ? a : b;
}

}  // namespace

PeakOrientedMaterial::PeakOrientedMaterial(const PeakOrientedParameters& p) : p_(p) {
  if (!(p.elastic_stiffness > 0) || !(p.yield_deformation > 0) ||
      !(p.post_yield_ratio >= 0 && p.post_yield_ratio < 1) ||
      !(p.capping_deformation > p.yield_deformation) || !(p.post_capping_ratio > 0) ||
      !(p.residual_strength_ratio >= 0 && p.residual_strength_ratio <= 1) ||
      !(p.deterioration >= 0))
    throw std::invalid_argument(
        "peak-oriented: need k > 0, d_y > 0, 0 <= alpha < 1, d_c > d_y, post-capping ratio > 0, "
        "0 <= residual ratio <= 1 and lambda >= 0");
  const double k = p.elastic_stiffness;
  yield_force_ = k * p.yield_deformation;
  residual_force_ = p.residual_strength_ratio * yield_force_;
  capping_slope_ = p.post_capping_ratio * k;
  reference_energy_ = p.deterioration * yield_force_ * p.yield_deformation;
  const double hardening = p.post_yield_ratio * k;
  const double capping_force =
      yield_force_ + hardening * (p.capping_deformation - p.yield_deformation);
  State s;
  s.tangent = k;
  s.unloading_stiffness = k;
  for (Side& side : s.side)
    side = {yield_force_, hardening, capping_force + capping_slope_ * p.capping_deformation,
            p.yield_deformation, 0.0};
  trial_ = committed_ = s;
}

double PeakOrientedMaterial::backbone(int side, double x) const {
  const Side& s = trial_.side[side > 0 ? 0 : 1];
  const double yield_x = s.yield_force / p_.elastic_stiffness;
  const double hardening = s.yield_force + s.hardening * std::max(x - yield_x, 0.0);
  return std::max(residual_force_, std::min(hardening, s.capping_ref - capping_slope_ * x));
}

double PeakOrientedMaterial::stored_energy() const {
  return 0.5 * trial_.force * trial_.force / trial_.unloading_stiffness;
}

void PeakOrientedMaterial::deteriorate(State& s, int side, double excursion_energy) const {
  if (reference_energy_ <= 0.0) return;
  const double remaining = reference_energy_ - s.energy_at_crossing;
  double beta = 1.0;
  if (remaining > 0.0) beta = std::clamp(excursion_energy / remaining, 0.0, 1.0);
  if (beta == 0.0) return;
  Side& d = s.side[side];
  d.yield_force *= 1.0 - beta;
  d.hardening *= 1.0 - beta;
  d.capping_ref *= 1.0 - beta;
  d.target *= 1.0 + beta;
  s.unloading_stiffness = std::max((1.0 - beta) * s.unloading_stiffness,
                                   kMinUnloadingStiffnessRatio * p_.elastic_stiffness);
}

double PeakOrientedMaterial::load(const State& s, int side, double x_c, double f_c, double x,
                                  double& integral, double& slope) const {
  const Side& sd = s.side[side];
  const double k = p_.elastic_stiffness;
  const double ku = s.unloading_stiffness;
  const double sign = side == 0 ? 1.0 : -1.0;
  // The lines: elastic, reloading, yield plateau, hardening, post-capping, residual.
  const Line elastic{ku, f_c - ku * x_c};
  const double yield_x = sd.yield_force / k;
  const Line plateau{0.0, sd.yield_force};
  const Line hardening{sd.hardening, sd.yield_force - sd.hardening * yield_x};
  const Line capping{-capping_slope_, sd.capping_ref};
  const Line residual{0.0, residual_force_};
  const double x0 = sign * sd.zero_point;
  const double xt = sd.target;
  const auto backbone_at = [&](double at) {
    return max_of(piece(residual, at),
                  min_of(max_of(piece(plateau, at), piece(hardening, at)), piece(capping, at)));
  };
  const double ft = backbone_at(xt).value;
  const bool has_reload = xt - x0 > 1e-12 * p_.yield_deformation;
  Line reload;
  if (has_reload) reload = {ft / (xt - x0), -ft / (xt - x0) * x0};
  const auto f = [&](double at) {
    Piece r = min_of(piece(elastic, at), backbone_at(at));
    if (has_reload) r = min_of(r, piece(reload, at));
    return r;
  };
  // Fast path: the elastic line still below the bound at x. The bound minus the elastic line
  // has slope K_s - K_u, -K_c - K_u, -K_u or K_rel - K_u on its pieces, all <= 0 when the
  // reloading slope K_rel <= K_u: then it stayed below on all of [x_c, x] (one linear piece).
  const Piece end = f(x);
  if (end.slope == ku && end.value == elastic.at(x) && (!has_reload || reload.slope <= ku)) {
    integral = 0.5 * (f_c + end.value) * (x - x_c);
    slope = ku;
    return end.value;
  }
  // Breakpoints: every pairwise intersection of the lines inside (x_c, x).
  const std::array<Line, 6> lines{elastic, reload, plateau, hardening, capping, residual};
  std::array<double, 17> points;
  int count = 0;
  points[count++] = x_c;
  for (int a = 0; a < 6; ++a) {
    if (a == 1 && !has_reload) continue;
    for (int b = a + 1; b < 6; ++b) {
      if (b == 1 && !has_reload) continue;
      const double ds = lines[a].slope - lines[b].slope;
      if (ds == 0.0) continue;
      const double at = (lines[b].intercept - lines[a].intercept) / ds;
      if (at > x_c && at < x) points[count++] = at;
    }
  }
  points[count++] = x;
  std::sort(points.begin() + 1, points.begin() + count - 1);
  integral = 0.0;
  double f_prev = f(x_c).value;
  for (int i = 1; i < count; ++i) {
    const double f_here = f(points[i]).value;
    integral += 0.5 * (f_prev + f_here) * (points[i] - points[i - 1]);
    f_prev = f_here;
  }
  slope = end.slope;
  return end.value;
}

void PeakOrientedMaterial::set_trial(double d) {
  State s = committed_;
  if (d == s.d) {
    trial_ = s;
    return;
  }
  const double dir = d > s.d ? 1.0 : -1.0;
  const int side = dir > 0 ? 0 : 1;
  const double x = dir * d;
  double x_c = dir * s.d;
  double f_c = dir * s.force;
  if (f_c < 0.0) {
    // Unloading from the other side towards zero force.
    const double x_zero = x_c - f_c / s.unloading_stiffness;
    if (x < x_zero) {
      const double f = f_c + s.unloading_stiffness * (x - x_c);
      s.work += 0.5 * (f_c + f) * (x - x_c);
      s.d = d;
      s.force = dir * f;
      s.tangent = s.unloading_stiffness;
      trial_ = s;
      return;
    }
    // The excursion ends at the zero-force crossing: deteriorate, reload from there.
    s.work += 0.5 * f_c * (x_zero - x_c);
    const double excursion = s.work - s.energy_at_crossing;
    s.energy_at_crossing = s.work;
    deteriorate(s, side, excursion);
    s.side[side].zero_point = dir * x_zero;
    x_c = x_zero;
    f_c = 0.0;
  }
  double integral = 0.0, slope = 0.0;
  const double f = load(s, side, x_c, f_c, x, integral, slope);
  s.work += integral;
  s.d = d;
  s.force = dir * f;
  s.tangent = slope;
  if (x > s.side[side].target && f < f_c + s.unloading_stiffness * (x - x_c))
    s.side[side].target = x;  // a new peak on this side: the next reloading aims at it
  trial_ = s;
}

}  // namespace isopound
