// Rubber strip in front of a moat wall's inner face (bumper_layer3d.h).
#include "solver/structures/bumper_layer3d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace isopound {

std::vector<Vec2> bumper_layer_outline(const std::vector<Vec2>& wall, int side, double thickness,
                                       BumperSpan span, double setback) {
  if (wall.size() != 4 || side < 0 || side > 3)
    throw std::invalid_argument("bumper layer: a moat wall is a rectangle on side 0-3");
  if (!(thickness > 0)) throw std::invalid_argument("bumper layer: thickness must be > 0");
  double x0 = wall[0].x, x1 = wall[0].x, y0 = wall[0].y, y1 = wall[0].y;
  for (const Vec2& p : wall) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const bool along_y = side <= 1;  // east and west walls run along y
  const double start = along_y ? y0 : x0, length = along_y ? y1 - y0 : x1 - x0;
  const double to = std::isinf(span.to) ? length : span.to;
  if (!(span.from >= 0 && to <= length * (1 + 1e-12) && span.from < to))
    throw std::invalid_argument(
        "bumper layer: from = " + std::to_string(span.from) + " m, to = " + std::to_string(to) +
        " m must satisfy 0 <= from < to <= the face length " + std::to_string(length) + " m");
  const double a = start + span.from, b = start + std::min(to, length);
  // The inner face: east x0, west x1, north y0, south y1; the strip lies on the slab's side.
  x0 -= setback, x1 += setback, y0 -= setback, y1 += setback;
  switch (side) {
    case 0:
      return {{x0 - thickness, a}, {x0, a}, {x0, b}, {x0 - thickness, b}};
    case 1:
      return {{x1, a}, {x1 + thickness, a}, {x1 + thickness, b}, {x1, b}};
    case 2:
      return {{a, y0 - thickness}, {b, y0 - thickness}, {b, y0}, {a, y0}};
    default:
      return {{a, y1}, {b, y1}, {b, y1 + thickness}, {a, y1 + thickness}};
  }
}

BumperStrips bumper_strips(const std::vector<Vec2>& wall, int side, const Bumper3DConfig& bumper) {
  const double t = bumper.thickness, s = bumper.max_strain * t;
  const BumperSpan span{bumper.from, bumper.to};
  static constexpr Vec2 kInto[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};  // into the east wall, ...
  return {bumper_layer_outline(wall, side, s, span, t - s),
          bumper_layer_outline(wall, side, t - s, span), kInto[side]};
}

namespace {

// A strip over [from, to] along the face from `start` (direction d), between `setback` and
// `setback + thickness` in front of it (against n), counter-clockwise.
std::vector<Vec2> face_strip(Vec2 start, Vec2 d, Vec2 n, double from, double to, double thickness,
                             double setback) {
  const Vec2 a = start + from * d, b = start + to * d;
  const Vec2 near = -setback * n, far = -(setback + thickness) * n;
  std::vector<Vec2> strip = {a + far, b + far, b + near, a + near};
  if (cross(strip[1] - strip[0], strip[2] - strip[1]) < 0) std::swap(strip[1], strip[3]);
  return strip;
}

}  // namespace

BumperStrips face_bumper_strips(const std::vector<Vec2>& wall, Vec2 n,
                                const Bumper3DConfig& bumper) {
  if (!(bumper.thickness > 0)) throw std::invalid_argument("bumper layer: thickness must be > 0");
  // The inner face: the two corners of least n·x (a wall is a quadrilateral with that face).
  std::vector<Vec2> corners = wall;
  std::sort(corners.begin(), corners.end(), [&](Vec2 p, Vec2 q) { return dot(n, p) < dot(n, q); });
  Vec2 start = corners[0], end = corners[1];
  if (starts_face_before(end, start)) std::swap(start, end);
  const double length = std::hypot(end.x - start.x, end.y - start.y);
  const double to = std::isinf(bumper.to) ? length : bumper.to;
  if (!(bumper.from >= 0 && to <= length * (1 + 1e-12) && bumper.from < to))
    throw std::invalid_argument(
        "bumper layer: from = " + std::to_string(bumper.from) + " m, to = " + std::to_string(to) +
        " m must satisfy 0 <= from < to <= the face length " + std::to_string(length) + " m");
  const Vec2 d = (1.0 / length) * (end - start);
  // The face line through the corners' mean (both lie on it to round-off).
  const Vec2 on_face = 0.5 * (start + end);
  const Vec2 face_start = on_face + dot(start - on_face, d) * d;
  const double t = bumper.thickness, s = bumper.max_strain * t, b = std::min(to, length);
  return {face_strip(face_start, d, n, bumper.from, b, s, t - s),
          face_strip(face_start, d, n, bumper.from, b, t - s, 0.0), n};
}

BumperStrips slab_bumper_strips(const std::vector<Vec2>& plan, int side,
                                const Bumper3DConfig& bumper) {
  if (plan.size() < 3 || side < 0 || side > 3)
    throw std::invalid_argument("slab bumper: a slab is a polygon, sides 0-3");
  Vec2 lo = plan[0], hi = plan[0];
  for (const Vec2& p : plan)
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)},
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  const bool along_y = side <= 1;
  const double line = side == 0 ? hi.x : side == 1 ? lo.x : side == 2 ? hi.y : lo.y;
  const double tol = 1e-9 * std::max(hi.x - lo.x, hi.y - lo.y);
  // The extent of the vertices on the bounding box's side: an edge when it has length.
  double a = std::numeric_limits<double>::infinity(), b = -a;
  for (const Vec2& p : plan)
    if (std::abs((along_y ? p.x : p.y) - line) <= tol) {
      a = std::min(a, along_y ? p.y : p.x);
      b = std::max(b, along_y ? p.y : p.x);
    }
  if (!(b - a > tol))
    throw std::invalid_argument(std::string("the slab has no straight edge on its ") +
                                MoatWalls3DConfig::kSideNames[side] +
                                " side (only a corner) for the rubber");
  // The face as the inner face of a wall on the opposite side, standing inside the slab: its
  // strips then lie outside the slab, the rubber outermost.
  static constexpr int kOpposite[4] = {1, 0, 3, 2};
  const double depth = b - a;
  std::vector<Vec2> wall;
  switch (side) {
    case 0:
      wall = {{line - depth, a}, {line, a}, {line, b}, {line - depth, b}};
      break;
    case 1:
      wall = {{line, a}, {line + depth, a}, {line + depth, b}, {line, b}};
      break;
    case 2:
      wall = {{a, line - depth}, {b, line - depth}, {b, line}, {a, line}};
      break;
    default:
      wall = {{a, line}, {b, line}, {b, line + depth}, {a, line + depth}};
      break;
  }
  return bumper_strips(wall, kOpposite[side], bumper);
}

std::shared_ptr<const ImpactLaw> bumper_rubber_law(const Bumper3DConfig& bumper, double k_normal) {
  BumperConfig b;
  b.thickness = bumper.thickness;
  b.law = bumper.law;
  b.k = bumper.modulus * bumper.height / std::pow(bumper.thickness, b.law == "hertz" ? 1.5 : 1.0);
  b.e = bumper.e;
  b.max_strain = bumper.max_strain;
  return make_bumper_law(b, bumper_bottomed_law(k_normal)->clone());
}

std::shared_ptr<const ImpactLaw> bumper_bottomed_law(double k_normal) {
  ImpactLawConfig concrete;
  concrete.law = "linear";
  concrete.k = k_normal;
  return make_impact_law(concrete);
}

}  // namespace isopound
