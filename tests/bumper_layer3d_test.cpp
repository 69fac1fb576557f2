// The rubber strip of a 3D moat wall in plan (solver/structures/bumper_layer3d.h): in front of
// the inner face of each of the four walls of the thesis building, over [from, to].
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <vector>

#include "geometry/overlap.h"
#include "solver/structures/bumper_layer3d.h"
#include "solver/structures/pounding3d.h"

namespace isopound {
namespace {

// The thesis building's 16.5 m square slab, walls at 20 cm, 1 m thick, 1 m beyond each end.
Building3DConfig walled_square() {
  Building3DConfig b;
  b.base.plan = {{0.0, 0.0}, {16.5, 0.0}, {16.5, 16.5}, {0.0, 16.5}};
  b.walls.present = {true, true, true, true};
  return b;
}

double area(const std::vector<Vec2>& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 a = p[i], b = p[(i + 1) % p.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twice;  // > 0: counter-clockwise
}

TEST(BumperLayer3D, StripLiesOnTheInnerFaceOfEveryWall) {
  const Building3DConfig b = walled_square();
  const ConvexPolygon slab{std::span<const Vec2>(b.base.plan)};
  for (int side = 0; side < 4; ++side) {
    SCOPED_TRACE(side);
    const std::vector<Vec2> wall = moat_wall_outline(b, side);
    const std::vector<Vec2> strip = bumper_layer_outline(wall, side, 0.1);
    EXPECT_NEAR(area(strip), 0.1 * 18.5, 1e-12);  // the face is 16.5 + 2 x 1 m long
    // It touches the wall without overlapping it, and stands 10 cm from the slab (gap 20 cm).
    const ConvexPolygon s(strip), w(wall);
    EXPECT_NEAR(overlap_of(s, w).area, 0.0, 1e-12);
    EXPECT_NEAR(overlap_of(s, slab).area, 0.0, 1e-12);
    // Distance between the bounding boxes (both are axis-aligned rectangles here).
    const double dx =
        std::max({s.box_min().x - slab.box_max().x, slab.box_min().x - s.box_max().x, 0.0});
    const double dy =
        std::max({s.box_min().y - slab.box_max().y, slab.box_min().y - s.box_max().y, 0.0});
    const double nearest = std::hypot(dx, dy);
    EXPECT_NEAR(nearest, 0.1, 1e-12);
  }
}

TEST(BumperLayer3D, FromAndToSelectPartOfTheFace) {
  const Building3DConfig b = walled_square();
  const std::vector<Vec2> east = moat_wall_outline(b, 0);
  const std::vector<Vec2> strip = bumper_layer_outline(east, 0, 0.05, {2.0, 5.0});
  EXPECT_NEAR(area(strip), 0.05 * 3.0, 1e-12);
  double y_min = 1e300, y_max = -1e300;
  for (const Vec2& p : strip) y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
  EXPECT_NEAR(y_min, east[0].y + 2.0, 1e-12);
  EXPECT_NEAR(y_max, east[0].y + 5.0, 1e-12);
  EXPECT_THROW(bumper_layer_outline(east, 0, 0.05, {5.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(bumper_layer_outline(east, 0, 0.05, {-1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(bumper_layer_outline(east, 0, 0.05, {0.0, 30.0}), std::invalid_argument);
  EXPECT_THROW(bumper_layer_outline(east, 0, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace isopound
