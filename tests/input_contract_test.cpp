// Issue 24 items 3 and 5: records say their unit, options that do not apply are errors, Rayleigh
// damping at modes of equal frequency is refused at input, and one command-line contract for
// isopound, isopound-pre and isopound-post (exit 2 for usage errors, --version, readable ranges,
// units in quantity options, model_file absolute, binary files and tabs named as such).
#include <gtest/gtest.h>

#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "solver/core/constants.h"
#include "solver/excitation/ground_motion.h"
#include "solver/io/model_input.h"
#include "solver/structures/rayleigh_modes.h"
#include "tests/test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;
using Command = test::CommandResult;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class Scratch {
 public:
  explicit Scratch(const std::string& name)
      : dir_(fs::temp_directory_path() /
             ("isopound-contract-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~Scratch() { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  const fs::path& dir() const { return dir_; }

 private:
  fs::path dir_;
};

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

// A PEER file with the given unit line (line 3) and values 1, -2, 3, ... (10 values).
std::string peer_with_unit(const std::string& unit_line) {
  std::string text = "PEER NGA STRONG MOTION DATABASE RECORD\nTest, 1/1/2000, Station, 0\n" +
                     unit_line + "\nNPTS=   10, DT=   .0100 SEC\n";
  for (int k = 0; k < 10; ++k) text += std::to_string((k % 2 ? -1 : 1) * (k + 1)) + " ";
  return text + "\n";
}

// --- records say their unit ---

TEST(RecordUnits, PeerHeaderUnitIsReadAndConverted) {
  const Scratch s("units");
  struct Case {
    const char* line;
    double si;  // m/s^2 per value
    bool note;  // a conversion or assumption is stated
  };
  const Case cases[] = {
      {"ACCELERATION TIME SERIES IN UNITS OF G", kGravity, false},
      {"ACCELERATION TIME HISTORY IN UNITS OF G. FILTER POINTS: HP=0.1 Hz LP=25 Hz", kGravity,
       false},
      {"The units are (g)", kGravity, false},
      {"Acceleration in g", kGravity, false},
      {"ACCELERATION TIME SERIES IN UNITS OF CM/S/S", 0.01, true},
      {"ACCELERATION TIME SERIES IN UNITS OF CM/SEC/SEC", 0.01, true},
      {"ACCELERATION TIME SERIES IN UNITS OF cm/s^2", 0.01, true},
      {"ACCELERATION TIME SERIES IN UNITS OF GAL", 0.01, true},
      {"ACCELERATION TIME SERIES IN UNITS OF M/S/S", 1.0, true},
      {"ACCELERATION TIME SERIES IN UNITS OF M/S2", 1.0, true},
      {"ACCELERATION TIME SERIES IN UNITS OF MM/S/S", 0.001, true},
      {"a header line that states no unit", kGravity, true},
  };
  for (const Case& c : cases) {
    const fs::path p = s.write("r.AT2", peer_with_unit(c.line));
    const GroundMotion m = read_record(p.string());
    ASSERT_EQ(m.acceleration.size(), 10u) << c.line;
    for (int k = 0; k < 10; ++k)
      EXPECT_DOUBLE_EQ(m.acceleration[k], (k % 2 ? -1 : 1) * (k + 1) * c.si) << c.line;
    EXPECT_EQ(m.unit_note.empty(), !c.note) << c.line << ": " << m.unit_note;
  }
  // Scale still multiplies the converted values.
  RecordReadOptions o;
  o.scale = 2.0;
  const GroundMotion m =
      read_record(s.write("r.AT2", peer_with_unit("IN UNITS OF CM/S/S")).string(), o);
  EXPECT_DOUBLE_EQ(m.acceleration[0], 0.02);
  EXPECT_TRUE(contains(m.unit_note, "converted")) << m.unit_note;
}

TEST(RecordUnits, UnknownHeaderUnitIsAnErrorAtItsLine) {
  const Scratch s("units-bad");
  for (const char* unit : {"FURLONGS/S/S", "CM/S", "KG"}) {
    const fs::path p =
        s.write("r.AT2", peer_with_unit(std::string("ACCELERATION IN UNITS OF ") + unit));
    try {
      read_record(p.string());
      ADD_FAILURE() << unit << " accepted";
    } catch (const RecordError& e) {
      EXPECT_EQ(e.line(), 3) << e.what();
      EXPECT_TRUE(contains(e.what(), unit)) << e.what();
    }
  }
}

TEST(RecordUnits, TheConsoleStatesAConversion) {
  const Scratch s("units-cli");
  s.write("r.AT2", peer_with_unit("ACCELERATION TIME SERIES IN UNITS OF CM/S/S"));
  const fs::path model = s.write(
      "m.yaml",
      "building:\n  base: {mass: 340 t}\n"
      "  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}\n"
      "ground_motion: {record: r.AT2}\n");
  const Command c = test::run_isopound("check " + quoted(model));
  EXPECT_EQ(c.exit_code, 0) << c.output;
  EXPECT_TRUE(contains(c.output, "says units of CM/S/S: converted to m/s^2")) << c.output;
}

// A cm/s^2 column file declared in g: PGA of hundreds of g is refused with the unit named.
TEST(RecordUnits, ColumnFileInTheWrongUnitIsRefused) {
  const Scratch s("units-columns");
  std::string columns;
  for (int k = 0; k < 200; ++k) columns += std::to_string(500.0 * std::sin(0.1 * k)) + "\n";
  s.write("q.txt", columns);
  const std::string building =
      "building:\n  base: {mass: 340 t}\n"
      "  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}\n";
  const fs::path wrong =
      s.write("wrong.yaml", building + "ground_motion: {record: q.txt, dt: 0.01 s, unit: g}\n");
  for (const char* verb : {"check", "run -q --no-histories -o /tmp/isopound-contract-never"}) {
    const Command c = test::run_isopound(std::string(verb) + " " + quoted(wrong));
    EXPECT_EQ(c.exit_code, 2) << c.output;
    EXPECT_TRUE(contains(c.output, "cm/s^2")) << c.output;
    EXPECT_TRUE(contains(c.output, "peak ground acceleration")) << c.output;
  }
  const fs::path right =
      s.write("right.yaml", building + "ground_motion: {record: q.txt, dt: 0.01 s, unit: cm/s2}\n");
  EXPECT_EQ(test::run_isopound("check " + quoted(right)).exit_code, 0);
}

// A column file read as columns only because no NPTS/DT line was found says so.
TEST(RecordUnits, ColumnFileWithoutFormatSaysItWasReadAsColumns) {
  const Scratch s("as-columns");
  s.write("q.acc", "0.1\n0.2\n0.3\n");
  const std::string text =
      "building:\n  base: {mass: 340 t}\n"
      "  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}\n"
      "ground_motion: {record: q.acc, unit: g}\n";
  try {
    load_model(YAML::Load(text), "m.yaml", s.dir().string());
    ADD_FAILURE() << "no dt accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "ground_motion.dt");
    EXPECT_TRUE(contains(e.detail(), "read as a plain column file")) << e.what();
  }
}

// --- options that do not apply ---

TEST(OptionsApply, RecordOnARecordPairModelIsAnError) {
  const fs::path model = test::source_dir() / "configs" / "3d-xy5.yaml";
  const Command c = test::run_isopound("run " + quoted(model) +
                                       " --record /nonexistent/x.AT2 -q -o /tmp/isopound-never");
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_TRUE(contains(c.output, "--record")) << c.output;
  EXPECT_TRUE(contains(c.output, "ground_motion.L")) << c.output;
}

TEST(OptionsApply, JobsWithoutEnsembleIsAnError) {
  const Command c =
      test::run_isopound("run " + quoted(test::source_dir() / "configs" / "tutorial.yaml") +
                         " -j 2 -q -o /tmp/isopound-never");
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_TRUE(contains(c.output, "--ensemble")) << c.output;
}

// --- Rayleigh damping at modes of equal frequency ---

TEST(RayleighModes, EqualFrequenciesAreRefusedWithTheNextDistinctMode) {
  Eigen::VectorXd omega(4);
  omega << 20.0, 20.0 * (1 + 1e-4), 25.0, 60.0;
  try {
    require_distinct_modes(omega, 1, 2, "test system");
    ADD_FAILURE() << "modes 1 and 2 accepted";
  } catch (const RayleighModesError& e) {
    EXPECT_TRUE(contains(e.what(), "modes 1 and 2")) << e.what();
    EXPECT_TRUE(contains(e.what(), "0.3142 s")) << e.what();  // 2 pi / 20
    EXPECT_TRUE(contains(e.what(), "modes: [1, 3]")) << e.what();
  }
  EXPECT_NO_THROW(require_distinct_modes(omega, 1, 3, "test system"));
  EXPECT_NO_THROW(require_distinct_modes(omega, 2, 4, "test system"));
}

// The symmetric 3D thesis building: modes 1 and 2 are the x and y pair (0.3113 s fixed base).
TEST(RayleighModes, SymmetricThesisBuildingIsRefusedAtInput) {
  const fs::path path = test::source_dir() / "configs" / "3d-thesis-building.yaml";
  for (const char* damping :
       {"{type: non_classical, ratios: [2 %, 2 %], modes: [1, 2]}",
        "{type: rayleigh, ratios: [5 %, 2 %], modes: [1, 2], bearing_stiffness: post_yield}"}) {
    YAML::Node root = YAML::LoadFile(path.string());
    root["structures"][0]["damping"] = YAML::Load(damping);
    try {
      load_model(root, path.string(), path.parent_path().string());
      ADD_FAILURE() << damping << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "structures[0].damping.modes") << e.what();
      EXPECT_TRUE(contains(e.detail(), "modes 1 and 2")) << e.what();
      EXPECT_TRUE(contains(e.detail(), "next distinct mode")) << e.what();
      EXPECT_GT(e.line(), 0);
    }
  }
  // The fixed-base pair's period, as the issue gives it.
  YAML::Node root = YAML::LoadFile(path.string());
  root["structures"][0]["damping"] =
      YAML::Load("{type: non_classical, ratios: [2 %, 2 %], modes: [1, 2]}");
  try {
    load_model(root, path.string(), path.parent_path().string());
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.detail(), "0.3113 s")) << e.what();
  }
}

// --- one command-line contract ---

fs::path program(const std::string& name) {
  return fs::path(ISOPOUND_BINARY).parent_path() / name;
}

Command run_program(const std::string& name, const std::string& args) {
  return test::run_command(quoted(program(name)) + " " + args);
}

TEST(CliContract, VersionAndUsageErrorsInAllThreePrograms) {
  int tried = 0;
  for (const char* name : {"isopound", "isopound-pre", "isopound-post"}) {
    if (!fs::exists(program(name))) continue;  // isopound-pre/-post: built with VTK and Gmsh
    ++tried;
    const Command v = run_program(name, "--version");
    EXPECT_EQ(v.exit_code, 0) << name << ": " << v.output;
    EXPECT_TRUE(contains(v.output, "0.")) << name << ": " << v.output;
    for (const char* bad : {"--no-such-option", ""}) {
      const Command c = run_program(name, bad);
      EXPECT_EQ(c.exit_code, 2) << name << " " << bad << ": " << c.output;
    }
  }
  EXPECT_GE(tried, 1);
}

TEST(CliContract, RangesArePrintedAsPeopleWriteThem) {
  const Command c = test::run_isopound("sweep x.yaml --jobs=-1");
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_TRUE(contains(c.output, ">= 0")) << c.output;
  EXPECT_FALSE(std::regex_search(c.output, std::regex("[0-9]{20}"))) << c.output;
  const Command r =
      test::run_isopound("run " + quoted(test::source_dir() / "configs" / "tutorial.yaml") +
                         " --ensemble 2 --jobs=-3 -q -o /tmp/isopound-never");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_FALSE(std::regex_search(r.output, std::regex("[0-9]{20}"))) << r.output;
}

TEST(CliContract, UntilTakesAUnitAndModelFileIsAbsolute) {
  const Scratch s("until");
  const fs::path model = s.write(
      "m.yaml",
      "building:\n  base: {mass: 340 t}\n"
      "  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}\n");
  const fs::path out = s.dir() / "out";
  // Run from the scratch directory with a relative model path.
  const Command c =
      test::run_command("cd " + quoted(s.dir()) + " && " + quoted(fs::path(ISOPOUND_BINARY)) +
                        " run m.yaml --until '1500 ms' -q -o out");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("model_file").get<std::string>(), fs::canonical(model).string());
  EXPECT_EQ(j.at("model_file_as_given").get<std::string>(), "m.yaml");
  EXPECT_EQ(fs::canonical(j.at("model_file_resolved_from").get<std::string>()),
            fs::canonical(s.dir()));
  EXPECT_TRUE(j.at("warnings").is_array());
  // The run stopped at 1.5 s: the last row of histories.csv.
  std::ifstream histories(out / "histories.csv");
  std::string line, last;
  while (std::getline(histories, line))
    if (!line.empty()) last = line;
  EXPECT_NEAR(std::stod(last.substr(0, last.find(','))), 1.5, 1e-9) << last;
  for (const char* bad : {"'5 m'", "'-1 s'", "five"}) {
    const Command b = test::run_isopound("run " + quoted(model) + " --until " + bad + " -q -o " +
                                         quoted(s.dir() / "never"));
    EXPECT_EQ(b.exit_code, 2) << bad << ": " << b.output;
    EXPECT_TRUE(contains(b.output, "--until")) << b.output;
  }
}

TEST(CliContract, StrictTurnsWarningsIntoErrorsAndSummaryListsThem) {
  const Scratch s("strict");
  const fs::path model = s.write("m.yaml",
                                 "building:\n  base: {mass: 340 t}\n  floors:\n"
                                 "    - {mass: 340, stiffness: 600 MN/m, height: 3.2 m}\n"
                                 "    - {mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}\n"
                                 "    - {mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}\n"
                                 "analysis: {t_end: 0.5 s}\n");
  const Command w = test::run_isopound("run " + quoted(model) + " -o " + quoted(s.dir() / "out"));
  EXPECT_EQ(w.exit_code, 0) << w.output;
  EXPECT_TRUE(contains(w.output, "warning:")) << w.output;
  std::ifstream in(s.dir() / "out" / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j.at("warnings").size(), 1u);
  EXPECT_TRUE(contains(j.at("warnings")[0].get<std::string>(), "building.floors[0].mass"));
  for (const char* verb : {"check --strict", "run --strict -q -o /tmp/isopound-never"}) {
    const Command c = test::run_isopound(std::string(verb) + " " + quoted(model));
    EXPECT_EQ(c.exit_code, 2) << verb << ": " << c.output;
    EXPECT_TRUE(contains(c.output, "did you mean '340 t'?")) << c.output;
  }
}

TEST(CliContract, TabsAndBinaryFilesAreNamedAsSuch) {
  const Scratch s("tab");
  const fs::path tab = s.write("tab.yaml", "building:\n\tbase: {mass: 340 t}\n");
  Command c = test::run_isopound("check " + quoted(tab));
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_TRUE(contains(c.output, "tab.yaml:2:1:")) << c.output;
  EXPECT_TRUE(contains(c.output, "tab character")) << c.output;
  const fs::path binary = s.write("model.yaml", std::string("\x7f"
                                                            "ELF\x02\x01\x01\0\0\0",
                                                            10));
  c = test::run_isopound("check " + quoted(binary));
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_TRUE(contains(c.output, "binary file")) << c.output;
}

TEST(CliContract, SelfCrossingPlanIsNamedAsSelfCrossing) {
  const Scratch s("bowtie");
  // A bow tie: zero net area, not four points on a line.
  const fs::path bowtie =
      s.write("pairs.yaml",
              "pairs:\n  - a: [[0, 0], [1, 1], [1, 0], [0, 1]]\n    b: [[0, 0], [1, 0], [1, 1]]\n");
  Command c = test::run_isopound("geometry overlap " + quoted(bowtie));
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_TRUE(contains(c.output, "self-crossing")) << c.output;
  EXPECT_FALSE(contains(c.output, "one line")) << c.output;
  // Self-crossing with a net area: named too.
  const fs::path z =
      s.write("z.yaml",
              "pairs:\n  - a: [[0, 0], [4, 0], [0, 1], [3, 3]]\n    b: [[0, 0], [1, 0], [1, 1]]\n");
  c = test::run_isopound("geometry overlap " + quoted(z));
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_TRUE(contains(c.output, "self-crossing")) << c.output;
}

TEST(CliContract, PreAngleNeedsAUnit) {
  if (!fs::exists(program("isopound-pre"))) GTEST_SKIP() << "isopound-pre not built";
  const fs::path model = test::source_dir() / "configs" / "3d-xy5.yaml";
  const Command c = run_program(
      "isopound-pre", quoted(model) + " --angle 30 --no-plan -o " + "/tmp/isopound-contract-pre");
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_TRUE(contains(c.output, "30 deg") && contains(c.output, "30 rad")) << c.output;
  fs::remove_all("/tmp/isopound-contract-pre");
}

}  // namespace
}  // namespace isopound
