// Following moat: per straight run of the outline (corners as SimplePolygon's partition sees
// them), offsets g and g + t outward; convex corners extended by e along the run, re-entrant
// ones cut where the neighbouring walls' faces meet (2 x 2 solves of the two offset lines).
#include "geometry/moat.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "geometry/outline_rules.h"

namespace isopound {
namespace {

using detail::kCollinearSine;
using detail::turn_sine;

Vec2 unit(Vec2 v) {
  const double l = std::hypot(v.x, v.y);
  return {v.x / l, v.y / l};
}

// The point X with dot(X - p, n1) = a1 and dot(X - p, n2) = a2 (two offset lines of one corner).
Vec2 offset_corner(Vec2 p, Vec2 n1, Vec2 n2, double a1, double a2) {
  const double det = n1.x * n2.y - n1.y * n2.x;
  if (a1 == a2) return {p.x + a1 * (n2.y - n1.y) / det, p.y + a1 * (n1.x - n2.x) / det};
  return {p.x + (a1 * n2.y - a2 * n1.y) / det, p.y + (a2 * n1.x - a1 * n2.x) / det};
}

// The outline without its straight-through vertices.
std::vector<Vec2> corners_of(const SimplePolygon& plan) {
  const int n = plan.size();
  std::vector<Vec2> corner;
  for (int i = 0; i < n; ++i)
    if (std::abs(turn_sine(plan[(i + n - 1) % n], plan[i], plan[(i + 1) % n])) > kCollinearSine)
      corner.push_back(plan[i]);
  return corner;
}

}  // namespace

std::vector<std::pair<Vec2, Vec2>> outline_runs(const SimplePolygon& plan) {
  const std::vector<Vec2> corner = corners_of(plan);
  std::vector<std::pair<Vec2, Vec2>> runs;
  for (std::size_t k = 0; k < corner.size(); ++k)
    runs.emplace_back(corner[k], corner[(k + 1) % corner.size()]);
  return runs;
}

std::vector<MoatWall> following_moat(const SimplePolygon& plan, double gap, double thickness,
                                     double extension) {
  return following_moat(plan, std::vector<double>(corners_of(plan).size(), gap), thickness,
                        extension);
}

std::vector<MoatWall> following_moat(const SimplePolygon& plan, const std::vector<double>& gaps,
                                     double thickness, double extension) {
  return following_moat(plan, gaps, std::vector<double>(gaps.size(), thickness), extension);
}

std::vector<MoatWall> following_moat(const SimplePolygon& plan, const std::vector<double>& gaps,
                                     const std::vector<double>& thicknesses, double extension) {
  const std::vector<Vec2> corner = corners_of(plan);
  const int m = int(corner.size());
  if (gaps.size() != corner.size() || thicknesses.size() != corner.size())
    throw std::invalid_argument("following_moat: one gap and thickness per run of the outline");
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
    const double gap = gaps[k], gap_before = gaps[(k + m - 1) % m], gap_after = gaps[(k + 1) % m];
    const double thickness = thicknesses[k], thickness_before = thicknesses[(k + m - 1) % m],
                 thickness_after = thicknesses[(k + 1) % m];
    Vec2 inner_s, inner_e, outer_s, outer_e;
    if (convex_at(k)) {
      inner_s = s + gap * nk - extension * d;
      outer_s = inner_s + thickness * nk;
    } else {
      inner_s = offset_corner(s, outward((k + m - 1) % m), nk, gap_before, gap);
      outer_s = offset_corner(s, outward((k + m - 1) % m), nk, gap_before + thickness_before,
                              gap + thickness);
    }
    if (convex_at((k + 1) % m)) {
      inner_e = e + gap * nk + extension * d;
      outer_e = inner_e + thickness * nk;
    } else {
      inner_e = offset_corner(e, nk, outward((k + 1) % m), gap, gap_after);
      outer_e =
          offset_corner(e, nk, outward((k + 1) % m), gap + thickness, gap_after + thickness_after);
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

namespace {

// The points of `line` that start or end a run (index into `line`, kept for messages): its ends,
// and the interior points where the line turns.
std::vector<int> polyline_corners(std::span<const Vec2> line) {
  std::vector<int> at;
  const int n = static_cast<int>(line.size());
  double size = 0.0;
  for (int i = 1; i < n; ++i)
    size = std::max(size, std::hypot(line[i].x - line[0].x, line[i].y - line[0].y));
  for (int i = 0; i < n; ++i) {
    if (!at.empty()) {
      const Vec2 e = line[i] - line[at.back()];
      if (std::hypot(e.x, e.y) <= detail::kRepeatedFraction * size)
        throw InvalidPolygon(i, detail::describe_vertex(i, line[i]) + " repeats the one before it");
    }
    if (at.size() >= 2) {
      const Vec2 p = line[at[at.size() - 2]], q = line[at.back()], r = line[i];
      if (std::abs(turn_sine(p, q, r)) <= kCollinearSine) {
        if (dot(q - p, r - q) < 0.0)
          throw InvalidPolygon(at.back(), detail::describe_vertex(at.back(), line[at.back()]) +
                                              ": the line turns back along itself");
        at.back() = i;  // straight through: one run
        continue;
      }
    }
    at.push_back(i);
  }
  if (at.size() < 2) throw InvalidPolygon(-1, "a polyline needs two distinct points");
  return at;
}

}  // namespace

std::vector<std::pair<Vec2, Vec2>> polyline_runs(std::span<const Vec2> line) {
  const std::vector<int> at = polyline_corners(line);
  std::vector<std::pair<Vec2, Vec2>> runs;
  for (std::size_t k = 0; k + 1 < at.size(); ++k) runs.emplace_back(line[at[k]], line[at[k + 1]]);
  return runs;
}

bool lies_left_of(std::span<const Vec2> polygon, std::span<const Vec2> line) {
  double nearest = std::numeric_limits<double>::infinity(), side = 0.0;
  for (std::size_t k = 0; k + 1 < line.size(); ++k)
    for (const Vec2& p : polygon)
      if (const double d = detail::point_segment_distance_sq(p, line[k], line[k + 1]); d < nearest)
        nearest = d, side = cross(line[k + 1] - line[k], p - line[k]);
  return side >= 0.0;
}

std::vector<MoatWall> polyline_walls(std::span<const Vec2> line, double thickness,
                                     bool walls_left) {
  return polyline_walls(line, std::vector<double>(polyline_runs(line).size(), thickness),
                        walls_left);
}

std::vector<MoatWall> polyline_walls(std::span<const Vec2> line,
                                     const std::vector<double>& thicknesses, bool walls_left) {
  const std::vector<int> at = polyline_corners(line);
  const int m = static_cast<int>(at.size()) - 1;  // runs
  if (thicknesses.size() != static_cast<std::size_t>(m))
    throw std::invalid_argument("polyline_walls: one thickness per run of the line");
  const auto direction = [&](int k) { return unit(line[at[k + 1]] - line[at[k]]); };
  const double side = walls_left ? -1.0 : 1.0;
  const auto right = [&](int k) {  // into the wall
    const Vec2 d = direction(k);
    return Vec2{side * d.y, -side * d.x};
  };
  // The back's corner at vertex at[k]: square at the ends, else where the two backs cross.
  const auto back = [&](int k) {
    const Vec2 p = line[at[k]];
    if (k == 0) return p + thicknesses[0] * right(0);
    if (k == m) return p + thicknesses[m - 1] * right(m - 1);
    return offset_corner(p, right(k - 1), right(k), thicknesses[k - 1], thicknesses[k]);
  };
  std::vector<MoatWall> out;
  for (int k = 0; k < m; ++k) {
    const Vec2 s = line[at[k]], e = line[at[k + 1]];
    const Vec2 bs = back(k), be = back(k + 1);
    const Vec2 quad[] = {s, bs, be, e};  // counter-clockwise for walls on the right
    try {
      if (!(dot(be - bs, direction(k)) > 0.0))
        throw InvalidPolygon(-1, "its back would run backwards");
      // The run as MoatWall gives it: the wall to its right.
      out.push_back(
          {ConvexPolygon(std::span<const Vec2>(quad)), walls_left ? e : s, walls_left ? s : e});
    } catch (const InvalidPolygon& error) {
      std::ostringstream where;
      where.precision(12);
      where << "the wall from " << detail::describe_vertex(at[k], s) << " to "
            << detail::describe_vertex(at[k + 1], e) << " is too short for its mitres at thickness "
            << thicknesses[k] << " m (" << error.what() << ")";
      throw InvalidPolygon(at[k], where.str());
    }
  }
  return out;
}

WallExtent wall_extent(std::span<const Vec2> wall, Vec2 n) {
  const Vec2 t{-n.y, n.x};
  WallExtent e{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
               std::numeric_limits<double>::infinity()};
  for (const Vec2& p : wall) {
    e.lo = std::min(e.lo, dot(t, p));
    e.hi = std::max(e.hi, dot(t, p));
    e.face = std::min(e.face, dot(n, p));
  }
  return e;
}

NormalClearance normal_clearance(std::span<const Vec2> slab, std::span<const Vec2> wall, Vec2 n) {
  const Vec2 t{-n.y, n.x};
  const auto [lo, hi, face] = wall_extent(wall, n);
  double reach = -std::numeric_limits<double>::infinity();
  Vec2 at;
  const auto consider = [&](Vec2 p) {
    if (dot(n, p) > reach) reach = dot(n, p), at = p;
  };
  for (std::size_t i = 0; i < slab.size(); ++i) {
    const Vec2 p = slab[i], q = slab[(i + 1) % slab.size()];
    const double tp = dot(t, p), tq = dot(t, q);
    if (tp >= lo && tp <= hi) consider(p);
    for (const double bound : {lo, hi})
      if ((tp - bound) * (tq - bound) < 0) consider(p + ((bound - tp) / (tq - tp)) * (q - p));
  }
  if (!std::isfinite(reach)) return {std::numeric_limits<double>::infinity(), {}};
  return {face - reach, at};
}

}  // namespace isopound
