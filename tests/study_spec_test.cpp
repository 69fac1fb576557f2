// Study files: parameter paths on YAML trees, axes (values, ranges with units, zips, levels),
// enumeration order, case models and de-duplication, and located errors for malformed studies.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "solver/study/study_cases.h"
#include "solver/study/study_path.h"
#include "solver/study/study_spec.h"
#include "tests/study_test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;

// A scratch directory removed when the test process exits.
struct ScratchDir {
  fs::path path = test::study_scratch("spec");
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// Writes `text` as <scratch>/<name> and loads it.
Study load_study_text(const std::string& name, const std::string& text) {
  static const ScratchDir dir;
  const fs::path path = dir.path / name;
  test::write_file(path, text);
  return load_study_file(path.string());
}

std::string model_line() {
  return "model: " + test::thesis_model() + "\n";
}

TEST(StudyPath, ParsesKeysAndListIndices) {
  const ParameterPath p = parse_parameter_path("building.floors[2].mass");
  ASSERT_EQ(p.steps.size(), 4u);
  EXPECT_EQ(p.steps[0].key, "building");
  EXPECT_EQ(p.steps[1].key, "floors");
  EXPECT_EQ(p.steps[2].index, 2);
  EXPECT_EQ(p.steps[3].key, "mass");
  EXPECT_EQ(p.text, "building.floors[2].mass");
  for (const char* bad : {"", "a..b", "a.", ".a", "a[x]", "a[-1]", "a[1", "a b"})
    EXPECT_THROW(parse_parameter_path(bad), std::invalid_argument) << bad;
  EXPECT_TRUE(is_prefix_of(parse_parameter_path("building.walls"),
                           parse_parameter_path("building.walls.gap")));
  EXPECT_FALSE(is_prefix_of(parse_parameter_path("building.wall"),
                            parse_parameter_path("building.walls.gap")));
}

TEST(StudyPath, OverridesSetCreateAndRemoveNodes) {
  YAML::Node tree =
      YAML::Load("building: {isolator: {uy: 1 cm}, floors: [{mass: 1 t}, {mass: 2 t}]}");
  apply_override(tree, parse_parameter_path("building.isolator.uy"), YAML::Node("2 cm"));
  apply_override(tree, parse_parameter_path("building.walls.gap"), YAML::Node("20 cm"));
  apply_override(tree, parse_parameter_path("building.floors[1].mass"), YAML::Node("3 t"));
  EXPECT_EQ(tree["building"]["isolator"]["uy"].Scalar(), "2 cm");
  EXPECT_EQ(tree["building"]["walls"]["gap"].Scalar(), "20 cm");
  EXPECT_EQ(tree["building"]["floors"][1]["mass"].Scalar(), "3 t");
  apply_override(tree, parse_parameter_path("building.walls"), YAML::Node());  // null removes
  EXPECT_FALSE(tree["building"]["walls"].IsDefined());
  EXPECT_THROW(apply_override(tree, parse_parameter_path("building.floors.count"), YAML::Node("3")),
               std::invalid_argument);
  EXPECT_THROW(
      apply_override(tree, parse_parameter_path("building.floors[5].mass"), YAML::Node("3 t")),
      std::invalid_argument);
  EXPECT_THROW(
      apply_override(tree, parse_parameter_path("building.isolator.uy.x"), YAML::Node("1")),
      std::invalid_argument);
}

TEST(StudySpec, RangeWithUnitsIsInclusiveAndWrittenInSi) {
  const Study s = load_study_text("range.yaml", model_line() + R"(
axes:
  - {path: building.isolator.uy, range: {from: 1 cm, to: 3 cm, step: 0.05 cm}}
  - {path: building.walls.gap, range: {from: 30 cm, to: 10 cm, step: -0.2 cm}, name: gap}
)");
  ASSERT_EQ(s.axes.size(), 2u);
  const Axis& uy = s.axes[0];
  EXPECT_EQ(uy.name, "uy");
  ASSERT_EQ(uy.levels.size(), 41u);
  EXPECT_EQ(uy.levels[0].label, "0.01");
  EXPECT_EQ(uy.levels[1].label, "0.0105");
  EXPECT_EQ(uy.levels[3].label, "0.0115");
  EXPECT_EQ(uy.levels[40].label, "0.03");
  EXPECT_TRUE(uy.levels[7].numeric);
  EXPECT_DOUBLE_EQ(uy.levels[7].si, 0.0135);
  EXPECT_EQ(uy.levels[1].overrides.front().value.Scalar(), "0.0105 m");
  EXPECT_EQ(s.axes[1].levels.size(), 101u);
  EXPECT_EQ(s.axes[1].levels.back().label, "0.1");
  EXPECT_EQ(s.case_count(), 41 * 101);
}

TEST(StudySpec, ProductAndZipEnumerateWithTheLastAxisFastest) {
  const Study s = load_study_text("zip.yaml", model_line() + R"(
axes:
  - {name: storeys, path: building.floors.count, values: [3, 5]}
  - zip:
    - {path: building.isolator.QW, values: [5 %, 10 %, 7.5 %]}
    - {path: building.isolator.uy, values: [1 cm, 2.5 cm, 2 cm]}
variants:
  BL: {building.isolator.model: bilinear, building.isolator.n: ~, building.isolator.A: ~, building.isolator.beta: ~, building.isolator.gamma: ~}
  BW: {building.isolator.model: bouc_wen}
)");
  ASSERT_EQ(s.axes.size(), 4u);
  EXPECT_EQ(s.group_count, 3);
  EXPECT_EQ(s.case_count(), 2 * 3 * 2);
  EXPECT_EQ(s.axes[3].name, "variant");
  // case 9 = storeys 1, zip 1, variant 1
  const std::vector<int> levels = s.levels_of(9);
  EXPECT_EQ(levels, (std::vector<int>{1, 1, 1, 1}));
  EXPECT_EQ(s.levels_of(2), (std::vector<int>{0, 1, 1, 0}));
  EXPECT_EQ(s.axes[1].levels[2].label, "0.075");
}

TEST(StudySpec, DefaultsForOutputsAndStatistics) {
  const Study s = load_study_text(
      "defaults.yaml", model_line() + "axes: [{path: building.isolator.Tb, values: [2 s]}]\n");
  ASSERT_EQ(s.outputs.size(), 3u);
  EXPECT_EQ(s.outputs[0].column, "base_displacement");
  EXPECT_EQ(s.outputs[1].selector, "stories.drift_ratio");
  EXPECT_TRUE(s.statistics.empty());  // no records: nothing to average over by default
  EXPECT_EQ(s.name, "defaults");
}

TEST(StudySpec, RecordSetsFromFilesFoldersAndComponents) {
  ISOPOUND_REQUIRE_RECORDS();
  const std::string records = test::records_dir().string();
  const Study s = load_study_text(
      "records.yaml",
      model_line() +
          "records:\n"
          "  - {folder: " +
          records +
          ", glob: \"RSN1084_*.AT2\", scale: 0.5}\n"
          "  - {file: " +
          records +
          "/erzikan.txt, format: columns, dt: 0.005 s, unit: cm/s2, components: {NS: 0, EW: 1}}\n");
  ASSERT_EQ(s.axes.size(), 1u);
  EXPECT_EQ(s.axes[0].name, "record");
  ASSERT_EQ(s.axes[0].levels.size(), 4u);
  EXPECT_EQ(s.axes[0].levels[0].label, "RSN1084_NORTHR_SCS052");
  EXPECT_EQ(s.axes[0].levels[1].label, "RSN1084_NORTHR_SCS142");
  EXPECT_EQ(s.axes[0].levels[3].label, "erzikan_EW");
  EXPECT_EQ(s.statistics.size(), 1u);  // over records by default
  const CaseBuilder builder(s);
  const CaseInput first = builder.input_of(0);
  EXPECT_FALSE(first.config.ground_motion.use_pulse);
  EXPECT_DOUBLE_EQ(first.config.ground_motion.read.scale, 0.5);
  const CaseInput ew = builder.input_of(3);
  EXPECT_EQ(ew.config.ground_motion.read.column, 1);
  EXPECT_EQ(fs::path(ew.config.ground_motion.record_path).filename(), "erzikan.txt");
  EXPECT_NE(first.motion_key, ew.motion_key);
}

TEST(StudyCases, OverridesReachTheModelAndHistoriesAreOff) {
  const Study s = load_study_text("cases.yaml", model_line() + R"(
set:
  ground_motion.pulse: {amplitude: 0.5 m/s, duration: 4 s}
axes:
  - {path: building.isolator.uy, values: [1 cm, 2.5 cm]}
  - {name: storeys, path: building.floors.count, values: [3, 5]}
variants:
  BL: {building.isolator.model: bilinear, building.isolator.n: ~, building.isolator.A: ~, building.isolator.beta: ~, building.isolator.gamma: ~}
)");
  const CaseBuilder builder(s);
  const CaseInput c = builder.input_of(3);  // uy 2.5 cm, 5 storeys
  EXPECT_DOUBLE_EQ(c.config.building.isolator.yield_displacement, 0.025);
  EXPECT_EQ(c.config.building.floors.size(), 5u);
  EXPECT_EQ(c.config.building.isolator.model, IsolatorConfig::Model::kBilinear);
  EXPECT_TRUE(c.config.ground_motion.use_pulse);  // `set` replaced the base model's record
  EXPECT_DOUBLE_EQ(c.config.ground_motion.pulse.amplitude, 0.5);
  EXPECT_FALSE(c.config.output.histories);
  EXPECT_EQ(builder.describe(3), "uy=0.025, storeys=5, variant=BL");
}

TEST(StudyCases, CasesWithIdenticalModelsShareOneAnalysis) {
  const Study s = load_study_text("dedupe.yaml", model_line() + R"(
set:
  ground_motion.pulse: {duration: 4 s}
axes:
  - {path: building.isolator.uy, values: [1 cm, 2 cm, 3 cm]}
variants:
  own: {}
  fixed_uy: {building.isolator.uy: 1.5 cm}
)");
  const ValidatedStudy v = validate_study(s, 2);
  ASSERT_EQ(v.representative.size(), 6u);
  EXPECT_EQ(v.distinct_models, 4);
  EXPECT_EQ(v.representative[3], 1);  // uy 2 cm + fixed_uy is the same model as uy 1 cm + fixed_uy
  EXPECT_EQ(v.representative[5], 1);
  EXPECT_EQ(v.representative[2], 2);
  EXPECT_EQ(v.motions.size(), 1u);
}

// A malformed study's InputError: its "file:line:col: key" prefix and a piece of the message.
struct Malformed {
  const char* name;
  const char* body;     // after the model line (line 1)
  const char* located;  // expected "line:col: key" after the file name
  const char* fragment;
};

TEST(StudyErrors, MalformedStudiesNameFileLineAndKeyBeforeAnyRun) {
  const Malformed cases[] = {
      {"unknown_path", "axes:\n  - {path: building.isolator.uyy, values: [1 cm]}\n",
       "3:44: axes[0].values[0]", "building.isolator.uyy: unknown key 'uyy' (did you mean 'uy'?)"},
      {"empty_axis", "axes:\n  - path: building.isolator.uy\n    values: []\n",
       "4:5: axes[0].values", "empty axis"},
      {"wrong_sign",
       "axes:\n  - path: building.isolator.uy\n    range: {from: 1 cm, to: 3 cm, step: -0.05 cm}\n",
       "4:41: axes[0].range.step", "step of wrong sign"},
      {"unit_mismatch_range",
       "axes:\n  - path: building.walls.gap\n    range: {from: 10 cm, to: 30 s, step: 0.2 cm}\n",
       "4:30: axes[0].range.to", "unit mismatch"},
      {"unit_mismatch_model", "axes:\n  - path: building.isolator.Tb\n    values: [2 s, 2 cm]\n",
       "4:19: axes[0].values[1]",
       "building.isolator.Tb: unit 'cm' is a length (m), expected a time (s)"},
      {"zero_step",
       "axes:\n  - {path: building.isolator.uy, range: {from: 1 cm, to: 2 cm, step: 0 cm}}\n",
       "3:70: axes[0].range.step", "must not be 0"},
      {"zip_lengths",
       "axes:\n  - zip:\n    - {path: building.isolator.QW, values: [5 %, 10 %]}\n"
       "    - {path: building.isolator.uy, values: [1 cm]}\n",
       "5:7: axes[0].zip[1]", "same number of values"},
      {"list_by_key",
       "axes:\n  - {path: building.damping.superstructure.modes.first, values: [1]}\n",
       "3:66: axes[0].values[0]", "building.damping.superstructure.modes is a list, not a map"},
      {"unknown_statistics_axis",
       "axes:\n  - {path: building.isolator.uy, values: [1 cm]}\nstatistics: {over: [record]}\n",
       "4:21: statistics.over[0]", "no axis named 'record'"},
      {"unknown_ratio_level",
       "variants: {BL: {building.isolator.model: bilinear, building.isolator.n: ~, building.isolator.A: ~, building.isolator.beta: ~, building.isolator.gamma: ~}}\nderived: {r: {ratio: [BL, BW]}}\n",
       "3:27: derived.r.ratio[1]", "no level 'BW'"},
      {"duplicate_axis",
       "axes:\n  - {path: building.isolator.uy, values: [1 cm]}\n  - {path: building.walls.uy, "
       "values: [1 cm]}\n",
       "4:5: axes[1].name", "two axes are named 'uy'"},
      {"bad_peak", "outputs: [base.drift]\n", "2:11: outputs[0]", "drifts belong to stories"},
      {"missing_floor", "outputs: [floor7.displacement]\n", "2:11: outputs[0]",
       "the building has 3 floors"},
      {"unknown_key", "axis: []\n", "2:1: axis", "unknown key 'axis' (did you mean 'axes'?)"},
      {"model_combination",
       "axes:\n  - {name: storeys, path: building.floors.count, values: [3, 1]}\n",
       "9:22: building.damping.superstructure.type", "(case 1: storeys=1)"},
  };
  for (const Malformed& c : cases) {
    const std::string file = std::string(c.name) + ".yaml";
    std::string message;
    try {
      const Study s = load_study_text(file, model_line() + c.body);
      validate_study(s, 2);
    } catch (const InputError& e) {
      message = e.what();
    }
    ASSERT_FALSE(message.empty()) << c.name << ": no error";
    // Combination errors of the base model point into the model file, others into the study.
    const std::string where =
        std::string(c.name) == "model_combination" ? test::thesis_model() : file;
    EXPECT_NE(message.find(where + ":" + c.located + ": "), std::string::npos)
        << c.name << ": " << message;
    EXPECT_NE(message.find(c.fragment), std::string::npos) << c.name << ": " << message;
  }
}

}  // namespace
}  // namespace isopound
