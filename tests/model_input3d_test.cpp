// The 3D model format: a valid building parses to SI values; each bad input of the issue is an
// InputError naming the line and the key path (and `isopound check` exits with 2).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "solver/io/model_input.h"
#include "solver/structures/config3d.h"
#include "test_support.h"

namespace isopound {
namespace {

ModelConfig load_text(const std::string& text) {
  return load_model(YAML::Load(text), "inline.yaml", "/models");
}

struct Bad {
  std::string text;
  int line;
  std::string key;   // the key path the error names
  std::string what;  // a fragment of the message
};

constexpr const char* kBuilding = R"(structures:
  - name: b
    grid: {bays_x: [5.5 m, 5.5 m], bays_y: [5.5 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.2 m, mass: 340 t}
    base: {mass: 340 t}
    bearing: {model: bouc_wen_uncoupled, QW: 10 %}
)";

TEST(ModelInput3D, GridBuildingParses) {
  const ModelConfig c = load_text(kBuilding);
  ASSERT_EQ(c.structures3d.size(), 1u);
  const Building3DConfig& b = c.structures3d[0];
  ASSERT_EQ(b.storeys.size(), 2u);
  ASSERT_EQ(b.storeys[0].columns.size(), 6u);  // 3 x 2 grid lines
  EXPECT_EQ(b.storeys[0].columns.front().label, "A1");
  EXPECT_EQ(b.storeys[0].columns.back().label, "C2");
  EXPECT_DOUBLE_EQ(b.storeys[0].columns[0].position.x, -5.5);  // grid centred
  EXPECT_DOUBLE_EQ(b.storeys[0].columns[0].position.y, -2.75);
  EXPECT_DOUBLE_EQ(b.storeys[0].columns[0].I11, 0.45 * 0.45 * 0.45 * 0.45 / 12.0);
  EXPECT_DOUBLE_EQ(b.storeys[0].columns[0].G, 30e9 / 2.4);
  EXPECT_DOUBLE_EQ(b.bearing.strength_ratio, 0.10);
}

TEST(ModelInput3D, BadInputsNameLineAndKey) {
  const std::string base = kBuilding;
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string s = base;
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  const std::string pair_records =
      "ground_motion:\n  L: {record: a.txt, format: columns, dt: 0.01 s, unit: g}\n";
  const Bad cases[] = {
      {with("grid: {bays_x: [5.5 m, 5.5 m], bays_y: [5.5 m]}",
            "grid: {bays_x: [5.5 m, 5.5 m], bays_y: [5.5 m]}\n    plan: {polygon: [[-6, -3], "
            "[6, -3], [-1, 0], [6, 3], [-6, 3]]}"),
       6, "structures[0].storeys", "outside"},  // an arrow whose notch holds columns C1, C2
      {with("grid: {bays_x: [5.5 m, 5.5 m], bays_y: [5.5 m]}",
            "grid: {bays_x: [5.5 m, 5.5 m], bays_y: [5.5 m]}\n    plan: {polygon: [[-6, -3], "
            "[6, 3], [6, -3], [-6, 3]]}"),
       4, "structures[0].plan.polygon", "simple polygon"},  // self-intersecting (a bow tie)
      {with(
           "grid: {bays_x: [5.5 m, 5.5 m], bays_y: [5.5 m]}",
           "grid: {bays_x: [5.5 m, 5.5 m], bays_y: [5.5 m]}\n    plan: {rectangle: [10 m, 5.5 m]}"),
       6, "structures[0].storeys", "outside"},
      {with("section: [45 cm, 45 cm]", "section: [0 cm, 45 cm]"), 4,
       "structures[0].columns.section[0]", ""},
      {with("height: 3.2 m", "height: -3.2 m"), 5, "structures[0].storeys.height", ""},
      {with("mass: 340 t}\n    base", "mass: 0 t}\n    base"), 5, "structures[0].storeys.mass", ""},
      {base + pair_records + "  angle: 30 deg\n", 10, "ground_motion.angle", "both components"},
      {base + pair_records + "  T: {record: b.txt, format: columns, dt: 0.01 s, unit: cm/s2}\n", 10,
       "ground_motion.T.unit", "unit"},
      {with("    base: {mass: 340 t}\n",
            "    base: {mass: 340 t}\n    bearings: [{at: [20 m, 0 m]}]\n"),
       7, "structures[0].bearings[0].at", "outside"},
      // The bearing law reads only its own keys (the key rule): friction keys with Bouc-Wen,
      // Bouc-Wen keys with the friction pendulum, are refused; R is required for the pendulum.
      {with("bearing: {model: bouc_wen_uncoupled, QW: 10 %}",
            "bearing: {model: bouc_wen_uncoupled, QW: 10 %, R: 2 m}"),
       7, "structures[0].bearing.R", "not used"},
      {with("bearing: {model: bouc_wen_uncoupled, QW: 10 %}",
            "bearing: {model: friction_pendulum, R: 2 m, mu_slow: 5 %, mu_fast: 5 %, Tb: 2 s}"),
       7, "structures[0].bearing.Tb", "not used"},
      {with("bearing: {model: bouc_wen_uncoupled, QW: 10 %}",
            "bearing: {model: friction_pendulum, mu_slow: 5 %, mu_fast: 5 %}"),
       7, "structures[0].bearing.R", "missing required key"},
  };
  for (const Bad& c : cases) {
    try {
      load_text(c.text);
      ADD_FAILURE() << "no error for:\n" << c.text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), c.line) << e.what();
      EXPECT_EQ(e.key(), c.key) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.what), std::string::npos) << e.what();
    }
  }
}

// Collinear vertices, as drawings have them (a vertex in the middle of a side; an L whose notch
// has no size), are not corners: the plan is the rectangle's, the same numbers.
TEST(ModelInput3D, CollinearPlanVerticesAreDropped) {
  const std::string base = kBuilding;
  const auto with_plan = [&](const std::string& plan) {
    std::string text = base;
    const std::string grid = "grid: {bays_x: [5.5 m, 5.5 m], bays_y: [5.5 m]}";
    return text.replace(text.find(grid), grid.size(), grid + "\n    plan: " + plan);
  };
  const ModelConfig rect = load_text(with_plan("{rectangle: [12 m, 6 m]}"));
  const ModelConfig drawn = load_text(
      with_plan("{polygon: [[-6, -3], [0, -3], [6, -3], [6, 0], [6, 3], [0, 3], [-6, 3]]}"));
  const Building3DConfig& r = rect.structures3d[0];
  const Building3DConfig& d = drawn.structures3d[0];
  ASSERT_EQ(d.storeys[0].floor.plan.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(d.storeys[0].floor.plan[k].x, r.storeys[0].floor.plan[k].x) << k;
    EXPECT_EQ(d.storeys[0].floor.plan[k].y, r.storeys[0].floor.plan[k].y) << k;
  }
}

TEST(ModelInput3D, TutorialAndThesisConfigsParse) {
  const ModelConfig t =
      load_model_file((test::source_dir() / "configs" / "tutorial-3d.yaml").string());
  ASSERT_EQ(t.structures3d.size(), 1u);
  ASSERT_EQ(t.ground_motion.components.size(), 2u);
  EXPECT_NEAR(t.ground_motion.angle, 30.0 * 3.14159265358979323846 / 180.0, 1e-15);
  EXPECT_EQ(t.structures3d[0].storeys[0].columns.size(), 16u);
  const ModelConfig e =
      load_model_file((test::source_dir() / "configs" / "3d-eccentric-v30.yaml").string());
  EXPECT_DOUBLE_EQ(e.structures3d[0].base.eccentricity.x, 0.60);
  EXPECT_DOUBLE_EQ(e.structures3d[0].storeys[2].floor.eccentricity.y, 0.60);
  EXPECT_DOUBLE_EQ(e.structures3d[0].bearing.strength_ratio, 0.10);
}

TEST(ModelInput3D, CheckCommandExitsWith2) {
  const std::string path = ::testing::TempDir() + "bad3d.yaml";
  {
    std::ofstream f(path);
    f << "structures:\n  - name: b\n    storeys: {count: 1, height: 0 m, mass: 1 t}\n";
  }
  const test::CommandResult r = test::run_isopound("check " + path);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("bad3d.yaml:3:"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace isopound
