// The rubber layer of a 3D moat wall in plan (issue 27, first 3D step; plan in
// BUMPERS-STATUS.md): a strip `thickness` deep in front of the wall's inner face, over [from, to].
#pragma once

#include <limits>
#include <vector>

#include "geometry/convex_polygon.h"

namespace isopound {

// Where the rubber sits along the face: metres from the face's start (its lower x for the
// north and south walls, its lower y for the east and west walls); `to` = +inf: to the end.
struct BumperSpan {
  double from = 0.0;
  double to = std::numeric_limits<double>::infinity();
};

// The strip's outline (counter-clockwise rectangle, building frame like the wall's) in front of
// the inner face of `wall`, the outline moat_wall_outline() gives for `side`
// (MoatWalls3DConfig::Side: 0 east, 1 west, 2 north, 3 south). The inner face is the one towards
// the slab; the strip occupies [face − thickness, face] on the slab's side. Throws
// std::invalid_argument for thickness <= 0, from < 0, to > the face's length or from >= to.
std::vector<Vec2> bumper_layer_outline(const std::vector<Vec2>& wall, int side, double thickness,
                                       BumperSpan span = {});

}  // namespace isopound
