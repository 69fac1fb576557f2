// "No silent wrong answers" (issue 14), the output side: the exact output grid, streamed
// histories, shear equilibrium, residual displacement, critical gap per contact, exit codes.
#include <gtest/gtest.h>

#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "solver/core/constants.h"
#include "solver/io/model_input.h"
#include "solver/structures/job.h"
#include "solver/study/study_outputs.h"
#include "tests/model_test_support.h"
#include "tests/test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

ModelConfig load(const std::string& text) {
  return test::load_model_text(text);
}
int column(const History& h, const std::string& name) {
  return test::history_column(h, name);
}

// 100,000 samples at 1 ms (a pulse sampled that finely): every row on k * interval, none lost.
// The old schedule accumulated next += interval and lost rows / drifted late on such records.
TEST(OutputGrid, EveryRowOfAHundredThousandSamplesIsOnTheGrid) {
  for (const double interval : {0.0, 0.01}) {
    ModelConfig m = load(R"(
building:
  base: {mass: 340 t}
  floors: {count: 1, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: linear, Tb: 2 s}
  damping: {superstructure: {type: modal, ratio: 2 %}}
ground_motion: {pulse: {dt: 1 ms, duration: 99.999 s, t_peak: 4 s}}
analysis: {stepping: fixed, dt: 1 ms}
)");
    m.output.interval = interval;
    const JobResult job = run_job(m);
    ASSERT_EQ(job.motion.acceleration.size(), 100000u);
    const History& h = job.analysis.history;
    const double step = interval > 0 ? interval : 1e-3;
    const std::size_t expected = interval > 0 ? 10000 : 100000;  // 0 .. 99.99 or 99.999 s
    ASSERT_EQ(h.rows(), expected) << "interval " << interval;
    const std::size_t cols = h.columns.size();
    for (std::size_t k = 0; k < h.rows(); ++k)
      ASSERT_EQ(h.values[k * cols], static_cast<double>(k) * step) << "row " << k;
  }
}

// A sink sees the rows as they come: the analysis keeps none of them.
TEST(OutputGrid, RowsStreamToASinkAndAreNotKept) {
  struct Counter : HistorySink {
    std::size_t columns = 0, rows = 0;
    double last_time = -1.0;
    void begin(const std::vector<std::string>& c) override { columns = c.size(); }
    void row(const double* values, std::size_t count) override {
      EXPECT_EQ(count, columns);
      EXPECT_GT(values[0], last_time);
      last_time = values[0];
      ++rows;
    }
  } sink;
  const ModelConfig m = load(R"(
building:
  base: {mass: 340 t}
  floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
ground_motion: {pulse: {dt: 0.01 s, duration: 10 s}}
)");
  const JobResult job = run_job(m, &sink);
  EXPECT_EQ(sink.rows, 1001u);
  EXPECT_EQ(job.analysis.history.rows(), 0u);
}

constexpr const char* kThreeStorey = R"(
building:
  name: main
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: bouc_wen, Tb: 2 s, QW: 5 %, uy: 1 cm}
  damping: {superstructure: {type: rayleigh, ratio: 2 %, modes: [1, 2]}, isolation: 5 %}
ground_motion: {pulse: {amplitude: 0.8 m/s, period: 1.5 s, dt: 0.005 s, duration: 12 s}}
analysis: {stepping: fixed, dt: 0.005 s}
)";

// Base shear = isolator force + c_b v_base at every row (c_b = 2 xi_b m_tot 2 pi / Tb computed
// here); storey 1 shear = -sum over the floors of m a_abs. Both to 1e-6 of the peak (the CSV is
// not involved: values are doubles).
TEST(OutputShear, BaseShearIsIsolatorPlusDampingAndStoreyShearIsInertiaAbove) {
  const JobResult job = run_job(load(kThreeStorey));
  const History& h = job.analysis.history;
  const double m_total = 340e3 * 3 + 250e3;
  const double c_b = 2 * 0.05 * m_total * 2 * std::numbers::pi / 2.0;
  const int base_shear = column(h, "main base_shear [N]");
  const int story1 = column(h, "main/story 1 shear [N]");
  const int iso = column(h, "main/isolator force [N]");
  const int v_base = column(h, "main/base v [m/s]");
  const double masses[] = {340e3, 340e3, 250e3};
  const double peak_base = job.analysis.base_shear[0].value;
  const double peak_story = job.analysis.story_shear[0].value;
  ASSERT_GT(peak_base, 0.0);
  const std::size_t cols = h.columns.size();
  for (std::size_t r = 0; r < h.rows(); ++r) {
    const double* row = &h.values[r * cols];
    EXPECT_NEAR(row[base_shear], row[iso] + c_b * row[v_base], 1e-6 * peak_base) << "row " << r;
    double inertia = 0.0;
    for (int f = 0; f < 3; ++f)
      inertia +=
          masses[f] * row[column(h, "main/floor " + std::to_string(f + 1) + " a_abs [m/s2]")];
    EXPECT_NEAR(row[story1], -inertia, 1e-6 * peak_story) << "row " << r;
  }
  // The residual isolator displacement is where the base is at the end.
  EXPECT_DOUBLE_EQ(job.analysis.final_displacement[0],
                   h.values[(h.rows() - 1) * cols + column(h, "main/base u [m]")]);
  // Positive and negative peaks bracket the history and one of them is the |x| peak.
  const Peak& base = job.analysis.displacement[0];
  EXPECT_GT(base.positive, 0.0);
  EXPECT_LT(base.negative, 0.0);
  EXPECT_DOUBLE_EQ(base.value, std::max(base.positive, -base.negative));
}

// Studies see the same numbers: storey shear and residual isolator displacement selectors.
TEST(OutputShear, StudySelectorsForShearAndResidual) {
  const JobResult job = run_job(load(kThreeStorey));
  const auto value = [&](const char* text) {
    return evaluate_output(resolve_output(parse_output_selector(text), job.model), job.analysis,
                           job.motion_peaks);
  };
  EXPECT_DOUBLE_EQ(value("story1.shear"), job.analysis.story_shear[0].value);
  EXPECT_DOUBLE_EQ(value("stories.shear"),
                   std::max({job.analysis.story_shear[0].value, job.analysis.story_shear[1].value,
                             job.analysis.story_shear[2].value}));
  EXPECT_DOUBLE_EQ(value("base.residual_displacement"),
                   std::abs(job.analysis.final_displacement[0]));
}

// Walls at floor 3: each wall's critical gap is the floor's own peak towards it in the run without
// walls (the old critical_gap_m reported the base slab's peak for every contact).
TEST(CriticalGap, WallsAtFloorThreeUseThatFloor) {
  std::string text = kThreeStorey;
  text.insert(text.find("ground_motion"),
              "  walls: {gap: 5 cm, level: 3, law: linear, k: 2500 kN/mm}\n");
  const ModelConfig m = load(text);
  const JobResult pounding = run_job(m);
  const UnobstructedResult free = run_unobstructed(m, pounding);
  ModelConfig no_walls = m;
  no_walls.building.walls.clear();
  const JobResult reference = run_job(no_walls);
  const Peak& floor3 = reference.analysis.displacement[3];
  const Peak& base = reference.analysis.displacement[0];
  ASSERT_EQ(free.gaps.size(), 2u);
  for (const ContactGap& g : free.gaps) {
    const bool right = g.label.find("right") != std::string::npos;
    EXPECT_DOUBLE_EQ(g.critical_gap, right ? floor3.positive : -floor3.negative) << g.label;
    EXPECT_NE(g.critical_gap, right ? base.positive : -base.negative) << g.label;
  }
}

// A neighbour: the critical gap is the peak closing u_main - u_neighbour of the floors that meet
// (neighbour on the right), computed here from the two free buildings' histories.
TEST(CriticalGap, NeighbourUsesTheRelativeDisplacementOfTheFloorsThatMeet) {
  const ModelConfig m = load(std::string(kThreeStorey) + R"(
neighbours:
  - side: right
    gap: 2 cm
    impact: {law: linear, k: 2500 kN/mm}
    building:
      name: next
      isolated: false
      floors: {count: 2, mass: 300 t, stiffness: 300 MN/m, height: 3.2 m}
)");
  const JobResult pounding = run_job(m);
  const UnobstructedResult free = run_unobstructed(m, pounding);
  ModelConfig apart = m;
  apart.neighbours[0].pounding = false;
  const JobResult reference = run_job(apart);  // fixed steps = record samples: every step a row
  const History& h = reference.analysis.history;
  const std::size_t cols = h.columns.size();
  ASSERT_EQ(free.gaps.size(), 2u);  // main floors 1 and 2 meet next's floors 1 and 2
  for (int floor = 1; floor <= 2; ++floor) {
    const int a = column(h, "main/floor " + std::to_string(floor) + " u [m]");
    const int b = column(h, "next/floor " + std::to_string(floor) + " u [m]");
    double closing = 0.0;
    for (std::size_t r = 0; r < h.rows(); ++r)
      closing = std::max(closing, h.values[r * cols + a] - h.values[r * cols + b]);
    const ContactGap& g = free.gaps[static_cast<std::size_t>(floor - 1)];
    EXPECT_NE(g.label.find("floor " + std::to_string(floor)), std::string::npos) << g.label;
    EXPECT_NEAR(g.critical_gap, closing, 1e-12) << g.label;
    EXPECT_GT(closing, 0.0);
  }
}

// --- exit codes as documented: 0 ok, 2 bad input (also usage errors), 3 diverged, 1 other ---

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("isopound-exit-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(ExitCodes, UsageErrorsAreBadInput) {
  EXPECT_EQ(test::run_isopound("run --no-such-flag x.yaml").exit_code, 2);
  EXPECT_EQ(test::run_isopound("frobnicate").exit_code, 2);
  EXPECT_EQ(test::run_isopound("").exit_code, 2);
  EXPECT_EQ(test::run_isopound("sweep").exit_code, 2);
  EXPECT_EQ(test::run_isopound("--help").exit_code, 0);
  const test::CommandResult v = test::run_isopound("--version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_NE(v.output.find("isopound 0."), std::string::npos) << v.output;
}

TEST(ExitCodes, FixedStepLongerThanTheRecordIntervalIsBadInput) {
  const fs::path dir = scratch("dt");
  std::ofstream(dir / "m.yaml") << "building:\n  base: {mass: 340 t}\n"
                                   "  floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, "
                                   "height: 3 m}\nanalysis: {stepping: fixed, dt: 10 s}\n";
  for (const std::string& verb :
       {std::string("check -q"), "run -q -o '" + (dir / "out").string() + "'"}) {
    const test::CommandResult c = test::run_isopound(verb + " '" + (dir / "m.yaml").string() + "'");
    EXPECT_EQ(c.exit_code, 2) << verb << ": " << c.output;
    EXPECT_NE(c.output.find("analysis.dt"), std::string::npos) << c.output;
  }
  fs::remove_all(dir);
}

TEST(ExitCodes, OutputDirectoryThatCannotBeMadeIsAPlainMessage) {
  const fs::path dir = scratch("outdir");
  std::ofstream(dir / "file") << "x";
  const test::CommandResult c =
      test::run_isopound("demo -q -o '" + (dir / "file" / "sub").string() + "'");
  EXPECT_EQ(c.exit_code, 1) << c.output;
  EXPECT_NE(c.output.find("cannot create the output directory"), std::string::npos) << c.output;
  fs::remove_all(dir);
}

// Every run of this sweep diverges: the sweep must fail, say how many and where the messages are.
TEST(ExitCodes, SweepWithFailedRunsIsNotASuccess) {
  const fs::path dir = scratch("sweep");
  std::ofstream(dir / "m.yaml") << "building:\n  base: {mass: 340 t}\n"
                                   "  floors: {count: 3, mass: 340 t, roof_mass: 250 t, "
                                   "stiffness: 600 MN/m, height: 3.2 m}\n"
                                   "ground_motion:\n  pulse: {amplitude: 100000 m/s}\n";
  std::ofstream(dir / "s.yaml") << "name: failing\nmodel: m.yaml\naxes:\n"
                                   "  - {path: building.isolator.Tb, values: [2 s, 2.5 s]}\n"
                                   "outputs: [base.displacement]\n";
  const test::CommandResult c = test::run_isopound("sweep -q -j 1 '" + (dir / "s.yaml").string() +
                                                   "' --db '" + (dir / "s.db").string() + "'");
  EXPECT_NE(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find("2 of 2 runs failed"), std::string::npos) << c.output;
  EXPECT_NE(c.output.find("error"), std::string::npos) << c.output;
  fs::remove_all(dir);
}

// Study tables say their units: units.csv from the export and a units table in the database.
TEST(StudyUnits, EveryColumnOfTheTablesHasAUnit) {
  const fs::path dir = scratch("units");
  std::ofstream(dir / "s.yaml")
      << "name: units\nmodel: " + (test::source_dir() / "configs" / "tutorial.yaml").string() +
             "\nset:\n  ground_motion.pulse: {duration: 2 s, dt: 0.01 s}\n"
             "axes:\n  - {path: building.isolator.uy, values: [1 cm, "
             "2 cm]}\noutputs: {u: base.displacement, V1: story1.shear, "
             "zeta: isolator.z, ratio: story1.drift_ratio}\n";
  const test::CommandResult c =
      test::run_isopound("sweep -q -j 1 '" + (dir / "s.yaml").string() + "' --db '" +
                         (dir / "s.db").string() + "' --export '" + (dir / "csv").string() + "'");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  std::ifstream in(dir / "csv" / "units.csv");
  std::stringstream text;
  text << in.rdbuf();
  for (const char* row : {"runs,uy,SI", "runs,u,m", "runs,V1,N", "runs,zeta,-", "runs,ratio,-"})
    EXPECT_NE(text.str().find(row), std::string::npos) << row << " in\n" << text.str();
  EXPECT_FALSE(fs::exists(dir / "s.db.lock"));  // a clean finish leaves no lock file
  fs::remove_all(dir);
}

}  // namespace
}  // namespace isopound
