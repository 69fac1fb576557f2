// Tests of the model file reader: a full model parses to SI values, and every malformed model in
// tests/data/bad_models/ is an InputError naming the file, the line and the key path.
#include "solver/io/model_input.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>  // getpid: a temporary directory of our own

namespace isopound {
namespace {

namespace fs = std::filesystem;

const fs::path kBadModels = fs::path(ISOPOUND_SOURCE_DIR) / "tests" / "data" / "bad_models";

ModelConfig load_text(const std::string& text, const std::string& base_dir = "/models") {
  return load_model(YAML::Load(text), "inline.yaml", base_dir);
}

// Runs `load` and returns the InputError it throws (fails the test if none).
template <typename Load>
InputError input_error_of(Load load) {
  try {
    load();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", 0, 0, "", "");
}

constexpr const char* kFullModel = R"(
building:
  name: 3-storey BW
  isolated: true
  base: {mass: 340 t}
  floors:
    - {mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
    - {mass: 340 t, stiffness: 550 MN/m, height: 3.0 m}
    - {mass: 250 t, stiffness: 500000 kN/m, height: 320 cm}
  isolator:
    model: bouc_wen
    Tb: 2.5 s
    QW: 10 %
    uy: 2.5 cm
    n: 1
    A: 1
    beta: 0.6
    gamma: 0.4
    strength_is_yield_force: true
    carried_mass: 1270 t
  damping:
    superstructure: {type: rayleigh, ratio: 3 %, modes: [1, 3]}
    isolation: 0.02
ground_motion:
  record: records/quake.txt
  format: columns
  column: 2
  time_column: 0
  unit: cm/s2
  scale: 1.5
  extra_time: 5 s
analysis:
  stepping: adaptive
  dt: 0 s
  steps_per_period: 40
  tolerance: 1e-4
  max_halvings: 10
  newton_tolerance: 1e-8
  max_iterations: 40
output:
  interval: 20 ms
  histories: true
)";

TEST(ModelInputValid, FullModelParsesToSI) {
  const ModelConfig m = load_text(kFullModel, "/models/study");
  EXPECT_EQ(m.source, "inline.yaml");
  const BuildingConfig& b = m.building;
  EXPECT_EQ(b.name, "3-storey BW");
  EXPECT_TRUE(b.isolated);
  EXPECT_DOUBLE_EQ(b.base_mass, 3.4e5);
  ASSERT_EQ(b.floors.size(), 3u);
  EXPECT_DOUBLE_EQ(b.floors[0].mass, 3.4e5);
  EXPECT_DOUBLE_EQ(b.floors[0].stiffness, 6e8);
  EXPECT_DOUBLE_EQ(b.floors[1].stiffness, 5.5e8);
  EXPECT_DOUBLE_EQ(b.floors[1].height, 3.0);
  EXPECT_DOUBLE_EQ(b.floors[2].mass, 2.5e5);
  EXPECT_DOUBLE_EQ(b.floors[2].stiffness, 5e8);
  EXPECT_DOUBLE_EQ(b.floors[2].height, 3.2);

  const IsolatorConfig& iso = b.isolator;
  EXPECT_EQ(iso.model, IsolatorConfig::Model::kBoucWen);
  EXPECT_DOUBLE_EQ(iso.period, 2.5);
  EXPECT_DOUBLE_EQ(iso.strength_ratio, 0.10);
  EXPECT_DOUBLE_EQ(iso.yield_displacement, 0.025);
  EXPECT_DOUBLE_EQ(iso.bouc_wen.n, 1.0);
  EXPECT_DOUBLE_EQ(iso.bouc_wen.A, 1.0);
  EXPECT_DOUBLE_EQ(iso.bouc_wen.beta, 0.6);
  EXPECT_DOUBLE_EQ(iso.bouc_wen.gamma, 0.4);
  EXPECT_TRUE(iso.strength_is_yield_force);
  EXPECT_DOUBLE_EQ(iso.carried_mass, 1.27e6);

  EXPECT_EQ(b.damping.type, SuperstructureDamping::Type::kRayleigh);
  EXPECT_DOUBLE_EQ(b.damping.ratio, 0.03);
  EXPECT_EQ(b.damping.mode_a, 1);
  EXPECT_EQ(b.damping.mode_b, 3);
  EXPECT_DOUBLE_EQ(b.isolation_damping_ratio, 0.02);

  const GroundMotionConfig& g = m.ground_motion;
  EXPECT_FALSE(g.use_pulse);
  EXPECT_EQ(g.record_path, "/models/study/records/quake.txt");
  EXPECT_EQ(g.read.format, RecordReadOptions::Format::kColumns);
  EXPECT_EQ(g.read.column, 2);
  EXPECT_EQ(g.read.time_column, 0);
  EXPECT_EQ(g.read.unit, AccelerationUnit::kCentimetrePerSecond2);
  EXPECT_DOUBLE_EQ(g.read.scale, 1.5);
  EXPECT_DOUBLE_EQ(g.extra_time, 5.0);

  EXPECT_EQ(m.analysis.stepping, AnalysisConfig::Stepping::kAdaptive);
  EXPECT_DOUBLE_EQ(m.analysis.dt, 0.0);
  EXPECT_DOUBLE_EQ(m.analysis.steps_per_period, 40.0);
  EXPECT_DOUBLE_EQ(m.analysis.tolerance, 1e-4);
  EXPECT_EQ(m.analysis.max_halvings, 10);
  EXPECT_DOUBLE_EQ(m.analysis.newton_tolerance, 1e-8);
  EXPECT_EQ(m.analysis.max_iterations, 40);
  EXPECT_DOUBLE_EQ(m.output.interval, 0.02);
  EXPECT_TRUE(m.output.histories);
}

TEST(ModelInputValid, ShortFloorsFormAndDefaults) {
  const ModelConfig m = load_text(R"(
building:
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}
)");
  const BuildingConfig& b = m.building;
  ASSERT_EQ(b.floors.size(), 3u);
  EXPECT_DOUBLE_EQ(b.floors[0].mass, 3.4e5);
  EXPECT_DOUBLE_EQ(b.floors[1].mass, 3.4e5);
  EXPECT_DOUBLE_EQ(b.floors[2].mass, 2.5e5);
  for (const FloorConfig& f : b.floors) {
    EXPECT_DOUBLE_EQ(f.stiffness, 6e8);
    EXPECT_DOUBLE_EQ(f.height, 3.2);
  }
  // Defaults of config.h survive (thesis values).
  EXPECT_TRUE(b.isolated);
  EXPECT_EQ(b.isolator.model, IsolatorConfig::Model::kBoucWen);
  EXPECT_DOUBLE_EQ(b.isolator.strength_ratio, 0.05);
  EXPECT_EQ(b.damping.type, SuperstructureDamping::Type::kRayleigh);
  EXPECT_DOUBLE_EQ(b.isolation_damping_ratio, 0.05);
  EXPECT_TRUE(m.ground_motion.use_pulse);
  EXPECT_EQ(m.analysis.stepping, AnalysisConfig::Stepping::kAdaptive);
  EXPECT_TRUE(m.output.histories);

  // Without roof_mass every floor has `mass`.
  const ModelConfig same = load_text(
      "building: {base: {mass: 1 t}, floors: {count: 2, mass: 5 t, stiffness: 1 MN/m, height: 3 "
      "m}}");
  EXPECT_DOUBLE_EQ(same.building.floors[1].mass, 5e3);
}

TEST(ModelInputValid, PulseWithUnits) {
  const ModelConfig m = load_text(R"(
building:
  base: {mass: 340 t}
  floors: {count: 2, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}
ground_motion:
  extra_time: 2 s
  pulse: {amplitude: 80 cm/s, period: 1.5 s, gamma: 2.5, phase: 90 deg, t_peak: 3 s, duration: 12 s, dt: 10 ms}
)");
  const GroundMotionConfig& g = m.ground_motion;
  EXPECT_TRUE(g.use_pulse);
  EXPECT_DOUBLE_EQ(g.pulse.amplitude, 0.8);
  EXPECT_DOUBLE_EQ(g.pulse.period, 1.5);
  EXPECT_DOUBLE_EQ(g.pulse.gamma, 2.5);
  EXPECT_NEAR(g.pulse.phase, std::numbers::pi / 2, 1e-15);
  EXPECT_DOUBLE_EQ(g.pulse.t_peak, 3.0);
  EXPECT_DOUBLE_EQ(g.pulse.duration, 12.0);
  EXPECT_DOUBLE_EQ(g.pulse.dt, 0.01);
  EXPECT_DOUBLE_EQ(g.extra_time, 2.0);
}

TEST(ModelInputValid, FixedBaseModalDampingAndRatiosInBothForms) {
  const ModelConfig m = load_text(R"(
building:
  isolated: false
  floors:
    - {mass: 100 t, stiffness: 2500 kN/mm, height: 4 m}
  damping:
    superstructure: {type: modal, ratio: 0.05}
)");
  EXPECT_FALSE(m.building.isolated);
  EXPECT_DOUBLE_EQ(m.building.floors[0].stiffness, 2.5e9);
  EXPECT_EQ(m.building.damping.type, SuperstructureDamping::Type::kModal);
  EXPECT_DOUBLE_EQ(m.building.damping.ratio, 0.05);

  const std::string base =
      "building: {base: {mass: 1 t}, floors: {count: 2, mass: 1 t, stiffness: 1 MN/m, height: 3 "
      "m}, ";
  EXPECT_DOUBLE_EQ(load_text(base + "isolator: {QW: 5 %}}").building.isolator.strength_ratio, 0.05);
  EXPECT_DOUBLE_EQ(load_text(base + "isolator: {QW: 0.05}}").building.isolator.strength_ratio,
                   0.05);
  // A linear isolator has no strength: QW is not one of its keys.
  EXPECT_THROW(load_text(base + "isolator: {model: linear, QW: 0}}"), InputError);
}

TEST(ModelInputValid, RecordPathRelativeToTheModelFile) {
  const fs::path dir =
      fs::temp_directory_path() / ("isopound_model_input_" + std::to_string(::getpid()));
  fs::create_directories(dir / "cases");
  const fs::path file = dir / "cases" / "model.yaml";
  {
    std::ofstream out(file);
    out << "building:\n  base: {mass: 340 t}\n"
           "  floors: {count: 3, mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}\n"
           "ground_motion:\n  record: ../records/RSN1084_NORTHR_SCS052.AT2\n  format: peer\n";
  }
  const ModelConfig m = load_model_file(file.string());
  EXPECT_EQ(m.source, file.string());
  EXPECT_FALSE(m.ground_motion.use_pulse);
  EXPECT_EQ(m.ground_motion.record_path, (dir / "records" / "RSN1084_NORTHR_SCS052.AT2").string());
  EXPECT_EQ(m.ground_motion.read.format, RecordReadOptions::Format::kPeer);
  fs::remove_all(dir);

  // An absolute record path is kept as written.
  const ModelConfig absolute = load_text(
      "building: {base: {mass: 1 t}, floors: {count: 2, mass: 1 t, stiffness: 1 MN/m, height: 3 "
      "m}}\n"
      "ground_motion: {record: /data/records/x.AT2}\n",
      "/models");
  EXPECT_EQ(absolute.ground_motion.record_path, "/data/records/x.AT2");
}

TEST(ModelInputErrors, MissingFileIsLineZero) {
  const std::string path = (kBadModels / "does_not_exist.yaml").string();
  const InputError e = input_error_of([&] { load_model_file(path); });
  EXPECT_EQ(e.line(), 0);
  EXPECT_EQ(e.file(), path);
  EXPECT_EQ(std::string(e.what()), path + ": file not found");
}

TEST(ModelInputErrors, FieldsAndMessageFormat) {
  const InputError e =
      input_error_of([] { load_model_file((kBadModels / "negative_mass.yaml").string()); });
  EXPECT_EQ(e.line(), 6);
  EXPECT_EQ(e.column(), 14);  // the value "-250 t" in "    - {mass: -250 t, ..."
  EXPECT_EQ(e.key(), "building.floors[1].mass");
  EXPECT_EQ(e.detail(), "must be > 0 (got '-250 t')");
  EXPECT_EQ(std::string(e.what()),
            (kBadModels / "negative_mass.yaml").string() +
                ":6:14: building.floors[1].mass: must be > 0 (got '-250 t')");
}

// Nodes built in code have no position: the error points at the nearest parent that has one.
TEST(ModelInputErrors, NodesWithoutMarkUseTheNearestParent) {
  YAML::Node built;
  built["building"]["base"]["mass"] = "340 t";
  built["building"]["floors"]["count"] = 2;
  built["building"]["floors"]["mass"] = "-1 t";
  built["building"]["floors"]["stiffness"] = "1 MN/m";
  built["building"]["floors"]["height"] = "3 m";
  const InputError none = input_error_of([&] { load_model(built, "built", "."); });
  EXPECT_EQ(none.line(), 0);
  EXPECT_EQ(none.key(), "building.floors.mass");
  EXPECT_EQ(std::string(none.what()), "built: building.floors.mass: must be > 0 (got '-1 t')");

  YAML::Node loaded = YAML::Load(
      "building:\n"
      "  base: {mass: 340 t}\n"
      "  floors:\n"
      "    - {mass: 340 t, stiffness: 600 MN/m, height: 3.2 m}\n");
  loaded["building"]["floors"][0]["height"] =
      "-3 m";  // replaces a parsed value by one without a mark
  const InputError mixed = input_error_of([&] { load_model(loaded, "mixed.yaml", "."); });
  EXPECT_EQ(mixed.line(), 4);
  EXPECT_EQ(mixed.key(), "building.floors[0].height");
}

TEST(ModelInputErrors, ReaderHelpers) {
  const YAML::Node doc = YAML::Load("a: 2.5\nb: yes\nc: Off\nd: [1]\ne: +7\nf: 1e3\n");
  const InputNode root(doc, "h.yaml");
  EXPECT_TRUE(root.required("b").boolean());
  EXPECT_FALSE(root.required("c").boolean());
  EXPECT_EQ(root.required("e").integer(0, 10), 7);
  const InputError not_int = input_error_of([&] { root.required("a").integer(0, 10); });
  EXPECT_EQ(std::string(not_int.what()), "h.yaml:1:4: a: expected an integer, got '2.5'");
  const InputError range = input_error_of([&] { root.required("e").integer(0, 5); });
  EXPECT_EQ(range.detail(), "must be between 0 and 5 (got +7)");
  const InputError list = input_error_of([&] { root.required("d").quantity(dim::kLength); });
  EXPECT_NE(list.detail().find("got a list"), std::string::npos);
  const InputError missing = input_error_of([&] { root.required("zz"); });
  EXPECT_EQ(std::string(missing.what()), "h.yaml:1:1: zz: missing required key 'zz'");
  EXPECT_FALSE(root.has("zz"));
  EXPECT_EQ(root.find("f")->quantity(dim::kForce), 1e3);
}

// One malformed model: the file, the 1-based line the message must name (0: none), the key path
// and a fragment of the explanation.
struct BadModel {
  const char* file;
  int line;
  const char* key;
  const char* what;
};

void PrintTo(const BadModel& m, std::ostream* os) {
  *os << m.file;
}

class ModelInputBadModels : public ::testing::TestWithParam<BadModel> {};

TEST_P(ModelInputBadModels, IsAnInputErrorWithFileLineAndKey) {
  const BadModel& bad = GetParam();
  const std::string path = (kBadModels / bad.file).string();
  ASSERT_TRUE(fs::exists(path)) << path;
  const InputError e = input_error_of([&] { load_model_file(path); });
  const std::string message = e.what();
  const std::string location = bad.line > 0
                                   ? std::string(bad.file) + ":" + std::to_string(bad.line) + ":"
                                   : std::string(bad.file) + ": ";
  EXPECT_NE(message.find(location), std::string::npos) << message;
  EXPECT_EQ(e.line(), bad.line) << message;
  EXPECT_EQ(e.key(), bad.key) << message;
  if (bad.key[0] != '\0') {
    EXPECT_NE(message.find(std::string(": ") + bad.key + ": "), std::string::npos) << message;
  }
  EXPECT_NE(message.find(bad.what), std::string::npos) << message;
  EXPECT_EQ(message.find("nan"), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    ModelInputFiles, ModelInputBadModels,
    ::testing::Values(
        BadModel{"unknown_key.yaml", 9, "building.isolator.Tbb",
                 "unknown key 'Tbb' (did you mean 'Tb'?); allowed: model, Tb, QW"},
        BadModel{"negative_mass.yaml", 6, "building.floors[1].mass", "must be > 0 (got '-250 t')"},
        BadModel{"wrong_dimension.yaml", 8, "building.isolator.uy",
                 "unit 'kg' is a mass (kg), expected a length (m)"},
        BadModel{"unknown_unit.yaml", 7, "building.floors[0].stiffness", "unknown unit 'furlong'"},
        BadModel{"garbage_mass.yaml", 3, "building.base.mass", "'abc' is not a quantity"},
        BadModel{"stiffness_as_text.yaml", 4, "building.floors[0].stiffness",
                 "'stiff' is not a quantity"},
        BadModel{"map_for_number.yaml", 5, "building.isolator.Tb", "got a map"},
        BadModel{"missing_floors.yaml", 3, "building.floors", "missing required key 'floors'"},
        BadModel{"missing_base.yaml", 3, "building.base", "missing required key 'base'"},
        BadModel{"missing_building.yaml", 2, "building", "missing required key 'building'"},
        BadModel{"fixed_base_with_isolator.yaml", 4, "building.isolator",
                 "not allowed for a fixed-base building"},
        BadModel{"rayleigh_one_storey.yaml", 8, "building.damping.superstructure.type",
                 "use type: modal"},
        BadModel{"rayleigh_default_one_storey.yaml", 1, "building.damping.superstructure",
                 "use type: modal"},
        BadModel{"rayleigh_same_modes.yaml", 5, "building.damping.superstructure.modes",
                 "must differ"},
        BadModel{"rayleigh_mode_out_of_range.yaml", 8, "building.damping.superstructure.modes[1]",
                 "mode 4 does not exist"},
        BadModel{"damping_ratio_too_large.yaml", 6, "building.damping.isolation",
                 "must be in [0, 1)"},
        BadModel{"unknown_model.yaml", 5, "building.isolator.model",
                 "unknown model 'boucwen'; allowed: linear, bilinear, bouc_wen"},
        BadModel{"qw_zero_bilinear.yaml", 7, "building.isolator.QW",
                 "must be > 0 for the bilinear and bouc_wen models"},
        BadModel{"beta_gamma.yaml", 6, "building.isolator.gamma", "beta + gamma must be > 0"},
        BadModel{"n_zero.yaml", 4, "building.isolator.n", "must be >= 1"},
        BadModel{"empty_floors.yaml", 3, "building.floors", "no floors"},
        BadModel{"count_zero.yaml", 4, "building.floors.count",
                 "must be between 1 and 200 (got 0)"},
        BadModel{"floors_scalar.yaml", 3, "building.floors", "expected a list of floors"},
        BadModel{"zero_height.yaml", 6, "building.floors[2].height", "must be > 0"},
        BadModel{"duplicate_key.yaml", 7, "building.floors[0].mass",
                 "duplicate key 'mass' (first at line 4)"},
        BadModel{"bad_bool.yaml", 2, "building.isolated", "expected true or false, got 'maybe'"},
        BadModel{"unknown_stepping.yaml", 5, "analysis.stepping",
                 "unknown stepping 'implicit'; allowed: adaptive, fixed"},
        BadModel{"negative_dt.yaml", 6, "analysis.dt", "must be > 0 (got '-0.01 s')"},
        BadModel{"tolerance_zero.yaml", 5, "analysis.tolerance", "must be > 0"},
        BadModel{"max_iterations_zero.yaml", 6, "analysis.max_iterations", "must be >= 1 (got 0)"},
        BadModel{"record_and_pulse.yaml", 6, "ground_motion.pulse", "either 'record' or 'pulse'"},
        BadModel{"unknown_acceleration_unit.yaml", 8, "ground_motion.unit",
                 "unknown unit 'ft/s2'; allowed: g, m/s2"},
        BadModel{"unknown_format.yaml", 6, "ground_motion.format",
                 "unknown format 'csv'; allowed: auto, peer, columns"},
        BadModel{"columns_without_dt.yaml", 4, "ground_motion.dt", "missing required key 'dt'"},
        BadModel{"pulse_gamma.yaml", 7, "ground_motion.pulse.gamma", "must be > 1"},
        BadModel{"record_option_without_record.yaml", 5, "ground_motion.scale",
                 "no 'record' is given"},
        BadModel{"unknown_top_level.yaml", 4, "anaysis", "(did you mean 'analysis'?)"},
        BadModel{"syntax_error.yaml", 4, "", "YAML syntax error"},
        BadModel{"empty.yaml", 0, "", "the document is empty"},
        BadModel{"wall_negative_gap.yaml", 5, "building.walls.gap", "must be >= 0 (got '-5 cm')"},
        BadModel{"wall_restitution_above_one.yaml", 8, "building.walls.e",
                 "coefficient of restitution must be in (0, 1]"},
        BadModel{"wall_restitution_zero.yaml", 8, "building.walls[0].e", "must be > 0 (got '0')"},
        BadModel{"wall_k_zero.yaml", 8, "building.walls.k", "must be > 0 (got '0 kN/mm')"},
        BadModel{"wall_k_negative.yaml", 9, "building.walls.k", "must be > 0 (got '-2500 kN/mm')"},
        BadModel{"wall_unknown_law.yaml", 7, "building.walls.law",
                 "unknown law 'kelvin_voight'; allowed: linear, kelvin_voigt"},
        BadModel{"wall_unknown_material.yaml", 8, "building.walls.material",
                 "unknown material 'granite'; allowed: none, concrete"},
        BadModel{"wall_gap_and_gap_left.yaml", 7, "building.walls.gap_left",
                 "give either gap (both sides) or gap_left/gap_right"},
        BadModel{"neighbour_without_gap.yaml", 6, "neighbours[0].gap",
                 "missing required key 'gap'"},
        BadModel{"wall_level_beyond_building.yaml", 5, "building.walls.level",
                 "level 4 does not exist (levels 0..3)"}),
    [](const ::testing::TestParamInfo<BadModel>& info) {
      return fs::path(info.param.file).stem().string();
    });

}  // namespace
}  // namespace isopound
