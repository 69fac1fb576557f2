// Witness function of a contact over one step: cubic Hermite interpolation of the penetration,
// its monotone pieces and the first crossing of zero against the contact status.
#include "solver/elements/witness.h"

#include <algorithm>
#include <cmath>

namespace isopound {

namespace {

// p(theta) = a theta^3 + b theta^2 + c theta + d for the Hermite data (slopes h r0, h r1).
struct Cubic {
  double a, b, c, d;
  double operator()(double t) const { return ((a * t + b) * t + c) * t + d; }
  double slope(double t) const { return (3 * a * t + 2 * b) * t + c; }
};

Cubic cubic_of(const WitnessStep& w) {
  const double s0 = w.h * w.r0, s1 = w.h * w.r1;
  return {2 * w.d0 + s0 - 2 * w.d1 + s1, -3 * w.d0 - 2 * s0 + 3 * w.d1 - s1, s0, w.d0};
}

// Roots of p' in (0, 1), ascending; returns how many (0 to 2).
int slope_roots(const Cubic& p, double roots[2]) {
  const double A = 3 * p.a, B = 2 * p.b, C = p.c;
  const double scale = std::abs(A) + std::abs(B) + std::abs(C);
  int n = 0;
  double r[2];
  if (scale == 0.0) return 0;
  if (std::abs(A) <= 1e-14 * scale) {
    if (B != 0.0) r[n++] = -C / B;
  } else {
    const double disc = B * B - 4 * A * C;
    if (disc >= 0) {
      // Stable form: q = -(B + sgn(B) sqrt(disc)) / 2, roots q / A and C / q.
      const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
      r[n++] = q / A;
      if (q != 0.0) r[n++] = C / q;
    }
  }
  int kept = 0;
  for (int i = 0; i < n; ++i)
    if (r[i] > 0.0 && r[i] < 1.0) roots[kept++] = r[i];
  if (kept == 2 && roots[0] > roots[1]) std::swap(roots[0], roots[1]);
  return kept;
}

// Root of sign * p in [lo, hi], where sign * p(lo) <= 0 < sign * p(hi) and p is monotone:
// Newton safeguarded by bisection.
double root_in(const Cubic& p, double sign, double lo, double hi) {
  double t = lo;
  const double q_lo = sign * p(lo), q_hi = sign * p(hi);
  if (q_hi != q_lo) t = lo + (hi - lo) * (-q_lo) / (q_hi - q_lo);  // linear first guess
  for (int it = 0; it < 60; ++it) {
    const double q = sign * p(t);
    if (q > 0)
      hi = t;
    else
      lo = t;
    const double dq = sign * p.slope(t);
    double next = dq != 0.0 ? t - q / dq : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - t) <= 1e-15 || hi - lo <= 1e-15) return next;
    t = next;
  }
  return t;
}

}  // namespace

double witness_value(const WitnessStep& w, double theta) {
  return cubic_of(w)(theta);
}

double witness_rate(const WitnessStep& w, double theta) {
  return w.h > 0 ? cubic_of(w).slope(theta) / w.h : w.r0;
}

double first_status_change(const WitnessStep& w, bool closed, double tolerance) {
  const double sign = closed ? -1.0 : 1.0;  // q = sign p > 0 is the side of a status change
  // Quick exit (most steps): the Hermite basis gives p between the end values, give or take
  // h (|r0| + |r1|) 4/27 (the largest |theta (1 - theta)^2|); if even that stays on the status'
  // side, nothing happens.
  const double bulge = (4.0 / 27.0) * w.h * (std::abs(w.r0) + std::abs(w.r1));
  if (std::max(sign * w.d0, sign * w.d1) + bulge <= tolerance) return 1.0;
  const Cubic p = cubic_of(w);
  double breaks[4] = {0.0, 1.0, 1.0, 1.0};
  const int n_roots = slope_roots(p, breaks + 1);
  breaks[n_roots + 1] = 1.0;
  bool armed = sign * w.d0 <= tolerance;  // on the status' side of 0 at the start
  for (int k = 0; k <= n_roots; ++k) {
    const double ta = breaks[k], tb = breaks[k + 1];
    const double qa = k == 0 ? sign * w.d0 : sign * p(ta);
    const double qb = k == n_roots ? sign * w.d1 : sign * p(tb);
    if (armed) {
      if (qb > tolerance) return qa > 0 ? ta : root_in(p, sign, ta, tb);
    } else if (qb > qa) {
      return ta;  // on the wrong side and moving further into it: the status changes now
    } else if (qb <= tolerance) {
      armed = true;  // back on the status' side
    }
  }
  return 1.0;
}

}  // namespace isopound
