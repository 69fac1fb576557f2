// Benchmarks of the convex-polygon overlap (ns per call): disjoint pairs rejected by their boxes
// or by the exact SAT, overlapping quadrilateral and triangle cases (fast and exact paths),
// separation. Each benchmark cycles through 64 placements of one pair near (1000 m, −2000 m).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "geometry/overlap.h"

namespace {

using namespace isopound;

constexpr Vec2 kSite{1000.0, -2000.0};

ConvexPolygon slab(double width, double depth) {
  return ConvexPolygon{{kSite.x, kSite.y},
                       {kSite.x + width, kSite.y},
                       {kSite.x + width, kSite.y + depth},
                       {kSite.x, kSite.y + depth}};
}

struct Pair {
  ConvexPolygon a, b;
};

// A 20 m × 15 m slab A and a 12 m × 10 m slab B beside it, B moved by `gap` past A's right face
// (gap < 0: penetration) and turned by θ + spread·(k − 32), k = 0..63.
std::vector<Pair> pairs(double gap, double theta, double spread = 1e-3) {
  const ConvexPolygon a = slab(20, 15);
  const ConvexPolygon b = slab(12, 10);
  std::vector<Pair> out;
  for (int k = 0; k < 64; ++k) {
    const double turn = theta + spread * (k - 32);
    // Place B's left face (or its lowest-left corner when turned) at x = 20 + gap.
    const ConvexPolygon placed = b.placed({20.0 + gap, 2.0 + 0.01 * k, turn}, kSite);
    const double min_x = placed.box_min().x - kSite.x;
    out.push_back({a, placed.placed({20.0 + gap - min_x, 0.0, 0.0})});
  }
  return out;
}

void run(benchmark::State& state, const std::vector<Pair>& set, OverlapMethod method) {
  size_t k = 0;
  double sink = 0.0;
  for (auto _ : state) {
    const Pair& p = set[k++ & 63];
    const Overlap o = overlap_of(p.a, p.b, method);
    sink += o.area;
    benchmark::DoNotOptimize(sink);
  }
  state.counters["area_m2"] = sink / double(state.iterations());
}

void BM_OverlapRejectedByBoxes(benchmark::State& state) {
  run(state, pairs(0.5, 0.0), OverlapMethod::kFast);
}
void BM_OverlapRejectedBySat(benchmark::State& state) {
  // B = 10 m × 10 m turned by π/4 (a diamond), its lower-left face 0.5 m (± 1 cm) from A's
  // corner (20, 15) along the diagonal: the boxes overlap by ~3 m, the polygons do not.
  const ConvexPolygon a = slab(20, 15), b = slab(10, 10);
  std::vector<Pair> set;
  for (int k = 0; k < 64; ++k) {
    const double d = (5.0 + 0.5 + 1e-2 * (k - 32)) / std::sqrt(2.0);
    // Turn about B's centre, then move the centre to A's corner + d (1, 1).
    const ConvexPolygon diamond =
        b.placed({20.0 + d - 5.0, 15.0 + d - 5.0, std::atan(1.0)}, {kSite.x + 5, kSite.y + 5});
    set.push_back({a, diamond});
  }
  run(state, set, OverlapMethod::kFast);
}
void BM_OverlapQuadrilateral(benchmark::State& state) {  // face-on, 2 cm penetration
  run(state, pairs(-0.02, 0.0, 0.0), OverlapMethod::kFast);
}
void BM_OverlapTriangle(benchmark::State& state) {  // corner-first, 2 cm penetration
  run(state, pairs(-0.02, 0.5), OverlapMethod::kFast);
}
void BM_OverlapQuadrilateralExact(benchmark::State& state) {
  run(state, pairs(-0.02, 0.0, 0.0), OverlapMethod::kExact);
}
void BM_OverlapTriangleExact(benchmark::State& state) {
  run(state, pairs(-0.02, 0.5), OverlapMethod::kExact);
}
void BM_SeparationNearContact(benchmark::State& state) {
  const std::vector<Pair> set = pairs(0.001, 0.5);
  size_t k = 0;
  double sink = 0.0;
  for (auto _ : state) {
    const Pair& p = set[k++ & 63];
    sink += separation_of(p.a, p.b).distance;
    benchmark::DoNotOptimize(sink);
  }
}
void BM_SeparationPenetrating(benchmark::State& state) {
  const std::vector<Pair> set = pairs(-0.02, 0.5);
  size_t k = 0;
  double sink = 0.0;
  for (auto _ : state) {
    const Pair& p = set[k++ & 63];
    sink += separation_of(p.a, p.b).distance;
    benchmark::DoNotOptimize(sink);
  }
}

BENCHMARK(BM_OverlapRejectedByBoxes);
BENCHMARK(BM_OverlapRejectedBySat);
BENCHMARK(BM_OverlapQuadrilateral);
BENCHMARK(BM_OverlapTriangle);
BENCHMARK(BM_OverlapQuadrilateralExact);
BENCHMARK(BM_OverlapTriangleExact);
BENCHMARK(BM_SeparationNearContact);
BENCHMARK(BM_SeparationPenetrating);

}  // namespace

BENCHMARK_MAIN();
