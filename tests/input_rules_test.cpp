// "No silent wrong answers" (issue 14), the input side: every key used or refused, null means
// absent, no silent physics defaults, ranges with hints, records that cannot be read refused.
#include <gtest/gtest.h>

#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "solver/excitation/ground_motion.h"
#include "solver/io/model_input.h"
#include "solver/materials/impact_law.h"
#include "solver/structures/job.h"
#include "tests/test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

// A scratch directory with a small column record (cm/s2) and a small PEER record.
class Scratch {
 public:
  Scratch() {
    dir_ = fs::temp_directory_path() / ("isopound-rules-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream columns(dir_ / "quake.txt");
    for (int k = 0; k < 200; ++k) columns << 0.01 * k << " " << 50.0 * ((k % 7) - 3) << "\n";
    std::ofstream peer(dir_ / "quake.AT2");
    peer << "PEER NGA STRONG MOTION DATABASE RECORD\nTEST\nACCELERATION TIME SERIES IN UNITS OF "
            "G\nNPTS=  200, DT=   .0100 SEC\n";
    for (int k = 0; k < 200; ++k) peer << 0.01 * ((k % 5) - 2) << ((k % 5 == 4) ? "\n" : " ");
  }
  ~Scratch() { fs::remove_all(dir_); }
  const fs::path& dir() const { return dir_; }

 private:
  fs::path dir_;
};

const Scratch& scratch() {
  static const Scratch s;
  return s;
}

constexpr const char* kBuilding = R"(
building:
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
)";

ModelConfig load(const std::string& text, std::vector<std::string>* used = nullptr) {
  return load_model(YAML::Load(text), "model.yaml", scratch().dir().string(), used);
}

InputError error_of(const std::string& text) {
  try {
    load(text);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("", 0, 0, "", "");
}

// --- the reproductions of issue 14, each an error naming file:line and key, or right physics ---

TEST(InputRules, ColumnRecordWithoutUnitIsRefused) {
  // Was read as g: the Erzincan file (cm/s2) gave PGA 505 g.
  const InputError e = error_of(std::string(kBuilding) +
                                "ground_motion: {record: quake.txt, format: columns, column: 1, "
                                "dt: 0.01 s}\n");
  EXPECT_EQ(e.key(), "ground_motion.unit");
  EXPECT_NE(e.detail().find("missing required key 'unit'"), std::string::npos) << e.what();
  EXPECT_GT(e.line(), 0);
  // With the unit it reads, and cm/s2 is 1/100 of m/s2.
  const ModelConfig m = load(std::string(kBuilding) +
                             "ground_motion: {record: quake.txt, format: columns, column: 1, "
                             "dt: 0.01 s, unit: cm/s2}\n");
  const GroundMotion motion = load_ground_motion(m.ground_motion);
  EXPECT_DOUBLE_EQ(motion.acceleration[0], -1.5);  // 50 * (0 - 3) cm/s2
}

TEST(InputRules, NullMeansAbsentAndWallsNeedAGap) {
  // `walls: ~` gave the thesis walls; now it is the same as no walls (as in a study override).
  for (const char* walls : {"  walls: ~\n", "  walls:\n", ""})
    EXPECT_TRUE(load(std::string(kBuilding) + walls).building.walls.empty()) << walls;
  // `walls: {}` and walls without a gap are refused: the gap decides whether pounding happens.
  for (const char* walls :
       {"  walls: {}\n", "  walls: {law: kelvin_voigt, k: 2500 kN/mm, e: 0.7, mass: 500 t}\n"}) {
    const InputError e = error_of(std::string(kBuilding) + walls);
    EXPECT_EQ(e.key(), "building.walls.gap") << e.what();
    EXPECT_GT(e.line(), 0) << e.what();
  }
}

TEST(InputRules, ImpactStiffnessOfTheOtherFamilyIsRefused) {
  // law: hertz with k used a default k_h (k = 1 and 5000 kN/mm gave identical results).
  InputError e =
      error_of(std::string(kBuilding) + "  walls: {gap: 20 cm, law: hertz, k: 2500 kN/mm}\n");
  EXPECT_EQ(e.key(), "building.walls.k_h") << e.what();
  EXPECT_NE(e.detail().find("not 'k'"), std::string::npos) << e.what();
  // The mirror case: kelvin_voigt with k_h.
  e = error_of(std::string(kBuilding) +
               "  walls: {gap: 20 cm, law: kelvin_voigt, k: 2500 kN/mm, e: 0.7, mass: 500 t, "
               "k_h: 2500 kN/mm^1.5}\n");
  EXPECT_EQ(e.key(), "building.walls.k_h") << e.what();
  EXPECT_NE(e.detail().find("not used with"), std::string::npos) << e.what();
  EXPECT_NE(e.detail().find("law: kelvin_voigt"), std::string::npos) << e.what();
  // Hertz with k_h reads k_h in its own unit.
  const ModelConfig m =
      load(std::string(kBuilding) + "  walls: {gap: 20 cm, law: hertz, k_h: 2.5e9 N/m^1.5}\n");
  EXPECT_DOUBLE_EQ(m.building.walls.at(0).impact.k_h, 2.5e9);
}

TEST(InputRules, StrengthRatioAboveOneHasAHint) {
  const InputError e = error_of(std::string(kBuilding) + "  isolator: {model: bilinear, QW: 5}\n");
  EXPECT_EQ(e.key(), "building.isolator.QW");
  EXPECT_NE(e.detail().find("did you mean '5 %'?"), std::string::npos) << e.what();
  EXPECT_NE(e.detail().find("500 %"), std::string::npos) << e.what();
  EXPECT_DOUBLE_EQ(load(std::string(kBuilding) + "  isolator: {model: bilinear, QW: 5 %}\n")
                       .building.isolator.strength_ratio,
                   0.05);
}

TEST(InputRules, PeerRecordRefusesDtAndUnit) {
  for (const char* key : {"dt: 0.02 s", "unit: cm/s2", "column: 1", "time_column: 0"}) {
    const InputError e =
        error_of(std::string(kBuilding) + "ground_motion: {record: quake.AT2, " + key + "}\n");
    const std::string name = std::string(key).substr(0, std::string(key).find(':'));
    EXPECT_EQ(e.key(), "ground_motion." + name) << e.what();
    EXPECT_NE(e.detail().find("PEER"), std::string::npos) << e.what();
  }
}

TEST(InputRules, FixedStepMustDivideTheRecordInterval) {
  // `stepping: fixed, dt: 10 s` ran with 0.005 s while summary.json said 10 s.
  const ModelConfig m = load(std::string(kBuilding) +
                             "analysis: {stepping: fixed, dt: 10 s}\n"
                             "ground_motion: {pulse: {dt: 0.005 s, duration: 2 s}}\n");
  const GroundMotion motion = load_ground_motion(m.ground_motion);
  try {
    check_step_against_record(m.analysis, motion);
    ADD_FAILURE() << "a 10 s fixed step was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("analysis.dt"), std::string::npos) << e.what();
  }
  // A divisor of the record interval is used as given.
  AnalysisConfig fine = m.analysis;
  fine.dt = 0.0025;
  EXPECT_NO_THROW(check_step_against_record(fine, motion));
  // Fixed stepping without dt: no silent step.
  EXPECT_EQ(error_of(std::string(kBuilding) + "analysis: {stepping: fixed}\n").key(),
            "analysis.dt");
}

TEST(InputRules, DefaultsThatChangeThePhysicsAreListed) {
  const ModelConfig m = load(std::string(kBuilding) +
                             "  walls: {gap: 20 cm, law: kelvin_voigt, k: 2500 kN/mm, e: 0.7}\n");
  std::map<std::string, std::string> defaults(m.defaults.begin(), m.defaults.end());
  EXPECT_EQ(defaults["building.walls.mass"], "500000 kg");
  EXPECT_EQ(defaults["building.isolator.model"], "bouc_wen");
  EXPECT_EQ(defaults["building.isolator.QW"], "0.05");
  EXPECT_EQ(defaults["building.damping.isolation"], "0.05");
  EXPECT_EQ(defaults["analysis.stepping"], "adaptive");
  EXPECT_EQ(defaults.count("building.walls.gap"), 0u);  // given
}

TEST(InputRules, DuplicateStructureNamesAreRefused) {
  const InputError e = error_of(std::string(kBuilding) + R"(neighbours:
  - gap: 10 cm
    impact: {law: linear, k: 2500 kN/mm}
    building: {isolated: false, floors: {count: 3, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}}
)");
  EXPECT_EQ(e.key(), "neighbours[0].building.name") << e.what();
}

TEST(InputRules, RecordsThatNeverEndAreRefused) {
  RecordReadOptions columns;
  columns.format = RecordReadOptions::Format::kColumns;
  columns.dt = 0.01;
  try {
    read_record("/dev/zero", columns);
    ADD_FAILURE() << "/dev/zero was read";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("1 MiB"), std::string::npos) << e.what();
  }
}

// --- one rule for keys, table-driven: for every impact law, isolator model and record format,
// every key the reader knows for that section but the choice does not use is refused ---

struct Choice {
  std::string section;  // the map the key goes into
  std::string text;     // a valid model with the choice made; "@" marks where keys go
};

std::vector<Choice> choices() {
  std::vector<Choice> out;
  for (const std::string_view law : impact_law_names()) {
    const ImpactLawUses uses = impact_law_uses(law);
    std::string wall = "{gap: 20 cm, law: " + std::string(law);
    if (uses.k) wall += ", k: 2500 kN/mm";
    if (uses.k_h) wall += ", k_h: 2.5e9";
    if (uses.e) wall += ", e: 0.7";
    out.push_back({"building.walls", std::string(kBuilding) + "  walls: " + wall + "@}\n"});
  }
  for (const char* model : {"linear", "bilinear", "bouc_wen"})
    out.push_back(
        {"building.isolator", std::string(kBuilding) + "  isolator: {model: " + model + "@}\n"});
  out.push_back(
      {"ground_motion", std::string(kBuilding) + "ground_motion: {record: quake.AT2@}\n"});
  out.push_back({"ground_motion", std::string(kBuilding) +
                                      "ground_motion: {record: quake.txt, format: columns, "
                                      "column: 1, dt: 0.01 s, unit: cm/s2@}\n"});
  out.push_back({"ground_motion", std::string(kBuilding) + "ground_motion: {pulse: {}@}\n"});
  for (const char* stepping : {"adaptive", "fixed, dt: 0.005 s"})
    out.push_back({"analysis", std::string(kBuilding) + "analysis: {stepping: " + stepping +
                                   ", dt: 0.005 s@}\n"});
  out.push_back({"output", std::string(kBuilding) + "output: {histories: false@}\n"});
  return out;
}

std::string with_key(const std::string& text, const std::string& key) {
  std::string out = text;
  out.replace(out.find('@'), 1, key.empty() ? "" : ", " + key + ": 1");
  return out;
}

// The universe of keys per section: whatever the reader looked up over every choice.
std::map<std::string, std::set<std::string>> keys_by_section() {
  std::map<std::string, std::set<std::string>> out;
  for (const Choice& c : choices()) {
    std::vector<std::string> used;
    std::string text = with_key(c.text, "");
    // "fixed, dt: ..." repeats dt for the adaptive form; keep the first.
    const auto dup = text.find(", dt: 0.005 s, dt: 0.005 s");
    if (dup != std::string::npos) text.erase(dup, std::string(", dt: 0.005 s").size());
    load(text, &used);
    for (const std::string& key : used)
      if (key.starts_with(c.section + ".") &&
          key.find('.', c.section.size() + 1) == std::string::npos)
        out[c.section].insert(key.substr(c.section.size() + 1));
  }
  return out;
}

TEST(InputRules, EveryKeyAChoiceDoesNotUseIsRefused) {
  const auto universe = keys_by_section();
  int refused = 0;
  for (Choice c : choices()) {
    const auto dup = c.text.find(", dt: 0.005 s, dt: 0.005 s");
    if (dup != std::string::npos) c.text.erase(dup, std::string(", dt: 0.005 s").size());
    std::vector<std::string> used_paths;
    load(with_key(c.text, ""), &used_paths);
    std::set<std::string> used;
    for (const std::string& key : used_paths)
      if (key.starts_with(c.section + ".")) used.insert(key.substr(c.section.size() + 1));
    for (const std::string& key : universe.at(c.section)) {
      if (used.count(key)) continue;
      const std::string text = with_key(c.text, key);
      try {
        load(text);
        ADD_FAILURE() << "unused key '" << key << "' accepted in:\n" << text;
      } catch (const InputError& e) {
        EXPECT_EQ(e.key(), c.section + "." + key) << e.what();
        EXPECT_GT(e.line(), 0) << e.what();
        ++refused;
      }
    }
  }
  // Not a vacuous table: e.g. the linear law alone leaves n, k_h, e, material, mass, ... unused.
  EXPECT_GT(refused, 60);
}

// --- the tutorial describes every key the reader accepts ---

TEST(InputRules, TutorialMentionsEveryKeyTheReaderKnows) {
  // Fill the reader's registry: the tutorial, every shipped config and every choice above.
  for (const auto& entry : fs::directory_iterator(test::source_dir() / "configs"))
    if (entry.path().extension() == ".yaml") {
      try {
        load_model_file(entry.path().string());
      } catch (const std::exception&) {
        // a config whose record is absent still registers the keys read before
      }
    }
  (void)keys_by_section();
  // The tutorial: configs/tutorial.yaml, whose 3D part is configs/tutorial-3d.yaml.
  std::stringstream buffer;
  for (const char* name : {"tutorial.yaml", "tutorial-3d.yaml"}) {
    std::ifstream in(test::source_dir() / "configs" / name);
    ASSERT_TRUE(in) << name;
    buffer << in.rdbuf() << '\n';
  }
  const std::string tutorial = buffer.str();
  const std::vector<std::string> keys = known_model_keys();
  ASSERT_GT(keys.size(), 60u);
  for (const std::string& path : keys) {
    const std::string name = path.substr(path.find_last_of('.') + 1);
    const std::regex written("(^|[\\s{,#])" + name + ":");
    EXPECT_TRUE(std::regex_search(tutorial, written))
        << "configs/tutorial.yaml (with tutorial-3d.yaml) does not mention '" << path << "'";
  }
}

}  // namespace
}  // namespace isopound
