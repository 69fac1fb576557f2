// A sweep's run records only what its outputs read (RunOptions::record, record_scope_of): every
// selector must give, from such a run, the value it gives from a run that records everything.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "solver/structures/job.h"
#include "solver/study/study_outputs.h"
#include "tests/model_test_support.h"

namespace isopound {
namespace {

// Three storeys on Bouc-Wen isolators, walls at the roof that the pulse reaches (contact outputs).
constexpr const char* kWalledBuilding = R"(
building:
  name: main
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: bouc_wen, Tb: 2 s, QW: 5 %, uy: 1 cm}
  damping: {superstructure: {type: rayleigh, ratio: 2 %, modes: [1, 2]}, isolation: 5 %}
  walls: {gap: 5 cm, level: 3, law: linear, k: 2500 kN/mm}
ground_motion: {pulse: {amplitude: 0.8 m/s, period: 1.5 s, dt: 0.005 s, duration: 8 s}}
analysis: {stepping: fixed, dt: 0.005 s}
)";

TEST(RecordScope, EachSelectorReadsTheSameFromARunThatRecordsOnlyItsNeeds) {
  const ModelConfig config = test::load_model_text(kWalledBuilding);
  const JobResult full = run_job(config);
  const char* selectors[] = {"base.displacement",
                             "roof.velocity",
                             "floors.absolute_acceleration",
                             "levels.residual_displacement",
                             "story1.drift",
                             "stories.drift_ratio",
                             "stories.shear",
                             "story2.residual_drift",
                             "isolator.force",
                             "wall*.impacts",
                             "sum:wall*.impacts",
                             "energy.input",
                             "energy.hysteretic",
                             "energy.max_relative_error",
                             "ground.pga"};
  for (const char* text : selectors) {
    const ResolvedOutput output = resolve_output(parse_output_selector(text), full.model);
    RunOptions options = run_options(config);
    options.record = record_scope_of({output});
    Model model = build_model(config);
    const AnalysisResult scoped = run_analysis(model, full.motion, options);
    const double expected = evaluate_output(output, full.analysis, full.motion_peaks);
    EXPECT_EQ(evaluate_output(output, scoped, full.motion_peaks), expected) << text;
    EXPECT_NE(expected, 0.0) << text << ": a selector that reads zero proves nothing";
  }
  // The displacement peaks alone switch every other record off (their fields stay zero).
  const RecordScope none =
      record_scope_of({resolve_output(parse_output_selector("base.displacement"), full.model)});
  EXPECT_FALSE(none.velocities || none.accelerations || none.story_shears || none.base_shears ||
               none.element_outputs || none.probes || none.energy);
}

}  // namespace
}  // namespace isopound
