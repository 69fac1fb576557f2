// Forward-mode differentiation: a value with its derivatives along N directions, carried through
// + − × ÷, sqrt, sin and cos by the chain rule. The derivatives are exact for the arithmetic done
// (no truncation error; round-off only), at the cost of N + 1 numbers per operation. Branches
// are taken on the value, so a function with switches gives the derivative of the branch it is on.
#pragma once

#include <array>
#include <cmath>

namespace isopound {

template <int N>
struct Dual {
  double v = 0.0;             // the value
  std::array<double, N> d{};  // its derivatives along the N seed directions

  static Dual constant(double x) { return Dual{x, {}}; }
};

template <int N>
Dual<N> operator+(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r{a.v + b.v, {}};
  for (int k = 0; k < N; ++k) r.d[k] = a.d[k] + b.d[k];
  return r;
}
template <int N>
Dual<N> operator-(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r{a.v - b.v, {}};
  for (int k = 0; k < N; ++k) r.d[k] = a.d[k] - b.d[k];
  return r;
}
template <int N>
Dual<N> operator-(const Dual<N>& a) {
  Dual<N> r{-a.v, {}};
  for (int k = 0; k < N; ++k) r.d[k] = -a.d[k];
  return r;
}
template <int N>
Dual<N> operator*(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r{a.v * b.v, {}};
  for (int k = 0; k < N; ++k) r.d[k] = a.d[k] * b.v + a.v * b.d[k];
  return r;
}
template <int N>
Dual<N> operator/(const Dual<N>& a, const Dual<N>& b) {
  const double inverse = 1.0 / b.v;
  Dual<N> r{a.v * inverse, {}};
  for (int k = 0; k < N; ++k) r.d[k] = (a.d[k] - r.v * b.d[k]) * inverse;
  return r;
}
template <int N>
Dual<N> operator+(const Dual<N>& a, double b) {
  Dual<N> r = a;
  r.v += b;
  return r;
}
template <int N>
Dual<N> operator+(double a, const Dual<N>& b) {
  return b + a;
}
template <int N>
Dual<N> operator-(const Dual<N>& a, double b) {
  Dual<N> r = a;
  r.v -= b;
  return r;
}
template <int N>
Dual<N> operator-(double a, const Dual<N>& b) {
  return -b + a;
}
template <int N>
Dual<N> operator*(double a, const Dual<N>& b) {
  Dual<N> r{a * b.v, {}};
  for (int k = 0; k < N; ++k) r.d[k] = a * b.d[k];
  return r;
}
template <int N>
Dual<N> operator*(const Dual<N>& a, double b) {
  return b * a;
}
template <int N>
Dual<N> sqrt(const Dual<N>& a) {
  Dual<N> r{std::sqrt(a.v), {}};
  const double slope = 0.5 / r.v;
  for (int k = 0; k < N; ++k) r.d[k] = slope * a.d[k];
  return r;
}
template <int N>
Dual<N> cos(const Dual<N>& a) {
  Dual<N> r{std::cos(a.v), {}};
  const double slope = -std::sin(a.v);
  for (int k = 0; k < N; ++k) r.d[k] = slope * a.d[k];
  return r;
}
template <int N>
Dual<N> sin(const Dual<N>& a) {
  Dual<N> r{std::sin(a.v), {}};
  const double slope = std::cos(a.v);
  for (int k = 0; k < N; ++k) r.d[k] = slope * a.d[k];
  return r;
}

// A plan vector of duals (x, y), with the products the contact geometry uses.
template <int N>
struct DualVec2 {
  Dual<N> x, y;
};
template <int N>
DualVec2<N> operator+(const DualVec2<N>& a, const DualVec2<N>& b) {
  return {a.x + b.x, a.y + b.y};
}
template <int N>
DualVec2<N> operator-(const DualVec2<N>& a, const DualVec2<N>& b) {
  return {a.x - b.x, a.y - b.y};
}
template <int N>
DualVec2<N> operator*(const Dual<N>& s, const DualVec2<N>& a) {
  return {s * a.x, s * a.y};
}
template <int N>
DualVec2<N> operator*(double s, const DualVec2<N>& a) {
  return {s * a.x, s * a.y};
}
template <int N>
Dual<N> dot(const DualVec2<N>& a, const DualVec2<N>& b) {
  return a.x * b.x + a.y * b.y;
}
template <int N>
Dual<N> cross(const DualVec2<N>& a, const DualVec2<N>& b) {
  return a.x * b.y - a.y * b.x;
}

}  // namespace isopound
