// One contact evaluation of a slab against the moat that follows it (issue 40), ns: the slab
// placed (u, v, θ) and overlapped with every wall, as the 3D contact does each trial. An
// L-shaped slab (two convex pieces) in its following moat (six walls, mitred at the re-entrant
// corner) against today's convex pair: its bounding rectangle in four walls. 64 placements
// pressing 0-4 cm into the east and north walls with small turns, near (1000 m, -2000 m).
#include <benchmark/benchmark.h>

#include <vector>

#include "geometry/moat.h"
#include "geometry/plan_overlap.h"

namespace {

using namespace isopound;

constexpr Vec2 kSite{1000.0, -2000.0};
constexpr double kGap = 0.2;

std::vector<Vec2> at_site(std::vector<Vec2> v) {
  for (Vec2& p : v) p = p + kSite;
  return v;
}

// L: 40 m x 30 m with the 16 m x 14 m corner (24..40, 16..30) cut away.
const SimplePolygon& l_slab() {
  static const SimplePolygon l{
      std::span<const Vec2>(at_site({{0, 0}, {40, 0}, {40, 16}, {24, 16}, {24, 30}, {0, 30}}))};
  return l;
}
const SimplePolygon& rectangle() {
  static const SimplePolygon r{
      std::span<const Vec2>(at_site({{0, 0}, {40, 0}, {40, 30}, {0, 30}}))};
  return r;
}

Placement2 placement(int k) {
  const double push = kGap + 0.04 * (k % 8) / 7.0;  // 0 to 4 cm past the gap
  return {push, (k % 3 == 0 ? push : 0.0), 1e-4 * (k - 32)};
}

void run(benchmark::State& state, const SimplePolygon& slab) {
  std::vector<SimplePolygon> walls;
  for (const MoatWall& w : following_moat(slab, kGap, 1.0, 1.0))
    walls.push_back(SimplePolygon{std::span<const Vec2>(w.outline.vertices())});
  const Vec2 about = area_properties(slab).p_WC;
  SimplePolygon placed = slab.placed({}, about);
  PlanOverlap o;
  std::size_t k = 0;
  double sink = 0.0;
  for (auto _ : state) {
    slab.placed_into(placement(int(k++ & 63)), about, placed);
    for (const SimplePolygon& w : walls) {
      plan_overlap(placed, w, o);
      for (int c = 0; c < o.count; ++c) sink += o.components[c].area;
    }
    benchmark::DoNotOptimize(sink);
  }
  state.counters["walls"] = double(walls.size());
  state.counters["pieces"] = double(slab.pieces().size());
  state.counters["area_m2"] = sink / double(state.iterations());
}

void BM_RectangleInFourWalls(benchmark::State& state) {
  run(state, rectangle());
}
void BM_LShapedSlabInItsFollowingMoat(benchmark::State& state) {
  run(state, l_slab());
}

}  // namespace

BENCHMARK(BM_RectangleInFourWalls);
BENCHMARK(BM_LShapedSlabInItsFollowingMoat);

BENCHMARK_MAIN();
