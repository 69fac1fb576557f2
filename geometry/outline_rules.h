// Internal to geometry/: the tolerances every outline is checked with (ConvexPolygon,
// SimplePolygon, following moats) and the small measures they share. Plan frame W, metres.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "geometry/convex_polygon.h"

namespace isopound::detail {

// A vertex whose turn has |sin| below this (relative to its two edges) lies on the line
// through its neighbours: it deviates from that line by < 1e-9 of an edge length, far below
// anything a drawing means, yet well above the round-off (~1e-13) of coordinates near 10³ m.
inline constexpr double kCollinearSine = 1e-9;
// Two vertices closer than this fraction of the polygon's size are the same vertex.
inline constexpr double kRepeatedFraction = 1e-12;

// "vertex 3 (1, 0.5)": how messages name a vertex (index in the order given).
inline std::string describe_vertex(int i, Vec2 p) {
  std::ostringstream out;
  out.precision(12);
  out << "vertex " << i << " (" << p.x << ", " << p.y << ")";
  return out.str();
}

// Sine of the turn at q (p -> q -> r), > 0 left, relative to the two edges' lengths (|sin| below
// kCollinearSine: straight through).
inline double turn_sine(Vec2 p, Vec2 q, Vec2 r) {
  const Vec2 e_in = q - p, e_out = r - q;
  return cross(e_in, e_out) / (std::hypot(e_in.x, e_in.y) * std::hypot(e_out.x, e_out.y));
}

// Squared distance from p to the segment ab.
inline double point_segment_distance_sq(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 e = b - a;
  const double ee = dot(e, e);
  const double s = ee > 0.0 ? std::clamp(dot(p - a, e) / ee, 0.0, 1.0) : 0.0;
  const Vec2 d = p - (a + s * e);
  return dot(d, d);
}

}  // namespace isopound::detail
