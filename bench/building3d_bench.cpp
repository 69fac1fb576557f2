// Benchmark of one 3D analysis: the eccentric validation building (configs/3d-eccentric-v30.yaml)
// under the RSN1084 pair at 30 degrees, default adaptive settings (and the all-modes step rule),
// histories off.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "solver/core/analysis.h"
#include "solver/io/model_input.h"
#include "solver/structures/config3d.h"
#include "solver/structures/job.h"

namespace {

using namespace isopound;

// state.range(0): 1 = the largest step from every mode (max_step_rule: all_modes, the rule
// before issue 10's benchmark work), 0 = the config's default (participating modes).
void BM_Eccentric3D_RSN1084Pair(benchmark::State& state) {
  const auto path =
      std::filesystem::path(ISOPOUND_SOURCE_DIR) / "configs" / "3d-eccentric-v30.yaml";
  ModelConfig config = load_model_file(path.string());
  GroundMotion motion;
  try {
    motion = load_ground_motion(config.ground_motion, true);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  const RunOptions options = [&] {
    RunOptions o = run_options(config);
    o.output.histories = false;
    if (state.range(0) == 1) o.analysis.max_step_rule = AnalysisConfig::MaxStepRule::kAllModes;
    return o;
  }();
  long steps = 0;
  for (auto _ : state) {
    Model model = build_model(config);
    const AnalysisResult r = run_analysis(model, motion, options);
    steps = r.stats.steps + r.stats.rejected_steps;
    benchmark::DoNotOptimize(r.displacement[0].value);
  }
  state.counters["steps"] = static_cast<double>(steps);
}

void BM_Eccentric3D_RSN1084Pair_Default(benchmark::State& state) {
  BM_Eccentric3D_RSN1084Pair(state);
}
void BM_Eccentric3D_RSN1084Pair_AllModes(benchmark::State& state) {
  BM_Eccentric3D_RSN1084Pair(state);
}

BENCHMARK(BM_Eccentric3D_RSN1084Pair_Default)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Eccentric3D_RSN1084Pair_AllModes)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
