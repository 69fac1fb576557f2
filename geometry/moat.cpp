// Following moat: per straight run of the outline (corners as SimplePolygon's partition sees
// them), offsets g and g + t outward; convex corners extended by e along the run, re-entrant
// ones cut where the neighbouring walls' faces meet (2 x 2 solves of the two offset lines).
#include "geometry/moat.h"

#include <cmath>
#include <sstream>
#include <string>

#include "geometry/outline_rules.h"

namespace isopound {
namespace {

using detail::kCollinearSine;

Vec2 unit(Vec2 v) {
  const double l = std::hypot(v.x, v.y);
  return {v.x / l, v.y / l};
}

// The point X with dot(X - p, n1) = a and dot(X - p, n2) = a (two offset lines of one corner).
Vec2 offset_corner(Vec2 p, Vec2 n1, Vec2 n2, double a) {
  const double det = n1.x * n2.y - n1.y * n2.x;
  return {p.x + a * (n2.y - n1.y) / det, p.y + a * (n1.x - n2.x) / det};
}

}  // namespace

std::vector<MoatWall> following_moat(const SimplePolygon& plan, double gap, double thickness,
                                     double extension) {
  const int n = plan.size();
  std::vector<Vec2> corner;  // the outline without its straight-through vertices
  for (int i = 0; i < n; ++i) {
    const Vec2 e_in = plan[i] - plan[(i + n - 1) % n], e_out = plan[(i + 1) % n] - plan[i];
    const double sine =
        cross(e_in, e_out) / (std::hypot(e_in.x, e_in.y) * std::hypot(e_out.x, e_out.y));
    if (std::abs(sine) > kCollinearSine) corner.push_back(plan[i]);
  }
  const int m = int(corner.size());
  const auto direction = [&](int k) { return unit(corner[(k + 1) % m] - corner[k]); };
  const auto outward = [&](int k) {
    const Vec2 d = direction(k);
    return Vec2{d.y, -d.x};  // right of a counter-clockwise run
  };
  const auto convex_at = [&](int k) {
    return cross(direction((k + m - 1) % m), direction(k)) > 0.0;
  };
  std::vector<MoatWall> out;
  for (int k = 0; k < m; ++k) {
    const Vec2 s = corner[k], e = corner[(k + 1) % m];
    const Vec2 d = direction(k), nk = outward(k);
    Vec2 inner_s, inner_e, outer_s, outer_e;
    if (convex_at(k)) {
      inner_s = s + gap * nk - extension * d;
      outer_s = inner_s + thickness * nk;
    } else {
      inner_s = offset_corner(s, outward((k + m - 1) % m), nk, gap);
      outer_s = offset_corner(s, outward((k + m - 1) % m), nk, gap + thickness);
    }
    if (convex_at((k + 1) % m)) {
      inner_e = e + gap * nk + extension * d;
      outer_e = inner_e + thickness * nk;
    } else {
      inner_e = offset_corner(e, nk, outward((k + 1) % m), gap);
      outer_e = offset_corner(e, nk, outward((k + 1) % m), gap + thickness);
    }
    const Vec2 quad[] = {outer_s, outer_e, inner_e, inner_s};
    try {
      if (!(dot(inner_e - inner_s, d) > 0.0) || !(dot(outer_e - outer_s, d) > 0.0))
        throw InvalidPolygon(-1, "its faces would run backwards");
      out.push_back({ConvexPolygon(std::span<const Vec2>(quad)), s, e});
    } catch (const InvalidPolygon& error) {
      std::ostringstream where;
      where.precision(12);
      where << "the wall along the edge from (" << s.x << ", " << s.y << ") to (" << e.x << ", "
            << e.y << ") at gap " << gap << " m and thickness " << thickness
            << " m: the edge is too short for its re-entrant corners (" << error.what() << ")";
      throw InvalidPolygon(-1, where.str());
    }
  }
  return out;
}

}  // namespace isopound
