// Tests of ConvexPolygon: validation messages, clockwise fix, rigid placement, area properties.
// Expected numbers are derived by hand in each test (closed forms for rectangles and triangles).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/convex_polygon.h"

namespace isopound {
namespace {

// The vertex index and message an invalid polygon gives.
struct Rejection {
  int vertex = -2;
  std::string message;
};

Rejection rejection_of(const std::vector<Vec2>& vertices) {
  try {
    ConvexPolygon polygon{std::span<const Vec2>(vertices)};
  } catch (const InvalidPolygon& e) {
    return {e.vertex(), e.what()};
  }
  return {};
}

TEST(GeometryPolygon, KeepsCounterClockwiseInputAsGiven) {
  const ConvexPolygon square{{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  ASSERT_EQ(square.size(), 4);
  EXPECT_FALSE(square.was_reversed());
  EXPECT_EQ(square[1].x, 2.0);
  EXPECT_EQ(square[1].y, 0.0);
  EXPECT_EQ(square.box_min().x, 0.0);
  EXPECT_EQ(square.box_max().x, 2.0);
  EXPECT_EQ(square.box_max().y, 1.0);
}

TEST(GeometryPolygon, ReversesClockwiseInput) {
  const ConvexPolygon square{{0, 0}, {0, 1}, {2, 1}, {2, 0}};
  EXPECT_TRUE(square.was_reversed());
  // Reversed order: (2,0), (2,1), (0,1), (0,0) — counter-clockwise.
  EXPECT_EQ(square[0].x, 2.0);
  EXPECT_EQ(square[0].y, 0.0);
  EXPECT_EQ(square[1].y, 1.0);
  EXPECT_NEAR(area_properties(square).area, 2.0, 1e-15);
}

TEST(GeometryPolygon, RejectsTooFewVertices) {
  const Rejection r = rejection_of({{0, 0}, {1, 0}});
  EXPECT_EQ(r.vertex, -1);
  EXPECT_NE(r.message.find("at least 3 vertices, got 2"), std::string::npos) << r.message;
}

TEST(GeometryPolygon, RejectsTooManyVertices) {
  std::vector<Vec2> circle;
  for (int i = 0; i < kMaxPolygonVertices + 1; ++i) {
    const double a = 2.0 * std::numbers::pi * i / (kMaxPolygonVertices + 1);
    circle.push_back({std::cos(a), std::sin(a)});
  }
  const Rejection r = rejection_of(circle);
  EXPECT_EQ(r.vertex, -1);
  EXPECT_NE(r.message.find("at most"), std::string::npos) << r.message;
}

TEST(GeometryPolygon, RejectsNonFiniteCoordinate) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Rejection r = rejection_of({{0, 0}, {1, 0}, {nan, 1}});
  EXPECT_EQ(r.vertex, 2);
  EXPECT_NE(r.message.find("vertex 2"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("not a finite number"), std::string::npos) << r.message;
  r = rejection_of({{0, 0}, {1, inf}, {0, 1}});
  EXPECT_EQ(r.vertex, 1);
}

TEST(GeometryPolygon, RejectsRepeatedVertex) {
  const Rejection r = rejection_of({{0, 0}, {1, 0}, {1, 1}, {1, 0}, {0, 1}});
  EXPECT_EQ(r.vertex, 3);
  EXPECT_NE(r.message.find("vertex 3 (1, 0): repeats vertex 1"), std::string::npos) << r.message;
}

TEST(GeometryPolygon, RejectsAllCollinear) {
  const Rejection r = rejection_of({{0, 0}, {1, 1}, {3, 3}});
  EXPECT_EQ(r.vertex, -1);
  EXPECT_NE(r.message.find("zero area"), std::string::npos) << r.message;
}

TEST(GeometryPolygon, RejectsVertexOnNeighboursLine) {
  // (1, 0) lies on the bottom edge from (0, 0) to (2, 0).
  const Rejection r = rejection_of({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}});
  EXPECT_EQ(r.vertex, 1);
  EXPECT_NE(r.message.find("straight line through its neighbours"), std::string::npos) << r.message;
}

TEST(GeometryPolygon, RejectsNonConvexNamingTheReflexVertex) {
  // An arrowhead: vertex 3 at (1, 0.5) points inwards.
  Rejection r = rejection_of({{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}});
  EXPECT_EQ(r.vertex, 3);
  EXPECT_NE(r.message.find("not convex"), std::string::npos) << r.message;
  // The same outline clockwise: the same vertex (index in the input order) is named.
  r = rejection_of({{0, 2}, {1, 0.5}, {2, 2}, {2, 0}, {0, 0}});
  EXPECT_EQ(r.vertex, 1);
  EXPECT_NE(r.message.find("not convex"), std::string::npos) << r.message;
}

TEST(GeometryPolygon, RejectsStarShapes) {
  // A pentagram: every turn is left (144°), but the outline goes round twice.
  std::vector<Vec2> star;
  for (int i = 0; i < 5; ++i) {
    const double a = 2.0 * std::numbers::pi * (2 * i) / 5.0;
    star.push_back({std::cos(a), std::sin(a)});
  }
  const Rejection r = rejection_of(star);
  // Cumulative turn 144° per vertex exceeds 360° at the third vertex visited (index 2).
  EXPECT_EQ(r.vertex, 2);
  EXPECT_NE(r.message.find("crosses itself"), std::string::npos) << r.message;
}

TEST(GeometryPolygon, RectangleAreaProperties) {
  // b × h rectangle with corner at (10, 20): A = bh, C = corner + (b/2, h/2), J_c = bh(b²+h²)/12.
  const double b = 3.0, h = 2.0;
  const ConvexPolygon rect{{10, 20}, {10 + b, 20}, {10 + b, 20 + h}, {10, 20 + h}};
  const AreaProperties p = area_properties(rect);
  EXPECT_NEAR(p.area, b * h, 1e-13);
  EXPECT_NEAR(p.p_WC.x, 10 + b / 2, 1e-13);
  EXPECT_NEAR(p.p_WC.y, 20 + h / 2, 1e-13);
  EXPECT_NEAR(p.polar_moment_c, b * h * (b * b + h * h) / 12.0, 1e-12);
  EXPECT_NEAR(p.radius_of_gyration_sq(), (b * b + h * h) / 12.0, 1e-13);
}

TEST(GeometryPolygon, RightTriangleAreaProperties) {
  // Legs a (x) and c (y) at the origin: A = ac/2, C = (a/3, c/3),
  // I_x,c = a c³/36, I_y,c = c a³/36, so J_c = ac(a² + c²)/36.
  const double a = 4.0, c = 3.0;
  const ConvexPolygon tri{{0, 0}, {a, 0}, {0, c}};
  const AreaProperties p = area_properties(tri);
  EXPECT_NEAR(p.area, a * c / 2, 1e-14);
  EXPECT_NEAR(p.p_WC.x, a / 3, 1e-14);
  EXPECT_NEAR(p.p_WC.y, c / 3, 1e-14);
  EXPECT_NEAR(p.polar_moment_c, a * c * (a * a + c * c) / 36.0, 1e-13);
}

TEST(GeometryPolygon, AreaPropertiesFarFromOriginKeepPrecision) {
  // A 1 m square at 10⁶ m: the vertex-mean shift keeps J_c = 1/6 to ~1e-9 (not lost to 10¹²).
  const double x0 = 1e6, y0 = -2e6;
  const ConvexPolygon sq{{x0, y0}, {x0 + 1, y0}, {x0 + 1, y0 + 1}, {x0, y0 + 1}};
  const AreaProperties p = area_properties(sq);
  EXPECT_NEAR(p.area, 1.0, 1e-9);
  EXPECT_NEAR(p.polar_moment_c, 1.0 / 6.0, 1e-9);
  EXPECT_NEAR(p.p_WC.x, x0 + 0.5, 1e-9);
}

TEST(GeometryPolygon, PlacementRotatesAboutTheGivenPoint) {
  const ConvexPolygon sq{{1, 0}, {2, 0}, {2, 1}, {1, 1}};
  // Quarter turn about (1, 0), then shift by (10, 5): (2, 0) -> (1, 1) -> (11, 6).
  const ConvexPolygon moved = sq.placed({10.0, 5.0, std::numbers::pi / 2}, {1.0, 0.0});
  EXPECT_NEAR(moved[0].x, 11.0, 1e-15);
  EXPECT_NEAR(moved[0].y, 5.0, 1e-15);
  EXPECT_NEAR(moved[1].x, 11.0, 1e-15);
  EXPECT_NEAR(moved[1].y, 6.0, 1e-15);
  EXPECT_NEAR(moved[2].x, 10.0, 1e-15);
  EXPECT_NEAR(moved[2].y, 6.0, 1e-15);
  EXPECT_NEAR(moved.box_min().x, 10.0, 1e-15);
  EXPECT_NEAR(moved.box_max().y, 6.0, 1e-15);
  // A rigid motion keeps area and J_c; the centroid moves as a point: (1.5, 0.5) -> (10.5, 5.5).
  const AreaProperties before = area_properties(sq), after = area_properties(moved);
  EXPECT_NEAR(after.area, before.area, 1e-14);
  EXPECT_NEAR(after.polar_moment_c, before.polar_moment_c, 1e-14);
  EXPECT_NEAR(after.p_WC.x, 10.5, 1e-14);
  EXPECT_NEAR(after.p_WC.y, 5.5, 1e-14);
}

TEST(GeometryPolygon, PlacementAboutOriginByDefault) {
  const ConvexPolygon sq{{1, 0}, {2, 0}, {2, 1}, {1, 1}};
  const double t = 0.3;
  const ConvexPolygon moved = sq.placed({0.0, 0.0, t});
  EXPECT_NEAR(moved[1].x, 2 * std::cos(t), 1e-15);
  EXPECT_NEAR(moved[1].y, 2 * std::sin(t), 1e-15);
}

// The overload with cos θ and sin θ given (a contact keeps them per body): the same vertices and
// box, bit for bit; other values place by them (a caller's stale pair would show).
TEST(GeometryPolygon, PlacementWithGivenCosAndSinIsBitIdentical) {
  const ConvexPolygon sq{{1, 0}, {2, 0.5}, {1.5, 1.25}, {0.75, 1}};
  for (const double t : {0.0, -0.0, 1e-12, -3e-5, 0.3, 2.9}) {
    const Placement2 x{0.125, -7.3, t};
    const Vec2 about{8.25, -3.1};
    const ConvexPolygon a = sq.placed(x, about);
    const ConvexPolygon b = sq.placed(x, about, std::cos(t), std::sin(t));
    for (int i = 0; i < sq.size(); ++i) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(a[i].x), std::bit_cast<std::uint64_t>(b[i].x));
      EXPECT_EQ(std::bit_cast<std::uint64_t>(a[i].y), std::bit_cast<std::uint64_t>(b[i].y));
    }
    EXPECT_EQ(a.box_min().x, b.box_min().x);
    EXPECT_EQ(a.box_max().y, b.box_max().y);
  }
  const ConvexPolygon quarter = sq.placed({0.0, 0.0, 0.3}, {0.0, 0.0}, 0.0, 1.0);
  EXPECT_NEAR(quarter[0].x, 0.0, 1e-15);  // (1, 0) turned by the given 90°, not by 0.3 rad
  EXPECT_NEAR(quarter[0].y, 1.0, 1e-15);
}

}  // namespace
}  // namespace isopound
