// End-to-end tests of the isopound binary: exit codes and located messages for bad input,
// the demo's files, a diverging analysis, the modes command.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "tests/test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

using Command = test::CommandResult;

Command run(const std::string& args) {
  return test::run_isopound(args);
}

fs::path scratch_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("isopound-cli-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(CliBadInput, EveryMalformedModelExitsNonZeroWithFileLineAndKey) {
  const fs::path dir = test::source_dir() / "tests" / "data" / "bad_models";
  int count = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    const std::string name = entry.path().filename().string();
    for (const char* verb : {"check", "run -q --no-histories -o /tmp/isopound-cli-never"}) {
      const Command c = run(std::string(verb) + " '" + entry.path().string() + "'");
      EXPECT_EQ(c.exit_code, 2) << name << ": " << c.output;
      // "name.yaml:LINE:COL: key.path: what". A YAML syntax error has a line but no key; an
      // empty document has neither.
      const std::string escaped = std::regex_replace(name, std::regex(R"(\.)"), R"(\.)");
      std::string pattern = escaped + R"(:[1-9][0-9]*:[0-9]+: [A-Za-z_]+[A-Za-z_0-9.\[\]]*: )";
      if (name == "syntax_error.yaml") pattern = escaped + R"(:[1-9][0-9]*:[0-9]+: YAML syntax)";
      if (name == "empty.yaml") pattern = escaped + R"(: the document is empty)";
      const std::regex located(pattern);
      EXPECT_TRUE(std::regex_search(c.output, located)) << name << ": " << c.output;
      EXPECT_EQ(c.output.find("nan"), std::string::npos) << name;
    }
  }
  EXPECT_GE(count, 10);
}

TEST(CliBadInput, MissingModelFileAndUnknownSubcommand) {
  Command c = run("run /nonexistent/model.yaml");
  EXPECT_EQ(c.exit_code, 2);
  EXPECT_NE(c.output.find("/nonexistent/model.yaml"), std::string::npos) << c.output;
  c = run("frobnicate");
  EXPECT_NE(c.exit_code, 0);
}

TEST(CliBadInput, TruncatedRecordNamesItsFileAndLine) {
  const fs::path dir = scratch_dir("truncated");
  std::ofstream(dir / "short.AT2") << "PEER NGA STRONG MOTION DATABASE RECORD\nx\n"
                                      "ACCELERATION TIME SERIES IN UNITS OF G\n"
                                      "NPTS=   10, DT=   .0050 SEC\n  .1E-01  .2E-01  .3E-01\n";
  std::ofstream(dir / "model.yaml") << "building:\n  base: {mass: 340 t}\n"
                                       "  floors: {count: 3, mass: 340 t, roof_mass: 250 t, "
                                       "stiffness: 600 MN/m, height: 3.2 m}\n"
                                       "ground_motion:\n  record: short.AT2\n";
  const Command c =
      run("run -q '" + (dir / "model.yaml").string() + "' -o '" + (dir / "out").string() + "'");
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_NE(c.output.find("short.AT2:5:"), std::string::npos) << c.output;
  fs::remove_all(dir);
}

TEST(CliDivergence, StopsWithTimeAndDof) {
  // A scale factor of 1e5 on the pulse drives the building far beyond any physical response:
  // the run must stop with the time, the DOF and a hint, exit code 3, and no output file.
  const fs::path dir = scratch_dir("diverge");
  std::ofstream(dir / "model.yaml") << "building:\n  base: {mass: 340 t}\n"
                                       "  floors: {count: 3, mass: 340 t, roof_mass: 250 t, "
                                       "stiffness: 600 MN/m, height: 3.2 m}\n"
                                       "ground_motion:\n  pulse: {amplitude: 100000 m/s}\n";
  const Command c =
      run("run '" + (dir / "model.yaml").string() + "' -o '" + (dir / "out").string() + "'");
  EXPECT_EQ(c.exit_code, 3) << c.output;
  EXPECT_TRUE(std::regex_search(
      c.output,
      std::regex(
          R"(diverged at t = [0-9.e+-]+ s, DOF '3-storey|diverged at t = [0-9.e+-]+ s, DOF 'building)")))
      << c.output;
  EXPECT_NE(c.output.find("Hint"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json"));
  fs::remove_all(dir);
}

// `isopound demo --2d` without -o writes into its own folder: into the 3D demo's isopound-out/ it
// replaced summary.json and histories.csv and left the 3D pictures and animation beside them.
TEST(CliDemo, TwoDimensionalDemoKeepsOutOfTheThreeDimensionalDemosFolder) {
  const fs::path dir = scratch_dir("demo-folder");
  const Command c = test::run_command("cd '" + dir.string() + "' && '" +
                                      std::string(ISOPOUND_BINARY) + "' demo --2d -q");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  EXPECT_TRUE(fs::exists(dir / "isopound-out-2d" / "summary.json"));
  EXPECT_FALSE(fs::exists(dir / "isopound-out"));
  fs::remove_all(dir);
}

TEST(CliDemo, TwoDimensionalDemoWritesSummaryAndHistoriesWithConsistentPeaks) {
  const fs::path dir = scratch_dir("demo");
  const Command c = run("demo --2d -o '" + dir.string() + "'");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find("displacement"), std::string::npos);
  std::ifstream in(dir / "summary.json");
  ASSERT_TRUE(in.good());
  const nlohmann::json s = nlohmann::json::parse(in);
  const double base = s["structures"][0]["base_displacement_m"].get<double>();
  EXPECT_GT(base, 0.05);
  EXPECT_LT(base, 2.0);
  EXPECT_LT(s["energy"]["relative_error"].get<double>(), 1e-3);
  EXPECT_GT(s["statistics"]["steps"].get<long>(), 1000);
  ASSERT_EQ(s["structures"][0]["stories"].size(), 3u);

  // histories.csv: the base displacement column's max |u| must not exceed the summary's peak
  // (peaks are taken at every step, histories at the output interval) and come within 1 %.
  std::ifstream csv(dir / "histories.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("time [s],ground_acceleration [m/s2],3-storey/base u [m]", 0), 0u)
      << header;
  double max_u = 0.0;
  std::size_t rows = 0;
  while (std::getline(csv, line)) {
    std::size_t p1 = line.find(','), p2 = line.find(',', p1 + 1), p3 = line.find(',', p2 + 1);
    max_u = std::max(max_u, std::abs(std::stod(line.substr(p2 + 1, p3 - p2 - 1))));
    ++rows;
  }
  EXPECT_GT(rows, 100u);
  EXPECT_LE(max_u, base * (1 + 1e-12));
  EXPECT_GT(max_u, 0.99 * base);
  fs::remove_all(dir);
}

TEST(CliModes, ThesisBuildingPeriods) {
  const Command c =
      run("modes '" + (test::source_dir() / "configs" / "tutorial.yaml").string() + "'");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find("0.3115"), std::string::npos) << c.output;  // fixed-base T1
  EXPECT_NE(c.output.find("2.0166"), std::string::npos) << c.output;  // isolated, K_post
}

TEST(CliRun, ThesisConfigsRunOnTheirRecord) {
  ISOPOUND_REQUIRE_RECORDS();
  for (const char* name : {"thesis-3storey-bw.yaml", "thesis-5storey-bl.yaml"}) {
    const fs::path dir = scratch_dir("thesis");
    const Command c = run("run -q '" + (test::source_dir() / "configs" / name).string() + "' -o '" +
                          dir.string() + "'");
    ASSERT_EQ(c.exit_code, 0) << name << ": " << c.output;
    std::ifstream in(dir / "summary.json");
    const nlohmann::json s = nlohmann::json::parse(in);
    EXPECT_NEAR(s["ground_motion"]["pga_g"].get<double>(), 0.623, 0.0006) << name;
    EXPECT_GT(s["structures"][0]["base_displacement_m"].get<double>(), 0.1) << name;
    fs::remove_all(dir);
  }
}

// --until takes a unit like analysis.t_end (a bare number is s) and gets its plausibility row: the
// same run from '0.5 s', '500 ms' and 0.5; 5000 (easily meant in ms) is warned with the hint and
// refused under --strict; 200000 is impossible.
TEST(CliQuantities, UntilTakesUnitsAndTheRuleOfAnalysisTEnd) {
  const std::string model = (test::source_dir() / "configs" / "tutorial.yaml").string();
  const fs::path dir = scratch_dir("until-units");
  std::string first;
  int k = 0;
  for (const char* until : {"0.5", "'0.5 s'", "'500 ms'"}) {
    const fs::path out = dir / std::to_string(k++);
    const Command c = run("run -q " + model + " --until " + until + " -o '" + out.string() + "'");
    ASSERT_EQ(c.exit_code, 0) << until << ": " << c.output;
    const std::string histories = test::file_text(out / "histories.csv");
    ASSERT_GT(histories.size(), 1000u);
    if (first.empty())
      first = histories;
    else
      EXPECT_EQ(histories, first) << until;
  }
  Command c = run("run " + model + " --until 5000 --strict -o '" + (dir / "never").string() + "'");
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_NE(c.output.find("--until: '5000' is implausible"), std::string::npos) << c.output;
  EXPECT_NE(c.output.find("did you mean '5000 ms'?"), std::string::npos) << c.output;
  EXPECT_FALSE(fs::exists(dir / "never" / "summary.json"));
  c = run("run " + model + " --until 200000 -o '" + (dir / "never").string() + "'");
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_NE(c.output.find("--until"), std::string::npos) << c.output;
  EXPECT_NE(c.output.find("impossible"), std::string::npos) << c.output;
  fs::remove_all(dir);
}

// pushover --target-drift is a ratio with a unit ('2 %' = 0.02, the default) and --angle an angle
// that needs its unit, as in the model files; bad values exit 2 naming the option.
TEST(CliQuantities, PushoverTargetDriftAndAngleTakeUnits) {
  const std::string model =
      (test::source_dir() / "configs" / "thesis-3storey-pushover.yaml").string();
  const fs::path dir = scratch_dir("pushover-units");
  std::string first;
  int k = 0;
  for (const char* drift :
       {"", "--target-drift '2 %'", "--target-drift 2%", "--target-drift 0.02"}) {
    const fs::path out = dir / std::to_string(k++);
    const Command c = run("pushover -q " + model + " " + drift + " -o '" + out.string() + "'");
    ASSERT_EQ(c.exit_code, 0) << drift << ": " << c.output;
    const std::string curve = test::file_text(out / "pushover.csv");
    if (first.empty())
      first = curve;
    else
      EXPECT_EQ(curve, first) << drift;
  }
  for (const char* bad : {"--target-drift 2", "--target-drift '2 m'", "--target-drift 0"}) {
    const Command c =
        run("pushover -q " + model + " " + bad + " -o '" + (dir / "x").string() + "'");
    EXPECT_EQ(c.exit_code, 2) << bad << ": " << c.output;
    EXPECT_NE(c.output.find("--target-drift"), std::string::npos) << bad << ": " << c.output;
  }
  const fs::path model3d = test::source_dir() / "configs" / "tutorial-3d.yaml";
  const Command bare =
      run("pushover -q '" + model3d.string() + "' --angle 30 -o '" + (dir / "x").string() + "'");
  EXPECT_EQ(bare.exit_code, 2) << bare.output;
  EXPECT_NE(bare.output.find("did you mean '30 deg'?"), std::string::npos) << bare.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace isopound
