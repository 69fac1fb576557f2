// Plans of any simple outline (geometry/simple_polygon.h) and their overlap (plan_overlap.h):
// validation, the convex partition, the component rule at diagonals and re-entrant corners, and
// random non-convex pairs against CGAL's exact Boolean intersection (an algorithm that knows
// nothing of pieces). ISOPOUND_GEOMETRY_PAIRS sets the number of random pairs (default 10⁴).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

#include "geometry/moat.h"
#include "geometry/plan_overlap.h"
#include "geometry/simple_polygon.h"

namespace isopound {
namespace {

double total_area(const PlanOverlap& o) {
  double a = 0.0;
  for (int k = 0; k < o.count; ++k) a += o.components[k].area;
  return a;
}

// An L: 10 x 8 with the 4 x 4 corner at (6..10, 4..8) cut away.
const std::vector<Vec2> kL = {{0, 0}, {10, 0}, {10, 4}, {6, 4}, {6, 8}, {0, 8}};
// A U opening upward: 12 x 6, the notch (4..8, 2..6).
const std::vector<Vec2> kU = {{0, 0}, {12, 0}, {12, 6}, {8, 6}, {8, 2}, {4, 2}, {4, 6}, {0, 6}};

TEST(SimplePolygon, PartitionsIntoConvexPiecesWhoseAreasSumToTheOutlines) {
  for (const auto& outline : {kL, kU}) {
    const SimplePolygon p{std::span<const Vec2>(outline)};
    EXPECT_FALSE(p.convex());
    double pieces = 0.0;
    for (const ConvexPolygon& q : p.pieces()) pieces += area_properties(q).area;
    EXPECT_NEAR(pieces, area_properties(p).area, 1e-12 * area_properties(p).area);
    EXPECT_EQ(p.diagonals().size() + 1, p.pieces().size());
  }
  EXPECT_EQ(SimplePolygon{std::span<const Vec2>(kL)}.pieces().size(), 2u);  // one reflex vertex
  EXPECT_LE(SimplePolygon{std::span<const Vec2>(kU)}.pieces().size(), 4u);
  EXPECT_NEAR(area_properties(SimplePolygon{std::span<const Vec2>(kL)}).area, 64.0, 1e-12);
}

TEST(SimplePolygon, MassPropertiesOfTheLFromItsTwoRectangles) {
  // 10 x 4 at y 0..4 plus 6 x 4 at y 4..8: A = 64, centroid ((40·5 + 24·3)/64, (40·2 + 24·6)/64).
  const AreaProperties p = area_properties(SimplePolygon{std::span<const Vec2>(kL)});
  EXPECT_NEAR(p.p_WC.x, (40 * 5.0 + 24 * 3.0) / 64, 1e-12);
  EXPECT_NEAR(p.p_WC.y, (40 * 2.0 + 24 * 6.0) / 64, 1e-12);
  // J about each rectangle's centroid plus the parallel-axis terms.
  const auto j = [](double b, double h) { return b * h * (b * b + h * h) / 12; };
  const double cx = p.p_WC.x, cy = p.p_WC.y;
  const double expected = j(10, 4) + 40 * (std::pow(5 - cx, 2) + std::pow(2 - cy, 2)) + j(6, 4) +
                          24 * (std::pow(3 - cx, 2) + std::pow(6 - cy, 2));
  EXPECT_NEAR(p.polar_moment_c, expected, 1e-10 * expected);
}

TEST(SimplePolygon, RefusesSelfCrossingRepeatedSpikesAndZeroAreaAcceptsCollinear) {
  const auto refused = [](std::vector<Vec2> v) {
    try {
      SimplePolygon{std::span<const Vec2>(v)};
    } catch (const InvalidPolygon& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refused({{0, 0}, {4, 4}, {4, 0}, {0, 4}}).find("crosses itself"), std::string::npos);
  EXPECT_NE(refused({{0, 0}, {4, 0}, {4, 4}, {4, 0.0}, {0, 4}}).find("repeats vertex"),
            std::string::npos);
  EXPECT_NE(refused({{0, 0}, {4, 0}, {4, 4}, {2, 4}, {6, 4}, {0, 4}}).find("turns back"),
            std::string::npos);
  // A vertex on another edge: two rooms joined at a point is not one slab.
  EXPECT_NE(refused({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}).find("touches or crosses"),
            std::string::npos);
  EXPECT_FALSE(refused({{0, 0}, {1, 0}, {2, 0}}).empty());
  // Collinear vertices as drawings have them; clockwise input reversed.
  const std::vector<Vec2> drawn = {{0, 0}, {0, 8}, {6, 8}, {10, 8}, {10, 4}, {10, 0}, {5, 0}};
  const SimplePolygon p{std::span<const Vec2>(drawn)};
  EXPECT_TRUE(p.was_reversed());
  EXPECT_TRUE(p.convex());
  EXPECT_EQ(p.pieces()[0].size(), 4);
}

TEST(PlanOverlap, TwoConvexPlansAreExactlyTheConvexOverlap) {
  const ConvexPolygon a{{0, 0}, {10, 0}, {10, 8}, {0, 8}};
  const ConvexPolygon b{{9, 1}, {13, 2}, {12, 7}, {9.5, 6}};
  const SimplePolygon sa{std::span<const Vec2>(a.vertices())};
  const SimplePolygon sb{std::span<const Vec2>(b.vertices())};
  const PlanOverlap o = plan_overlap(sa, sb);
  const Overlap direct = overlap_of(a, b);
  ASSERT_EQ(o.count, 1);
  EXPECT_EQ(o.components[0].area, direct.area);  // bit-identical
  EXPECT_EQ(o.components[0].p_WC.x, direct.p_WC.x);
  EXPECT_EQ(o.components[0].n_AB.y, direct.n_AB.y);
  EXPECT_EQ(o.components[0].indentation, direct.indentation);
}

TEST(PlanOverlap, ARectangleWithARedundantNotchGivesTheRectanglesOverlap) {
  // The L of kL with its notch closed to zero depth: the notch's corners are collinear vertices.
  const std::vector<Vec2> notch_free = {{0, 0}, {10, 0}, {10, 8}, {6, 8}, {0, 8}};
  const std::vector<Vec2> with_points = {{0, 0}, {10, 0}, {10, 3}, {10, 8}, {6, 8}, {0, 8}};
  const SimplePolygon rect{{0, 0}, {10, 0}, {10, 8}, {0, 8}};
  const SimplePolygon wall{{9.7, -1}, {12, -1}, {12, 9}, {9.7, 9}};
  for (const auto& v : {notch_free, with_points}) {
    const SimplePolygon p{std::span<const Vec2>(v)};
    for (const double theta : {0.0, 0.01, -0.02}) {
      const Placement2 x{0.1, 0.2, theta};
      const PlanOverlap o = plan_overlap(p.placed(x, {5, 4}), wall);
      const PlanOverlap r = plan_overlap(rect.placed(x, {5, 4}), wall);
      ASSERT_EQ(o.count, 1);
      ASSERT_EQ(r.count, 1);
      EXPECT_NEAR(o.components[0].area, r.components[0].area, 1e-9 * r.components[0].area);
      EXPECT_NEAR(o.components[0].p_WC.y, r.components[0].p_WC.y, 1e-9);
      EXPECT_NEAR(o.components[0].n_AB.x, r.components[0].n_AB.x, 1e-9);
      EXPECT_NEAR(o.components[0].indentation, r.components[0].indentation, 1e-9);
    }
  }
}

TEST(PlanOverlap, AWallAcrossTheLsDiagonalIsOneContactWithTheTrueChord) {
  // The L pressed 0.3 m into a wall along y = -0.3 .. : the wall overlaps both pieces (whatever
  // the diagonal), one strip 10 m x 0.3 m, the chord along the L's bottom edge crossings.
  const SimplePolygon l{std::span<const Vec2>(kL)};
  const SimplePolygon wall{{-5, -3}, {15, -3}, {15, 0.3}, {-5, 0.3}};
  const PlanOverlap o = plan_overlap(l, wall);
  ASSERT_EQ(o.count, 1);
  const Overlap& c = o.components[0];
  EXPECT_NEAR(c.area, 3.0, 1e-12);
  EXPECT_NEAR(c.p_WC.x, 5.0, 1e-12);
  EXPECT_NEAR(c.p_WC.y, 0.15, 1e-12);
  EXPECT_EQ(c.kind, OverlapCase::kTwoCrossings);
  EXPECT_NEAR(std::abs(c.n_AB.y), 1.0, 1e-12);  // normal across the strip
  EXPECT_NEAR(c.mean_depth, 0.3, 1e-12);
  EXPECT_NEAR(c.indentation, 0.3, 1e-12);  // a rectangle: δ_N = A/w
}

TEST(PlanOverlap, ABarAcrossBothArmsOfAUIsTwoContacts) {
  const SimplePolygon u{std::span<const Vec2>(kU)};
  const SimplePolygon bar{{-1, 5}, {13, 5}, {13, 7}, {-1, 7}};  // covers y 5..6 of both arms
  const PlanOverlap o = plan_overlap(u, bar);
  ASSERT_EQ(o.count, 2);
  EXPECT_NEAR(o.components[0].area, 4.0, 1e-12);
  EXPECT_NEAR(o.components[1].area, 4.0, 1e-12);
  EXPECT_NEAR(std::abs(o.components[0].p_WC.x - o.components[1].p_WC.x), 8.0, 1e-12);
  const auto exact = plan_overlap_areas_exact(u, bar);
  ASSERT_EQ(exact.size(), 2u);
}

TEST(PlanOverlap, SeparationIsTheLeastOverPiecesAndZeroAtTouch) {
  const SimplePolygon l{std::span<const Vec2>(kL)};
  // A square in the notch, 0.5 m from both notch faces.
  const SimplePolygon sq{{6.5, 4.5}, {9, 4.5}, {9, 7}, {6.5, 7}};
  EXPECT_NEAR(plan_separation(l, sq).distance, 0.5, 1e-12);
  EXPECT_EQ(plan_overlap(l, sq).count, 0);
  const SimplePolygon touching = sq.placed({-0.5, -0.5, 0.0});
  EXPECT_NEAR(plan_separation(l, touching).distance, 0.0, 1e-12);
  // Pressed into the re-entrant corner: one overlap region wrapping the corner, two crossings.
  const PlanOverlap in = plan_overlap(l, sq.placed({-0.7, -0.7, 0.0}));
  ASSERT_EQ(in.count, 1);
  EXPECT_NEAR(in.components[0].area, 2.5 * 2.5 - 2.3 * 2.3, 1e-12);
}

// Random simple plans: star-shaped outlines (non-convex, 5-14 vertices) and orthogonal L/T/U
// shapes on a 0.5 m lattice at 10³ m (exact coordinates: shared edges, vertices on edges,
// multi-component overlaps happen).
class PlanGenerator {
 public:
  explicit PlanGenerator(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(engine_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<>(lo, hi)(engine_); }

  std::vector<Vec2> star(Vec2 centre, double r) {
    const int k = integer(5, 14);
    std::vector<double> angles;
    while (int(angles.size()) < k) {
      const double t = uniform(0, 2 * std::numbers::pi);
      bool apart = true;
      for (double s : angles)
        apart = apart && std::abs(std::remainder(t - s, 2 * std::numbers::pi)) > 0.06;
      if (apart) angles.push_back(t);
    }
    std::sort(angles.begin(), angles.end());
    std::vector<Vec2> out;
    for (double t : angles) {
      const double rr = r * uniform(0.35, 1.0);
      out.push_back({centre.x + rr * std::cos(t), centre.y + rr * std::sin(t)});
    }
    return out;
  }

  // An L, T or U of lattice steps, at (ox, oy) steps from 10³ m.
  std::vector<Vec2> orthogonal(int ox, int oy) {
    const int w = integer(3, 8), h = integer(3, 8);
    const int nx = integer(1, w - 2), ny = integer(1, h - 1);
    std::vector<std::pair<int, int>> v;
    switch (integer(0, 2)) {
      case 0:  // L: the top-right nx x ny corner cut
        v = {{0, 0}, {w, 0}, {w, h - ny}, {w - nx, h - ny}, {w - nx, h}, {0, h}};
        break;
      case 1: {  // T: the two bottom corners cut
        const int side = std::max(1, nx / 2);
        if (2 * side >= w) return {};
        v = {{side, 0}, {w - side, 0}, {w - side, ny}, {w, ny},
             {w, h},    {0, h},        {0, ny},        {side, ny}};
        break;
      }
      default: {  // U: a notch from the top
        const int a = integer(1, w - 2), b = integer(a + 1, w - 1);
        if (ny >= h) return {};
        v = {{0, 0}, {w, 0}, {w, h}, {b, h}, {b, h - ny}, {a, h - ny}, {a, h}, {0, h}};
      }
    }
    const int turns = integer(0, 3);
    std::vector<Vec2> out;
    for (auto [x, y] : v) {
      for (int t = 0; t < turns; ++t) std::tie(x, y) = std::pair<int, int>{-y, x};
      out.push_back({1000.0 + 0.5 * (x + ox), -1000.0 + 0.5 * (y + oy)});
    }
    return out;
  }

 private:
  std::mt19937_64 engine_;
};

std::optional<SimplePolygon> make(const std::vector<Vec2>& v) {
  if (v.size() < 3) return std::nullopt;
  try {
    return SimplePolygon{std::span<const Vec2>(v)};
  } catch (const InvalidPolygon&) {
    return std::nullopt;
  }
}

TEST(PlanOverlapRandom, AreasAndCentroidsOfEveryComponentMatchTheExactBooleanIntersection) {
  const char* env = std::getenv("ISOPOUND_GEOMETRY_PAIRS");
  const int pairs = env ? std::atoi(env) : 10000;
  PlanGenerator gen(20261129);
  int made = 0, multi = 0, non_convex = 0;
  double worst_area = 0.0, worst_centroid = 0.0;
  while (made < pairs) {
    std::optional<SimplePolygon> a, b;
    if (made % 2 == 0) {
      const Vec2 c{1000 + gen.uniform(-5, 5), 1000 + gen.uniform(-5, 5)};
      const double ra = gen.uniform(1, 10), rb = gen.uniform(1, 10);
      const double r = gen.uniform(0, ra + rb), t = gen.uniform(0, 2 * std::numbers::pi);
      a = make(gen.star(c, ra));
      b = make(gen.star({c.x + r * std::cos(t), c.y + r * std::sin(t)}, rb));
    } else {
      a = make(gen.orthogonal(0, 0));
      b = make(gen.orthogonal(gen.integer(-6, 6), gen.integer(-6, 6)));
    }
    if (!a || !b) continue;
    if (made % 4 == 0) *b = b->placed({0, 0, gen.uniform(-0.5, 0.5)}, b->vertices()[0]);
    ++made;
    non_convex += !a->convex() || !b->convex();
    const PlanOverlap fast = plan_overlap(*a, *b);
    const std::vector<ComponentArea> exact = plan_overlap_areas_exact(*a, *b);
    const double scale = std::min(area_properties(*a).area, area_properties(*b).area);
    double exact_total = 0.0;
    for (const ComponentArea& c : exact) exact_total += c.area;
    const double area_error = std::abs(total_area(fast) - exact_total) / scale;
    worst_area = std::max(worst_area, area_error);
    ASSERT_LE(area_error, 1e-9) << "pair " << made;
    ASSERT_EQ(fast.dropped, 0);
    // Component by component: CGAL may join two regions that touch at a point into one polygon;
    // ours are separate contacts. Match each exact component to the set of ours inside it.
    multi += fast.count > 1;
    std::vector<bool> used(fast.count, false);
    for (const ComponentArea& c : exact) {
      double area = 0.0;
      Vec2 moment;
      // Ours whose centroid is nearest to this one's first, until the areas agree.
      std::vector<int> order(fast.count);
      for (int k = 0; k < fast.count; ++k) order[k] = k;
      std::sort(order.begin(), order.end(), [&](int p, int q) {
        const Vec2 dp = fast.components[p].p_WC - c.p_WC, dq = fast.components[q].p_WC - c.p_WC;
        return dot(dp, dp) < dot(dq, dq);
      });
      for (const int k : order) {
        if (used[k] || std::abs(area - c.area) <= 1e-9 * scale) continue;
        if (area + fast.components[k].area > c.area + 1e-9 * scale) continue;
        used[k] = true;
        area += fast.components[k].area;
        moment = moment + fast.components[k].area * fast.components[k].p_WC;
      }
      ASSERT_NEAR(area, c.area, 1e-9 * scale) << "pair " << made;
      if (c.area > 1e-6 * scale) {
        const Vec2 d = (1.0 / area) * moment - c.p_WC;
        const double centroid_error = std::hypot(d.x, d.y) / std::sqrt(scale);
        worst_centroid = std::max(worst_centroid, centroid_error);
        ASSERT_LE(centroid_error, 1e-9) << "pair " << made;
      }
    }
  }
  std::printf(
      "%d random pairs (%d with a non-convex plan, %d with several contacts): worst "
      "area error %.2e, centroid %.2e (relative)\n",
      made, non_convex, multi, worst_area, worst_centroid);
  EXPECT_GT(multi, pairs / 100);
}

TEST(FollowingMoat, ARectanglesMoatIsTodaysFourWalls) {
  // Today's walls (solver/structures/pounding3d.cpp, moat_wall_outline): east x in [hi.x + g,
  // hi.x + g + t], y in [lo.y - e, hi.y + e], and so on round the slab's box.
  const double g = 0.2, t = 1.0, e = 1.0;
  const SimplePolygon slab{{2, 3}, {18.5, 3}, {18.5, 19.5}, {2, 19.5}};
  const std::vector<MoatWall> walls = following_moat(slab, g, t, e);
  ASSERT_EQ(walls.size(), 4u);
  const auto box = [&](double x0, double x1, double y0, double y1) {
    return std::array<double, 4>{x0, x1, y0, y1};
  };
  const std::array<double, 4> expected[] = {
      box(2 - e, 18.5 + e, 3 - g - t, 3 - g),        // south (the run from (2, 3))
      box(18.5 + g, 18.5 + g + t, 3 - e, 19.5 + e),  // east
      box(2 - e, 18.5 + e, 19.5 + g, 19.5 + g + t),  // north
      box(2 - g - t, 2 - g, 3 - e, 19.5 + e)};       // west
  for (int k = 0; k < 4; ++k) {
    const ConvexPolygon& w = walls[k].outline;
    EXPECT_EQ(w.size(), 4);
    EXPECT_NEAR(w.box_min().x, expected[k][0], 1e-12) << k;
    EXPECT_NEAR(w.box_max().x, expected[k][1], 1e-12) << k;
    EXPECT_NEAR(w.box_min().y, expected[k][2], 1e-12) << k;
    EXPECT_NEAR(w.box_max().y, expected[k][3], 1e-12) << k;
    EXPECT_NEAR(area_properties(w).area,
                (expected[k][1] - expected[k][0]) * (expected[k][3] - expected[k][2]), 1e-9);
  }
}

TEST(FollowingMoat, TheLsWallsStandAtTheGapAndMeetOnceAtTheReEntrantCorner) {
  const SimplePolygon l{std::span<const Vec2>(kL)};
  const double g = 0.25, t = 0.8;
  const std::vector<MoatWall> walls = following_moat(l, g, t, 1.0);
  ASSERT_EQ(walls.size(), 6u);
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const SimplePolygon w{std::span<const Vec2>(walls[k].outline.vertices())};
    EXPECT_NEAR(plan_separation(l, w).distance, g, 1e-12) << k;  // the gap, nothing closer
    for (std::size_t j = k + 1; j < walls.size(); ++j) {
      const SimplePolygon v{std::span<const Vec2>(walls[j].outline.vertices())};
      const PlanOverlap o = plan_overlap(w, v);
      const bool neighbours = j == k + 1 || (k == 0 && j == walls.size() - 1);
      // At the re-entrant corner (6, 4) the two walls share their mitre and nothing else; at
      // the convex corners they overlap in the corner square (t + e beyond), as today's do.
      if (!neighbours || (walls[k].p_WE.x == 6 && walls[k].p_WE.y == 4)) {
        EXPECT_EQ(o.count, 0) << k << " " << j;
      }
    }
  }
  // The slab pushed 0.3 m (> g) along +x and +y into the notch corner meets the two notch walls
  // (and the outer east wall's run along x = 10 only below y = 4), each once.
  const SimplePolygon moved = l.placed({0.3, 0.3, 0.0});
  int touched = 0;
  for (const MoatWall& w : walls) {
    const SimplePolygon v{std::span<const Vec2>(w.outline.vertices())};
    const PlanOverlap o = plan_overlap(moved, v);
    EXPECT_LE(o.count, 1);
    touched += o.count;
  }
  EXPECT_EQ(touched, 4);  // east, notch bottom, notch side, north
  EXPECT_THROW(following_moat(l, 3.0, 2.0, 1.0), InvalidPolygon);  // the notch is 4 m wide
}

}  // namespace
// A gap per run: one gap for all equals the one-gap moat bit for bit; different gaps put each
// wall's face at its own run's gap (the face's offset from its run), the walls at the re-entrant
// corner still share their mitre and nothing else, and the mitred end of the wider one comes no
// nearer the other face than that face's own gap.
TEST(FollowingMoat, EachRunAtItsOwnGap) {
  const SimplePolygon l{std::span<const Vec2>(kL)};
  const double t = 0.8, e = 1.0;
  ASSERT_EQ(outline_runs(l).size(), 6u);
  const std::vector<MoatWall> one = following_moat(l, 0.25, t, e);
  const std::vector<MoatWall> same = following_moat(l, std::vector<double>(6, 0.25), t, e);
  for (std::size_t k = 0; k < 6; ++k)
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(one[k].outline[i].x, same[k].outline[i].x);
      EXPECT_EQ(one[k].outline[i].y, same[k].outline[i].y);
    }
  // Runs from (0, 0): south, east (x = 10), notch bottom (y = 4), notch side (x = 6), north, west.
  const std::vector<double> gaps = {0.2, 0.3, 0.35, 0.15, 0.25, 0.4};
  const std::vector<MoatWall> walls = following_moat(l, gaps, t, e);
  const std::vector<std::pair<Vec2, Vec2>> runs = outline_runs(l);
  for (std::size_t k = 0; k < 6; ++k) {
    const Vec2 d = runs[k].second - runs[k].first;
    const Vec2 n = (1.0 / std::hypot(d.x, d.y)) * Vec2{d.y, -d.x};
    double face = std::numeric_limits<double>::infinity();
    for (const Vec2& p : walls[k].outline.vertices()) face = std::min(face, dot(n, p));
    EXPECT_NEAR(face - dot(n, runs[k].first), gaps[k], 1e-12) << k;
    const SimplePolygon w{std::span<const Vec2>(walls[k].outline.vertices())};
    EXPECT_GE(plan_separation(l, w).distance,
              std::min({gaps[k], gaps[(k + 1) % 6], gaps[(k + 5) % 6]}) - 1e-12)
        << k;
  }
  const auto shared = [&](int a, int b) {
    return plan_overlap(SimplePolygon{std::span<const Vec2>(walls[a].outline.vertices())},
                        SimplePolygon{std::span<const Vec2>(walls[b].outline.vertices())});
  };
  EXPECT_EQ(shared(2, 3).count, 0);  // the notch's two walls meet along their mitre only
  // The notch bottom's wall (0.35) ends on the side wall's face line x = 6 + 0.15: its mitred
  // end is 0.15 from the notch side, its face 0.35 from the notch bottom.
  double least_x = std::numeric_limits<double>::infinity();
  for (const Vec2& p : walls[2].outline.vertices()) least_x = std::min(least_x, p.x);
  EXPECT_NEAR(least_x, 6.15, 1e-12);
  EXPECT_THROW(following_moat(l, std::vector<double>(5, 0.25), t, e), std::invalid_argument);
}

}  // namespace isopound
