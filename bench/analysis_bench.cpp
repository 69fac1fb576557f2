// Benchmarks of one analysis: the thesis 3-storey building under RSN1084 SCS052, at the default
// adaptive settings and at the thesis's fixed 2e-5 s step, and with moat walls at 10 cm; and the
// library path of `isopound run` for a plain 2D model (file, record, model, analysis).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>

#include "solver/core/analysis.h"
#include "solver/excitation/ground_motion.h"
#include "solver/io/model_input.h"
#include "solver/structures/building2d.h"
#include "solver/structures/job.h"
#include "solver/structures/pounding2d.h"

namespace {

using namespace isopound;

std::filesystem::path records_dir() {
  if (const char* env = std::getenv("ISOPOUND_SHARED"))
    return std::filesystem::path(env) / "records";
  return std::filesystem::path(ISOPOUND_SOURCE_DIR) / ".." / "shared" / "records";
}

BuildingConfig three_storey(IsolatorConfig::Model model) {
  BuildingConfig b;
  b.base_mass = 340e3;
  b.floors = {{340e3, 600e6, 3.2}, {340e3, 600e6, 3.2}, {250e3, 600e6, 3.2}};
  b.isolator.model = model;
  return b;
}

// Thesis chapter-4 set-up with walls at 10 cm on both sides of the base slab.
BuildingConfig with_walls(const std::string& law) {
  BuildingConfig b = three_storey(IsolatorConfig::Model::kBoucWen);
  WallConfig w;
  w.gap_left = w.gap_right = 0.10;
  w.impact.law = law;
  w.impact.k = 2.5e9;
  w.impact.k_h = 2.5e9;
  w.impact.e = 0.7;
  w.mass = 500e3;
  b.walls = {w};
  return b;
}

void run(benchmark::State& state, const BuildingConfig& building, double fixed_dt) {
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
    Model model = make_model(building);
    add_walls(model, 0, building, options.analysis.steps_per_contact);
    const AnalysisResult r = run_analysis(model, motion, options);
    steps = r.stats.steps + r.stats.rejected_steps;
    iterations = r.stats.newton_iterations;
    benchmark::DoNotOptimize(r.displacement[0].value);
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["newton_iterations"] = static_cast<double>(iterations);
}

using Iso = IsolatorConfig::Model;
void BM_BoucWen_Default(benchmark::State& s) {
  run(s, three_storey(Iso::kBoucWen), 0);
}
void BM_BoucWen_Fixed2e5(benchmark::State& s) {
  run(s, three_storey(Iso::kBoucWen), 2e-5);
}
void BM_Bilinear_Default(benchmark::State& s) {
  run(s, three_storey(Iso::kBilinear), 0);
}
void BM_Bilinear_Fixed2e5(benchmark::State& s) {
  run(s, three_storey(Iso::kBilinear), 2e-5);
}
void BM_Walls10cm_KelvinVoigt(benchmark::State& s) {
  run(s, with_walls("kelvin_voigt"), 0);
}
void BM_Walls10cm_HertzDampMuthukumar(benchmark::State& s) {
  run(s, with_walls("hertz_damp_muthukumar"), 0);
}
void BM_Walls10cm_HertzDampYe(benchmark::State& s) {
  run(s, with_walls("hertz_damp_ye"), 0);
}

// What `isopound run configs/<name> --no-histories` computes, in process: the model file and the
// record read, the model built, the analysis run (issue 39: a plain 2D run had become 12 %
// slower by reading its record twice; bench/run2d_bench.sh times the whole process).
void run_config(benchmark::State& state, const char* name) {
  const auto path = std::filesystem::path(ISOPOUND_SOURCE_DIR) / "configs" / name;
  ModelConfig config;
  try {
    config = load_model_file(path.string());
    config.output.histories = false;
    run_job(config);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());  // e.g. ../shared/records absent
    return;
  }
  long steps = 0;
  for (auto _ : state) {
    const JobResult job = run_job(config);
    steps = job.analysis.stats.steps;
    benchmark::DoNotOptimize(job.analysis.displacement[0].value);
  }
  state.counters["steps"] = static_cast<double>(steps);
}
void BM_RunJob_Thesis3StoreyBL(benchmark::State& s) {
  run_config(s, "thesis-3storey-bl.yaml");
}
void BM_RunJob_Thesis3StoreyBW(benchmark::State& s) {
  run_config(s, "thesis-3storey-bw.yaml");
}

BENCHMARK(BM_BoucWen_Default)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BoucWen_Fixed2e5)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_Bilinear_Default)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Bilinear_Fixed2e5)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_Walls10cm_KelvinVoigt)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Walls10cm_HertzDampMuthukumar)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Walls10cm_HertzDampYe)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RunJob_Thesis3StoreyBL)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RunJob_Thesis3StoreyBW)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
