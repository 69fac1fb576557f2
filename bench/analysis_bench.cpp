// Benchmarks of one analysis: the thesis 3-storey building under RSN1084 SCS052, at the default
// adaptive settings and at the thesis's fixed 2e-5 s step. Results go to bench/RESULTS.md.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>

#include "solver/analysis.h"
#include "solver/building2d.h"
#include "solver/ground_motion.h"

namespace {

using namespace isopound;

std::filesystem::path records_dir() {
  if (const char* env = std::getenv("ISOPOUND_SHARED")) return std::filesystem::path(env) / "records";
  return std::filesystem::path(ISOPOUND_SOURCE_DIR) / ".." / "shared" / "records";
}

BuildingConfig three_storey(IsolatorConfig::Model model) {
  BuildingConfig b;
  b.base_mass = 340e3;
  b.floors = {{340e3, 600e6, 3.2}, {340e3, 600e6, 3.2}, {250e3, 600e6, 3.2}};
  b.isolator.model = model;
  return b;
}

void run(benchmark::State& state, IsolatorConfig::Model isolator, double fixed_dt) {
  const auto path = records_dir() / "RSN1084_NORTHR_SCS052.AT2";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("../shared/records absent");
    return;
  }
  const GroundMotion motion = read_record(path.string());
  RunOptions options;
  options.output.histories = false;
  if (fixed_dt > 0) {
    options.analysis.stepping = AnalysisConfig::Stepping::kFixed;
    options.analysis.dt = fixed_dt;
  }
  long steps = 0, iterations = 0;
  for (auto _ : state) {
    Model model = make_model(three_storey(isolator));
    const AnalysisResult r = run_analysis(model, motion, options);
    steps = r.stats.steps + r.stats.rejected_steps;
    iterations = r.stats.newton_iterations;
    benchmark::DoNotOptimize(r.displacement[0].value);
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["newton_iterations"] = static_cast<double>(iterations);
}

void BM_BoucWen_Default(benchmark::State& s) { run(s, IsolatorConfig::Model::kBoucWen, 0); }
void BM_BoucWen_Fixed2e5(benchmark::State& s) { run(s, IsolatorConfig::Model::kBoucWen, 2e-5); }
void BM_Bilinear_Default(benchmark::State& s) { run(s, IsolatorConfig::Model::kBilinear, 0); }
void BM_Bilinear_Fixed2e5(benchmark::State& s) { run(s, IsolatorConfig::Model::kBilinear, 2e-5); }

BENCHMARK(BM_BoucWen_Default)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BoucWen_Fixed2e5)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_Bilinear_Default)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Bilinear_Fixed2e5)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
