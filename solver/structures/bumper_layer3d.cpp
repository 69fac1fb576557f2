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
  return {bumper_layer_outline(wall, side, s, span, t - s),
          bumper_layer_outline(wall, side, t - s, span)};
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
