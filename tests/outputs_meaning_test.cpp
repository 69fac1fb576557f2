// Outputs that mean what they say (issue 24, item 4): history rows exactly on k * interval for
// any interval (sampled from the Newmark solution inside a step), early and clipped ends of the
// analysis stated on the console and in summary.json.
#include <gtest/gtest.h>

#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "solver/io/model_input.h"
#include "solver/io/report.h"
#include "solver/structures/job.h"
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

// A 2-storey isolated building under a pulse sampled at 5 ms, fixed steps of `dt`.
ModelConfig two_storey(const std::string& dt, double interval) {
  ModelConfig m = load(R"(
building:
  name: main
  base: {mass: 340 t}
  floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: bouc_wen, Tb: 2 s, QW: 5 %, uy: 1 cm}
ground_motion: {pulse: {amplitude: 0.8 m/s, period: 1.5 s, dt: 5 ms, duration: 6 s}}
analysis: {stepping: fixed, dt: )" +
                       dt + R"(}
)");
  m.output.interval = interval;
  return m;
}

// The reproduction: interval 3 ms with 5 ms steps gave rows at 0, 0.005, 0.0075, ... while the
// console said "output every 0.003 s". Now every row is at exactly k * 0.003 s, none missing.
TEST(OutputSampling, RowsAreOnKTimesAnIntervalThatIsNotAMultipleOfTheStep) {
  const JobResult job = run_job(two_storey("5 ms", 0.003));
  const History& h = job.analysis.history;
  const std::size_t cols = h.columns.size();
  ASSERT_EQ(h.rows(), 2001u);  // 0, 0.003, ..., 6.000 s
  for (std::size_t k = 0; k < h.rows(); ++k)
    ASSERT_EQ(h.values[k * cols], static_cast<double>(k) * 0.003) << "row " << k;
}

// The rows inside a step follow the Newmark solution of that step (v linear, u from the average
// acceleration), computed here from the run's own step ends (every step written with interval
// 5 ms), and they converge to a run whose steps end on the grid: 1 ms steps, where 3 ms rows are
// step ends. The sampled u is much closer to that run than a linear interpolation of u would be.
TEST(OutputSampling, RowsInsideAStepFollowTheNewmarkSolution) {
  const JobResult sampled = run_job(two_storey("5 ms", 0.003));
  const JobResult ends = run_job(two_storey("5 ms", 0.005));
  const JobResult fine = run_job(two_storey("1 ms", 0.003));
  const History& hs = sampled.analysis.history;
  const History& he = ends.analysis.history;
  const History& hf = fine.analysis.history;
  const std::size_t cols = hs.columns.size();
  ASSERT_EQ(he.columns, hs.columns);
  ASSERT_EQ(hf.rows(), hs.rows());
  const int u = column(hs, "main/floor 2 u [m]");
  const int v = column(hs, "main/floor 2 v [m/s]");
  const int force = column(hs, "main/isolator force [N]");
  double peak_u = 0.0, error_newmark = 0.0, error_linear = 0.0, error_fine = 0.0;
  for (std::size_t k = 0; k < hs.rows(); ++k) {
    const double t = static_cast<double>(k) * 0.003;
    const std::size_t j = static_cast<std::size_t>(std::floor(t / 0.005 + 1e-9));
    const double* row = &hs.values[k * cols];
    const double* a = &he.values[j * cols];
    peak_u = std::max(peak_u, std::abs(row[u]));
    if (std::abs(a[0] - t) < 1e-12) {  // on a step end: that step's values, bit for bit
      for (std::size_t c = 1; c < cols; ++c) ASSERT_EQ(row[c], a[c]) << "row " << k;
      continue;
    }
    const double* b = &he.values[(j + 1) * cols];
    const double s = (t - a[0]) / (b[0] - a[0]);
    const double v_t = a[v] + s * (b[v] - a[v]);
    const double u_t = a[u] + 0.5 * (t - a[0]) * (a[v] + v_t);
    EXPECT_NEAR(row[v], v_t, 1e-12 * std::abs(b[v] - a[v]) + 1e-15) << "row " << k;
    EXPECT_NEAR(row[u], u_t, 1e-9 * std::abs(b[u] - a[u]) + 1e-15) << "row " << k;
    EXPECT_NEAR(row[force], a[force] + s * (b[force] - a[force]),
                1e-9 * std::abs(b[force] - a[force]) + 1e-9)
        << "row " << k;
    const double u_fine = hf.values[k * cols + u];
    error_newmark = std::max(error_newmark, std::abs(row[u] - u_fine));
    error_linear = std::max(error_linear, std::abs(a[u] + s * (b[u] - a[u]) - u_fine));
    error_fine = std::max(error_fine, std::abs(row[u] - u_fine));
  }
  ASSERT_GT(peak_u, 0.05);
  // The 5 ms and 1 ms solutions differ by the integrator's own error (O(h^2)); the sampling
  // adds little to it.
  EXPECT_LT(error_fine, 1e-3 * peak_u);
  EXPECT_LT(error_newmark, error_linear);
}

// A 3-storey isolated building pounding Kelvin-Voigt moat walls 5 cm away under an 8 s pulse.
ModelConfig pounding_three_storey() {
  return load(R"(
building:
  name: main
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: bouc_wen, Tb: 2 s, QW: 5 %, uy: 1 cm}
  walls: {gap: 5 cm, law: kelvin_voigt, k: 2500 kN/mm, e: 0.7, mass: 500 t}
ground_motion: {pulse: {amplitude: 0.8 m/s, period: 1.5 s, dt: 5 ms, duration: 8 s}}
)");
}

// Adaptive stepping with contacts (steps cut at events, of any length): still k * interval.
TEST(OutputSampling, AdaptiveSteppingWithImpactsStaysOnTheGrid) {
  ModelConfig m = pounding_three_storey();
  m.output.interval = 0.007;
  const JobResult job = run_job(m);
  const History& h = job.analysis.history;
  const std::size_t cols = h.columns.size();
  ASSERT_GT(job.analysis.stats.rejected_steps, 0);  // events cut steps
  ASSERT_EQ(h.rows(), static_cast<std::size_t>(std::floor(8.0 / 0.007)) + 1);
  for (std::size_t k = 0; k < h.rows(); ++k)
    ASSERT_EQ(h.values[k * cols], static_cast<double>(k) * 0.007) << "row " << k;
}

// Counts and 0/1 states change only where a step ends (an onset ends its step): a row inside a
// step holds them at the step's start. Interpolated, XY-5's wall contacts read in_contact
// 0.924 at 4.4604 s (12 such values to 4.6 s with rows every 0.7 ms), and a count could read
// 6.36 impacts. Every such column must hold integers, and a count must never decrease.
void expect_counts_and_states_held(const JobResult& job) {
  const History& h = job.analysis.history;
  const std::size_t cols = h.columns.size();
  int count_columns = 0, state_columns = 0;
  for (const auto& e : job.model.elements)
    for (int k = 0; k < e->output_count(); ++k) {
      const Element::OutputKind kind = e->output_kind(k);
      if (kind == Element::OutputKind::kContinuous) continue;
      const std::size_t c = static_cast<std::size_t>(
          column(h, e->label() + " " + e->output_name(k) + " [" + e->output_unit(k) + "]"));
      (kind == Element::OutputKind::kCount ? count_columns : state_columns) += 1;
      double previous = 0.0;
      for (std::size_t r = 0; r < h.rows(); ++r) {
        const double v = h.values[r * cols + c];
        ASSERT_EQ(v, std::round(v)) << h.columns[c] << " at " << h.values[r * cols] << " s";
        if (kind == Element::OutputKind::kCount)
          ASSERT_GE(v, previous) << h.columns[c] << " at " << h.values[r * cols] << " s";
        else
          ASSERT_TRUE(v == 0.0 || v == 1.0) << h.columns[c] << " at " << h.values[r * cols];
        previous = v;
      }
    }
  EXPECT_GT(count_columns, 0);
}

TEST(OutputSampling, CountsInsideAStepAreHeldNotInterpolated) {
  ModelConfig m = pounding_three_storey();
  m.output.interval = 0.0007;  // rows inside the steps of every impact
  const JobResult job = run_job(m);
  expect_counts_and_states_held(job);
  // And the last row's counts are the summary's.
  const History& h = job.analysis.history;
  for (const auto& e : job.model.elements)
    if (e->output_count() > 2 && e->output_name(2) == "impacts") {
      const int c = column(h, e->label() + " impacts [-]");
      EXPECT_EQ(h.values[(h.rows() - 1) * h.columns.size() + static_cast<std::size_t>(c)],
                e->output(2));
      EXPECT_GT(e->output(2), 0.0) << e->label();
    }
}

TEST(OutputSampling, ThreeDimensionalCountsAndSlipStatesAreHeld) {
  ISOPOUND_REQUIRE_RECORDS();
  ModelConfig m = test::load_shipped_config("3d-xy5.yaml");
  m.analysis.t_end = 4.6;  // the first impacts on the walls, with friction
  m.output.interval = 0.0007;
  expect_counts_and_states_held(run_job(m));
}

// t_end before the record's end: the run says it stopped early; after it: clipped, said so.
TEST(AnalysisEnd, EarlyStopAndClippedEndAreInSummaryJson) {
  ModelConfig m = two_storey("5 ms", 0.0);
  m.output.histories = false;
  {
    const JobResult job = run_job(m);
    const nlohmann::json end = summary_json(m, job)["end_of_analysis"];
    EXPECT_EQ(end["stopped_by"], "end of record + extra_time");
    EXPECT_EQ(end["clipped"], false);
    EXPECT_TRUE(end["requested_end_s"].is_null());
    EXPECT_EQ(end["note"], "");
  }
  m.analysis.t_end = 2.5;
  {
    const JobResult job = run_job(m);
    const nlohmann::json end = summary_json(m, job)["end_of_analysis"];
    EXPECT_EQ(end["stopped_by"], "t_end");
    EXPECT_DOUBLE_EQ(end["analysed_time_s"].get<double>(), 2.5);
    EXPECT_NEAR(end["record_end_s"].get<double>(), 6.0, 1e-9);
    EXPECT_NE(end["note"].get<std::string>().find("stopped early"), std::string::npos);
    std::ostringstream console;
    print_summary(console, m, job);
    EXPECT_NE(console.str().find("stopped early at t_end = 2.5 s"), std::string::npos)
        << console.str();
  }
  m.analysis.t_end = 60.0;
  {
    const JobResult job = run_job(m);
    const nlohmann::json end = summary_json(m, job)["end_of_analysis"];
    EXPECT_EQ(end["clipped"], true);
    EXPECT_EQ(end["stopped_by"], "end of record + extra_time");
    EXPECT_DOUBLE_EQ(end["requested_end_s"].get<double>(), 60.0);
    EXPECT_NEAR(end["analysed_time_s"].get<double>(), 6.0, 1e-9);
    std::ostringstream console;
    print_summary(console, m, job);
    EXPECT_NE(console.str().find("t_end = 60 s (analysis.t_end or --until) is past the end"),
              std::string::npos)
        << console.str();
  }
}

// The same through the command line: --until before and past the end of the record.
TEST(AnalysisEnd, UntilIsStatedOnTheConsole) {
  const fs::path dir = fs::temp_directory_path() / ("isopound-end-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string model = (test::source_dir() / "configs" / "tutorial.yaml").string();
  test::CommandResult c = test::run_isopound("run '" + model + "' --no-histories --until 1.5 -o '" +
                                             (dir / "a").string() + "'");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find("stopped early at t_end = 1.5 s"), std::string::npos) << c.output;
  c = test::run_isopound("run '" + model + "' --no-histories --until 1000 -o '" +
                         (dir / "b").string() + "'");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find("is past the end of the record"), std::string::npos) << c.output;
  std::ifstream summary(dir / "b" / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(summary);
  EXPECT_EQ(j["end_of_analysis"]["clipped"], true);
  fs::remove_all(dir);
}

constexpr const char* kWallsAtTheBase = R"(
building:
  name: main
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: bouc_wen, Tb: 2 s, QW: 5 %, uy: 1 cm}
  walls: {gap: 5 cm, law: kelvin_voigt, k: 2500 kN/mm, e: 0.7, mass: 500 t}
ground_motion: {pulse: {amplitude: 0.8 m/s, period: 1.5 s, dt: 5 ms, duration: 8 s}}
analysis: {stepping: fixed, dt: 1 ms}
)";

// With moat walls at the base the base shear is what reaches the foundation: isolator +
// damping + wall forces, which by the structure's equilibrium is -sum of m a_abs over all its
// levels (computed here from the histories) at every row. Before, the wall force was left out
// and storey 1 carried several times the printed base shear.
TEST(OutputBaseShear, IncludesTheWallForcesAtTheBase) {
  const JobResult job = run_job(load(kWallsAtTheBase));
  const History& h = job.analysis.history;
  const std::size_t cols = h.columns.size();
  const int base_shear = column(h, "main base_shear [N]");
  const char* levels[] = {"main/base", "main/floor 1", "main/floor 2", "main/floor 3"};
  const double masses[] = {340e3, 340e3, 340e3, 250e3};
  double peak_wall = 0.0;
  for (const auto& element : job.model.elements)
    if (element->label().find("/wall") != std::string::npos) {
      const std::size_t e = static_cast<std::size_t>(&element - &job.model.elements[0]);
      peak_wall = std::max(peak_wall, job.analysis.element_outputs[e][0].value);
    }
  ASSERT_GT(peak_wall, 1e6);  // it pounds, hard
  const double peak = job.analysis.base_shear[0].value;
  ASSERT_GT(peak, peak_wall);
  for (std::size_t r = 0; r < h.rows(); ++r) {
    const double* row = &h.values[r * cols];
    double inertia = 0.0;
    for (int l = 0; l < 4; ++l)
      inertia += masses[l] * row[column(h, std::string(levels[l]) + " a_abs [m/s2]")];
    ASSERT_NEAR(row[base_shear], -inertia, 1e-6 * peak) << "row " << r;
  }
  EXPECT_GE(peak, job.analysis.story_shear[0].value);  // the base carries storey 1 and more
}

// A neighbour's base slab pounding ours at the base level is in both buildings' base shear. The
// floors of a pounding pair stand at equal levels (site checks) and pound too: the base shear is
// the building's inertia less those floor contacts, which do not reach its foundation.
TEST(OutputBaseShear, IncludesANeighbourBaseSlabContact) {
  const ModelConfig m = load(R"(
building:
  name: main
  base: {mass: 340 t}
  floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: linear, Tb: 2 s}
neighbours:
  - side: right
    gap: 2 cm
    building:
      name: other
      base: {mass: 340 t}
      floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
      isolator: {model: linear, Tb: 3 s}
    impact: {law: linear, k: 2500 kN/mm}
ground_motion: {pulse: {amplitude: 0.8 m/s, period: 1.5 s, dt: 5 ms, duration: 8 s}}
analysis: {stepping: fixed, dt: 1 ms}
)");
  const JobResult job = run_job(m);
  const History& h = job.analysis.history;
  const std::size_t cols = h.columns.size();
  for (const char* name : {"main", "other"}) {
    const int base_shear = column(h, std::string(name) + " base_shear [N]");
    const double peak = job.analysis.base_shear[name == std::string("main") ? 0 : 1].value;
    ASSERT_GT(peak, 0.0);
    double worst = 0.0;
    for (std::size_t r = 0; r < h.rows(); ++r) {
      const double* row = &h.values[r * cols];
      double inertia = 0.0;
      for (const char* level : {"/base", "/floor 1", "/floor 2"})
        inertia += 340e3 * row[column(h, std::string(name) + level + " a_abs [m/s2]")];
      // The floors pound too (pounding pairs stand at equal levels): their contact forces push
      // the building from outside above the base and do not reach its foundation. A contact
      // force F >= 0 pushes the left building (main) towards -x and the right one towards +x.
      double floor_contacts = 0.0;
      for (const char* level : {"/floor 1", "/floor 2"})
        floor_contacts += row[column(h, std::string("main~other") + level + " force [N]")];
      const double on_building = name == std::string("main") ? -floor_contacts : floor_contacts;
      worst = std::max(worst, std::abs(row[base_shear] + inertia - on_building));
    }
    EXPECT_LT(worst, 1e-6 * peak) << name;
  }
}

// Without walls or neighbours, --compare-unobstructed says there is nothing to compare (it
// printed x1.00 everywhere), in the console and in summary.json.
TEST(Unobstructed, NothingToCompareIsSaid) {
  const fs::path dir =
      fs::temp_directory_path() / ("isopound-nothing-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string model = (dir / "free.yaml").string();
  std::ofstream(model) << "building:\n  base: {mass: 340 t}\n"
                          "  floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}\n"
                          "ground_motion: {pulse: {dt: 0.01 s, duration: 4 s}}\n";
  const test::CommandResult c = test::run_isopound(
      "run '" + model + "' --no-histories --compare-unobstructed -o '" + dir.string() + "'");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find("nothing to compare"), std::string::npos) << c.output;
  EXPECT_EQ(c.output.find("(x1.00)"), std::string::npos) << c.output;
  std::ifstream summary(dir / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(summary);
  EXPECT_NE(j["unobstructed"]["note"].get<std::string>().find("nothing to compare"),
            std::string::npos);
  EXPECT_FALSE(j["unobstructed"].contains("levels"));
  fs::remove_all(dir);
}

// 2D neighbours get amplifications too: every level and storey of the neighbour, each the ratio
// of its peak with and without pounding (looked up here by label in the two runs).
TEST(Unobstructed, NeighboursGetAmplifications) {
  const ModelConfig m = load(R"(
building:
  name: main
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: bouc_wen, Tb: 2 s, QW: 5 %, uy: 1 cm}
neighbours:
  - side: right
    gap: 5 cm
    building:
      name: other
      isolated: false
      floors: {count: 4, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
    impact: {law: kelvin_voigt, k: 2500 kN/mm, e: 0.7}
ground_motion: {pulse: {amplitude: 0.8 m/s, period: 1.5 s, dt: 5 ms, duration: 8 s}}
output: {histories: false}
)");
  const JobResult job = run_job(m);
  const UnobstructedResult free = run_unobstructed(m, job);
  const nlohmann::json u = summary_json(m, job, &free)["unobstructed"];
  ASSERT_EQ(u["buildings"].size(), 2u);
  EXPECT_EQ(u["buildings"][0]["levels"], u["levels"]);  // the old keys: the main building
  const nlohmann::json& other = u["buildings"][1];
  EXPECT_EQ(other["name"], "other");
  ASSERT_EQ(other["levels"].size(), 4u);
  ASSERT_EQ(other["stories"].size(), 4u);
  const auto dof = [](const Model& model, const std::string& label) {
    for (int i = 0; i < model.size(); ++i)
      if (model.dofs[i].label == label) return i;
    return -1;
  };
  bool amplified = false;
  for (const auto& level : other["levels"]) {
    const std::string label = level["label"];
    const int with = dof(job.model, label), without = dof(free.job.model, label);
    ASSERT_GE(with, 0);
    ASSERT_GE(without, 0);
    const double ratio =
        job.analysis.displacement[with].value / free.job.analysis.displacement[without].value;
    EXPECT_DOUBLE_EQ(level["displacement_amplification"].get<double>(), ratio) << label;
    amplified = amplified || std::abs(ratio - 1.0) > 0.01;
  }
  EXPECT_TRUE(amplified);  // pounding changes the neighbour's response
  std::ostringstream console;
  print_unobstructed(console, m, job, free);
  EXPECT_NE(console.str().find("other/floor 4"), std::string::npos) << console.str();
  EXPECT_NE(console.str().find("other/story 4"), std::string::npos) << console.str();
}

// Computed defaults are printed with the value they gave, never as 0.
TEST(ComputedDefaults, CarriedMassAndRigidWallAndIntervalsHaveTheirValues) {
  ModelConfig m = load(R"(
building:
  name: main
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
  isolator: {model: bouc_wen, Tb: 2 s, QW: 5 %, uy: 1 cm}
  walls: {gap: 20 cm, law: kelvin_voigt, k: 2500 kN/mm, e: 0.7, mass: 500 t}
ground_motion: {pulse: {amplitude: 0.8 m/s, period: 1.5 s, dt: 5 ms, duration: 4 s}}
)");
  const JobResult job = run_job(m);
  std::ostringstream console;
  print_summary(console, m, job);
  const std::string text = console.str();
  EXPECT_NE(text.find("building.isolator.carried_mass = 1.27e+06 kg (computed"), std::string::npos)
      << text;
  EXPECT_NE(text.find("stiffness = rigid"), std::string::npos) << text;
  EXPECT_NE(text.find("output.interval = 0.005 s (computed"), std::string::npos) << text;
  EXPECT_EQ(text.find(" = 0 kg"), std::string::npos) << text;
  EXPECT_EQ(text.find(" = 0 N/m"), std::string::npos) << text;
  const nlohmann::json settings = summary_json(m, job)["settings"]["defaults_used"];
  EXPECT_NE(settings["building.isolator.carried_mass"].get<std::string>().find("1.27e+06 kg"),
            std::string::npos);
}

// 3D: the bearings' share of the mass and the polar moments from the plan (eq. 5.9), computed
// here for the thesis building's square 16.5 m plan (configs/tutorial-3d.yaml):
// J = m (a^2 + a^2) / 12.
TEST(ComputedDefaults, BearingShareAndPolarMomentIn3D) {
  const std::string model = (test::source_dir() / "configs" / "tutorial-3d.yaml").string();
  const test::CommandResult c = test::run_isopound("check '" + model + "'");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  EXPECT_EQ(c.output.find(" = 0 kg"), std::string::npos) << c.output;
  EXPECT_EQ(c.output.find("polar_moment = 0"), std::string::npos) << c.output;
  char share[64], base_j[64];
  std::snprintf(share, sizeof share, "%.6g kg", (340e3 * 3 + 250e3) / 16);
  std::snprintf(base_j, sizeof base_j, "%.6g kg m2", 340e3 * 2 * 16.5 * 16.5 / 12);
  EXPECT_NE(c.output.find(share), std::string::npos) << share << "\n" << c.output;
  EXPECT_NE(c.output.find(base_j), std::string::npos) << base_j << "\n" << c.output;
}

// 3D: the base shear has x, y and a resultant. Without damping (so that nothing but the
// bearings reaches the ground) its x and y components equal the sums of the bearings' own
// forces, read here from their history columns, at every row.
TEST(OutputBaseShear, ThreeDimensionalHasXYAndResultant) {
  YAML::Node root = YAML::LoadFile((test::source_dir() / "configs" / "tutorial-3d.yaml").string());
  root["structures"][0]["damping"] = YAML::Load("{type: none}");
  root["ground_motion"]["L"]["pulse"]["duration"] = "6 s";
  root["ground_motion"]["T"]["pulse"]["duration"] = "6 s";
  const ModelConfig m = load_model(root, "tutorial-3d.yaml", "");
  const JobResult job = run_job(m);
  const History& h = job.analysis.history;
  const std::size_t cols = h.columns.size();
  const int x = column(h, "building base_shear [N]");
  const int y = column(h, "building base_shear_y [N]");
  std::vector<int> fx, fy;
  for (std::size_t c = 0; c < cols; ++c) {
    const std::string& name = h.columns[c];
    if (name.find(" force_x [N]") != std::string::npos) fx.push_back(static_cast<int>(c));
    if (name.find(" force_y [N]") != std::string::npos) fy.push_back(static_cast<int>(c));
  }
  ASSERT_EQ(fx.size(), 16u);
  ASSERT_EQ(fy.size(), 16u);
  const double peak = job.analysis.base_shear_resultant[0].value;
  ASSERT_GT(job.analysis.base_shear[0].value, 0.1 * peak);
  ASSERT_GT(job.analysis.base_shear_y[0].value, 0.1 * peak);  // 30 degrees: both directions
  double peak_resultant = 0.0;
  for (std::size_t r = 0; r < h.rows(); ++r) {
    const double* row = &h.values[r * cols];
    double sx = 0.0, sy = 0.0;
    for (const int c : fx) sx += row[c];
    for (const int c : fy) sy += row[c];
    ASSERT_NEAR(row[x], sx, 1e-6 * peak) << "row " << r;
    ASSERT_NEAR(row[y], sy, 1e-6 * peak) << "row " << r;
    peak_resultant = std::max(peak_resultant, std::hypot(row[x], row[y]));
  }
  EXPECT_LE(peak_resultant, peak * (1 + 1e-12));  // rows sample the steps' peak
  const nlohmann::json b = summary_json(m, job)["buildings_3d"][0]["base_shear"];
  EXPECT_DOUBLE_EQ(b["resultant"]["value"].get<double>(), peak);
}

}  // namespace
}  // namespace isopound
