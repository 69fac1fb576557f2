// Benchmarks of one set_trial of the bearing laws in plan (the per-bearing cost of a Newton
// iteration): coupled Bouc-Wen at typical increments, against the uniaxial law, and the others.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "solver/materials/bilinear_biaxial.h"
#include "solver/materials/bouc_wen.h"
#include "solver/materials/bouc_wen_coupled.h"
#include "solver/materials/friction_pendulum.h"

namespace {

using namespace isopound;
using Eigen::Vector2d;

// One of 16 thesis bearings: 1.27e6 kg / 16, T_b 2 s, Q/W 5 %, u_y 1 cm, n 2, beta = gamma = 0.5.
BoucWenParameters thesis_bearing() {
  const double m = 1.27e6 / 16, k_post = m * std::numbers::pi * std::numbers::pi;
  BoucWenParameters p;
  p.yield_displacement = 0.01;
  p.yield_force = 0.05 * m * 9.81 + k_post * 0.01;
  p.elastic_stiffness = p.yield_force / 0.01;
  p.alpha = k_post / p.elastic_stiffness;
  return p;
}

// Committed state: pushed 5 u_y along x (|z| ~ 1); trials alternate between two increments of
// the given size at 30 and 35 degrees to x (so the result is never reused).
void BM_CoupledBoucWen_SetTrial(benchmark::State& state) {
  const BoucWenParameters p = thesis_bearing();
  CoupledBoucWenMaterial law(p);
  for (int k = 1; k <= 50; ++k) {
    law.set_trial(Vector2d(0.1 * k * p.yield_displacement, 0), Vector2d::Zero());
    law.commit();
  }
  const double size = p.yield_displacement * static_cast<double>(state.range(0)) / 100.0;
  const Vector2d d0 = law.deformation();
  const Vector2d a = d0 + size * Vector2d(std::cos(0.52), std::sin(0.52));
  const Vector2d b = d0 + size * Vector2d(std::cos(0.61), std::sin(0.61));
  bool flip = false;
  for (auto _ : state) {
    law.set_trial(flip ? a : b, Vector2d::Zero());
    benchmark::DoNotOptimize(law.force());
    benchmark::DoNotOptimize(law.tangent());
    flip = !flip;
  }
}
// Increment in % of u_y: 10 % (a Newton iterate of a 2.5 ms step at 0.4 m/s: one sub-increment),
// 100 % (8 sub-increments), -300 % (a reversal: z_x crosses 0).
BENCHMARK(BM_CoupledBoucWen_SetTrial)->Arg(10)->Arg(100)->Arg(-300);

void BM_UniaxialBoucWen_SetTrial(benchmark::State& state) {
  const BoucWenParameters p = thesis_bearing();
  BoucWenMaterial law(p);
  for (int k = 1; k <= 50; ++k) {
    law.set_trial(0.1 * k * p.yield_displacement);
    law.commit();
  }
  const double size = p.yield_displacement * static_cast<double>(state.range(0)) / 100.0;
  const double a = law.deformation() + size * std::cos(0.52);
  const double b = law.deformation() + size * std::cos(0.61);
  bool flip = false;
  for (auto _ : state) {
    law.set_trial(flip ? a : b);
    benchmark::DoNotOptimize(law.force());
    benchmark::DoNotOptimize(law.tangent());
    flip = !flip;
  }
}
BENCHMARK(BM_UniaxialBoucWen_SetTrial)->Arg(10)->Arg(100)->Arg(-300);

void BM_BilinearBiaxial_SetTrial(benchmark::State& state) {
  const BoucWenParameters p = thesis_bearing();
  BilinearBiaxialMaterial law(p.elastic_stiffness, p.alpha, p.yield_force);
  law.set_trial(Vector2d(0.05, 0), Vector2d::Zero());
  law.commit();
  const Vector2d a(0.051, 0.0005), b(0.0512, 0.0006);
  bool flip = false;
  for (auto _ : state) {
    law.set_trial(flip ? a : b, Vector2d::Zero());
    benchmark::DoNotOptimize(law.force());
    benchmark::DoNotOptimize(law.tangent());
    flip = !flip;
  }
}
BENCHMARK(BM_BilinearBiaxial_SetTrial);

void BM_FrictionPendulum_SetTrial(benchmark::State& state) {
  FrictionPendulumParameters p;
  p.weight = 1.27e6 / 16 * 9.81;
  p.radius = 2.24;
  p.mu_slow = 0.04;
  p.mu_fast = 0.10;
  p.rate_parameter = 30;
  FrictionPendulumMaterial law(p);
  law.set_trial(Vector2d(0.05, 0), Vector2d(0.3, 0));
  law.commit();
  const Vector2d a(0.051, 0.0005), b(0.0512, 0.0006), v(0.3, 0.1);
  bool flip = false;
  for (auto _ : state) {
    law.set_trial(flip ? a : b, v);
    benchmark::DoNotOptimize(law.force());
    benchmark::DoNotOptimize(law.tangent());
    benchmark::DoNotOptimize(law.rate_tangent());
    flip = !flip;
  }
}
BENCHMARK(BM_FrictionPendulum_SetTrial);

}  // namespace

BENCHMARK_MAIN();
