// Benchmarks of the 3D polygon contact element (ns per call): set_trial with a quadrilateral
// overlap (slab against a wall face, slab against a turned slab), with and without friction, and
// add_tangent (central differences, 2 force evaluations per DOF).
#include <benchmark/benchmark.h>

#include <Eigen/Dense>
#include <stdexcept>

#include "solver/elements/polygon_contact.h"

namespace {

using namespace isopound;

ConvexPolygon rectangle(double x0, double y0, double x1, double y1) {
  return ConvexPolygon{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A 16.5 m square slab (DOFs 0-2) at the origin; B is a fixed 1 m wall whose face is 1 mm inside
// the slab's right face (wall = true), or a 16.5 m slab (DOFs 3-5) turned by 0.01 rad, 1 mm deep.
// Trials cycle through 64 states a few µm apart (as Newton iterations do): a quadrilateral
// overlap in every one.
struct Setup {
  PolygonContact contact;
  std::vector<Eigen::VectorXd> u, v;
};

Setup make(bool wall, bool friction) {
  const double a = 8.25;
  PolygonBody slab{0, 1, 2, {0, 0}, rectangle(-a, -a, a, a), 340e3};
  PolygonBody other =
      wall ? PolygonBody{-1, -1, -1, {0, 0}, rectangle(a - 1e-3, -12, a + 1, 12), 500e3}
           : PolygonBody{3, 4, 5, {2 * a, 3}, rectangle(a, 3 - a, 3 * a, 3 + a), 340e3};
  PolygonContactConfig cfg;
  cfg.friction = friction;
  Setup s{PolygonContact("bench", slab, other, cfg), {}, {}};
  const int n = wall ? 3 : 6;
  for (int k = 0; k < 64; ++k) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n);
    u[0] = 1e-6 * k;
    u[1] = 1e-6 * k;
    v[0] = 0.5;
    v[1] = 0.1;
    if (!wall) {
      u[2] = 1e-4;
      u[5] = 0.01;
      u[3] = -0.09 + 1e-6 * k;  // a turned face 1 mm (±) into the slab
      v[3] = -0.2;
    }
    s.u.push_back(u);
    s.v.push_back(v);
  }
  s.contact.begin_step(1e-4, false);
  for (int k = 0; k < 64; k += 63) {  // a quadrilateral at both ends of the cycle
    const Eigen::VectorXd& u = s.u[k];
    const ConvexPolygon pa = slab.shape.placed({u[0], u[1], u[2]}, slab.p_WO);
    const ConvexPolygon pb =
        wall ? other.shape : other.shape.placed({u[3], u[4], u[5]}, other.p_WO);
    if (overlap_of(pa, pb).vertex_count != 4) throw std::logic_error("not a quadrilateral");
  }
  return s;
}

void set_trial(benchmark::State& state, bool wall, bool friction) {
  Setup s = make(wall, friction);
  s.contact.set_trial(s.u[0], s.v[0]);
  if (s.contact.output(2) <= 0) state.SkipWithError("no overlap in the benchmark set-up");
  std::size_t k = 0;
  double sink = 0.0;
  for (auto _ : state) {
    s.contact.set_trial(s.u[k & 63], s.v[k & 63]);
    ++k;
    sink += s.contact.output(0);
    benchmark::DoNotOptimize(sink);
  }
  state.counters["F_N_N"] = sink / double(state.iterations());
}

void BM_SetTrialSlabWall(benchmark::State& state) {
  set_trial(state, true, false);
}
void BM_SetTrialSlabWallFriction(benchmark::State& state) {
  set_trial(state, true, true);
}
void BM_SetTrialSlabSlabFriction(benchmark::State& state) {
  set_trial(state, false, true);
}

void BM_TangentSlabSlabFriction(benchmark::State& state) {
  Setup s = make(false, true);
  s.contact.set_trial(s.u[0], s.v[0]);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6, 6);
  for (auto _ : state) {
    s.contact.add_tangent(K, 2e4);
    benchmark::DoNotOptimize(K.data());
  }
}

BENCHMARK(BM_SetTrialSlabWall);
BENCHMARK(BM_SetTrialSlabWallFriction);
BENCHMARK(BM_SetTrialSlabSlabFriction);
BENCHMARK(BM_TangentSlabSlabFriction);

}  // namespace

BENCHMARK_MAIN();
