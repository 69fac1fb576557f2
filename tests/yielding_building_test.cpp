// 2D buildings with yielding storeys (issue 23): the elastic limit, the energy balance with
// yielding storeys and moat walls, damage measures and the elastic-range warning in the outputs,
// and bad hysteresis input (file:line and key).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "solver/io/model_input.h"
#include "solver/io/report.h"
#include "solver/io/report_modes2d.h"
#include "solver/io/yaml_reader.h"
#include "solver/structures/job.h"
#include "solver/study/study_outputs.h"
#include "tests/model_test_support.h"

namespace isopound {
namespace {

// The thesis 3-storey building against Kelvin-Voigt walls at 20 cm under a strong pulse;
// `floors_extra` is appended inside the floors map (e.g. a hysteresis).
std::string thesis_model(const std::string& floors_extra, const std::string& building_extra = "",
                         const std::string& amplitude = "1.2 m/s") {
  return R"(
building:
  name: b
  base: {mass: 340 t}
  floors: {count: 3, mass: 340 t, roof_mass: 250 t, stiffness: 600 MN/m, height: 3.2 m)" +
         floors_extra + R"(}
  isolator: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm}
  damping:
    superstructure: {type: rayleigh, ratio: 2 %, modes: [1, 2]}
    isolation: 5 %
  walls: {sides: both, level: 0, gap: 20 cm, mass: 500 t, law: kelvin_voigt, k: 2500 kN/mm, e: 0.7})" +
         building_extra + R"(
ground_motion:
  extra_time: 4 s
  pulse: {amplitude: )" +
         amplitude +
         R"(, period: 1.0 s, gamma: 2.5, phase: 90 deg, t_peak: 2 s, duration: 5 s, dt: 5 ms}
)";
}

constexpr const char* kFineFixedStep = "analysis: {stepping: fixed, dt: 0.1 ms}\n";

ModelConfig load_text(const std::string& text) {
  return load_model(YAML::Load(text), "inline.yaml", ".");
}

double relative(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale > 0 ? std::abs(a - b) / scale : 0.0;
}

void expect_same_peaks(const std::vector<Peak>& a, const std::vector<Peak>& b, double tol,
                       const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_LE(relative(a[i].value, b[i].value), tol) << what << " " << i;
    EXPECT_LE(relative(a[i].positive, b[i].positive), tol) << what << " " << i;
    EXPECT_LE(relative(a[i].negative, b[i].negative), tol) << what << " " << i;
  }
}

// A bilinear storey whose yield drift is 100 m never yields: every peak is the elastic model's.
TEST(YieldingBuilding, BilinearWithAHugeYieldDriftIsTheElasticModel) {
  const JobResult elastic = run_job(load_text(thesis_model("")));
  const JobResult bilinear = run_job(load_text(thesis_model(
      ", hysteresis: {model: bilinear, yield_shear: 60000 MN, post_yield_ratio: 5 %}")));
  const AnalysisResult& e = elastic.analysis;
  const AnalysisResult& b = bilinear.analysis;
  ASSERT_GT(e.drift_ratio[0].value, 0.002);  // the pulse loads the storeys
  expect_same_peaks(e.displacement, b.displacement, 1e-9, "displacement");
  expect_same_peaks(e.velocity, b.velocity, 1e-9, "velocity");
  expect_same_peaks(e.absolute_acceleration, b.absolute_acceleration, 1e-9, "acceleration");
  expect_same_peaks(e.drift, b.drift, 1e-9, "drift");
  expect_same_peaks(e.story_shear, b.story_shear, 1e-9, "story shear");
  expect_same_peaks(e.base_shear, b.base_shear, 1e-9, "base shear");
  const nlohmann::json s = summary_json(
      load_text(thesis_model(
          ", hysteresis: {model: bilinear, yield_shear: 60000 MN, post_yield_ratio: 5 %}")),
      bilinear);
  EXPECT_FALSE(s["structures"][0]["stories"][0]["yielded"].get<bool>());
  EXPECT_TRUE(s["structures"][0]["stories"][0]["first_yield_time_s"].is_null());
}

// Bouc-Wen storeys yielding while the base pounds the walls: the balance closes, the storeys'
// dissipated energy is booked apart and the damage measures are consistent with the peaks.
TEST(YieldingBuilding, EnergyBalanceAndDamageMeasuresWithBoucWenStoreys) {
  // The balance's error is the trapezoidal rule's on the powers, O(h^2) as for the elastic
  // model (8.8e-5 elastic, 5.6e-5 yielding at the default adaptive steps): a fixed 0.1 ms step
  // takes it below 1e-6.
  const ModelConfig config = load_text(
      thesis_model(
          ", hysteresis: {model: bouc_wen, yield_drift_ratio: 0.5 %, post_yield_ratio: 5 %}") +
      kFineFixedStep);
  const JobResult job = run_job(config);
  const AnalysisResult& r = job.analysis;
  EXPECT_LT(r.energy.relative_error, 1e-6);
  const nlohmann::json s = summary_json(config, job);
  const nlohmann::json& story1 = s["structures"][0]["stories"][0];
  ASSERT_TRUE(story1["yielded"].get<bool>()) << story1.dump();
  EXPECT_NEAR(story1["ductility"].get<double>(), r.drift[0].value / 0.016, 1e-12);
  EXPECT_GT(story1["ductility"].get<double>(), 1.0);
  EXPECT_GT(story1["first_yield_time_s"].get<double>(), 0.0);
  EXPECT_GT(story1["hysteretic_energy_J"].get<double>(), 0.0);
  const double residual = r.final_displacement[1] - r.final_displacement[0];
  EXPECT_DOUBLE_EQ(story1["residual_drift_m"].get<double>(), residual);
  const nlohmann::json& en = s["energy"];
  const double stories = en["story_hysteretic_J"].get<double>();
  EXPECT_GT(stories, 0.0);
  EXPECT_NEAR(
      en["isolator_hysteretic_J"].get<double>() + en["impact_dissipated_J"].get<double>() + stories,
      en["hysteretic_J"].get<double>(), 1e-9 * en["input_J"].get<double>());
  // The study outputs read the same measures.
  const auto study = [&](const char* text) {
    return evaluate_output(resolve_output(parse_output_selector(text), job.model), r,
                           job.motion_peaks);
  };
  EXPECT_DOUBLE_EQ(study("story1.ductility"), story1["ductility"].get<double>());
  double residual_ratio = 0.0;
  for (const auto& st : s["structures"][0]["stories"])
    residual_ratio = std::max(residual_ratio, std::abs(st["residual_drift_ratio"].get<double>()));
  EXPECT_DOUBLE_EQ(study("stories.residual_drift_ratio"), residual_ratio);
  EXPECT_GT(study("stories.hysteretic_energy"), 0.0);
  std::ostringstream console;
  print_summary(console, config, job);
  EXPECT_NE(console.str().find("ductility"), std::string::npos) << console.str();
  EXPECT_NE(console.str().find("storey hysteretic"), std::string::npos);
}

TEST(YieldingBuilding, PeakOrientedStoreysWithPDeltaRunAndCloseTheBalance) {
  const ModelConfig config = load_text(
      thesis_model(
          ", hysteresis: {model: peak_oriented, yield_drift_ratio: 0.5 %, post_yield_ratio: 3 %, "
          "capping_drift_ratio: 2 %, post_capping_ratio: 10 %, residual_strength_ratio: 0.2, "
          "deterioration: 50}",
          "\n  p_delta: true") +
      kFineFixedStep);
  const JobResult job = run_job(config);
  EXPECT_LT(job.analysis.energy.relative_error, 1e-6);
  EXPECT_GT(job.analysis.drift[0].value, 0.016);
}

TEST(YieldingBuilding, PDeltaAddsTheGeometricStiffness) {
  const ModelConfig plain = load_text(thesis_model(""));
  const ModelConfig delta = load_text(thesis_model("", "\n  p_delta: true"));
  const Model a = build_model(plain), b = build_model(delta);
  // Storey 1 carries 340 + 340 + 250 t over 3.2 m: K_11 (floor 1) loses P1/h + P2/h.
  const double p1 = 9.81 * 930e3 / 3.2, p2 = 9.81 * 590e3 / 3.2;
  EXPECT_NEAR(a.stiffness(1, 1) - b.stiffness(1, 1), p1 + p2, 1e-6);
  EXPECT_NEAR(a.stiffness(0, 0) - b.stiffness(0, 0), p1, 1e-6);
  EXPECT_NEAR(a.stiffness(0, 1) - b.stiffness(0, 1), -p1, 1e-6);
}

TEST(YieldingBuilding, AnElasticStoreyBeyondItsLimitIsFlagged) {
  const ModelConfig config = load_text(thesis_model("", "\n  elastic_limit_drift_ratio: 0.1 %"));
  const JobResult job = run_job(config);
  ASSERT_GT(job.analysis.drift_ratio[0].value, 0.001);
  const nlohmann::json s = summary_json(config, job);
  EXPECT_TRUE(s["structures"][0]["stories"][0]["elastic_limit_exceeded"].get<bool>());
  std::ostringstream console;
  print_summary(console, config, job);
  EXPECT_NE(console.str().find("warning: b/story 1 is elastic"), std::string::npos)
      << console.str();
  EXPECT_THROW(resolve_output(parse_output_selector("story1.ductility"), job.model),
               std::invalid_argument);
  // Within the default 1 %: no flag, no warning (the elastic summary is as before).
  const ModelConfig quiet = load_text(thesis_model("", "", "0.2 m/s"));
  const JobResult calm = run_job(quiet);
  ASSERT_LT(calm.analysis.drift_ratio[0].value, 0.01);
  EXPECT_FALSE(
      summary_json(quiet, calm)["structures"][0]["stories"][0].contains("elastic_limit_exceeded"));
}

struct BadHysteresis {
  const char* hysteresis;
  const char* key;
  const char* what;
};

class YieldingBuildingBadInput : public ::testing::TestWithParam<BadHysteresis> {};

TEST_P(YieldingBuildingBadInput, IsAnInputErrorAtTheKey) {
  const std::string text = thesis_model(std::string(", hysteresis: ") + GetParam().hysteresis);
  try {
    load_text(text);
    FAIL() << "no InputError for " << GetParam().hysteresis;
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), GetParam().key) << e.what();
    EXPECT_EQ(e.line(), 5) << e.what();
    EXPECT_NE(std::string(e.what()).find(GetParam().what), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("inline.yaml:5:"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Hysteresis, YieldingBuildingBadInput,
    ::testing::Values(
        BadHysteresis{"{model: bilinear, yield_drift_ratio: 0}",
                      "building.floors.hysteresis.yield_drift_ratio", "must be > 0"},
        BadHysteresis{"{model: bilinear, yield_drift_ratio: -1 %}",
                      "building.floors.hysteresis.yield_drift_ratio", "must be > 0"},
        BadHysteresis{"{model: bilinear, yield_drift_ratio: 1 %, post_yield_ratio: 1}",
                      "building.floors.hysteresis.post_yield_ratio", "must be in [0, 1)"},
        BadHysteresis{"{model: bouc_wen, yield_drift_ratio: 1 %, post_yield_ratio: -5 %}",
                      "building.floors.hysteresis.post_yield_ratio",
                      "is impossible for a post-yield stiffness ratio"},
        BadHysteresis{"{model: peak_oriented, yield_drift_ratio: 1 %, capping_drift_ratio: 0.5 %, "
                      "post_capping_ratio: 0.1}",
                      "building.floors.hysteresis.capping_drift_ratio",
                      "must be beyond the yield drift"},
        BadHysteresis{"{model: peak_oriented, yield_drift_ratio: 1 %, capping_drift_ratio: 3 %, "
                      "post_capping_ratio: 0.1, residual_strength_ratio: 1.2}",
                      "building.floors.hysteresis.residual_strength_ratio",
                      "is impossible for a residual strength ratio"},
        BadHysteresis{"{model: bilinear, yield_drift_ratio: 1 %, n: 2}",
                      "building.floors.hysteresis.n", "is not used with model: bilinear"},
        BadHysteresis{"{model: bouc_wen, yield_drift_ratio: 1 %, deterioration: 20}",
                      "building.floors.hysteresis.deterioration",
                      "is not used with model: bouc_wen"},
        BadHysteresis{"{model: bilinear, yield_drift_ratio: 1 %, yield_shear: 2 MN}",
                      "building.floors.hysteresis.yield_shear", "give one of"},
        BadHysteresis{"{model: bilinear}", "building.floors.hysteresis.yield_drift_ratio",
                      "missing"}));

// Issue 37: `isopound modes` (and isopound-pre) on a building with yielding storeys refused it
// as a mechanism: the storeys' stiffness is in their elements, not in the model's linear K. The
// periods are now those of the initial (elastic) model: the same table, digit for digit, as for
// the building with its storeys elastic.
TEST(YieldingBuilding, ModesAreThoseOfTheInitialElasticModel) {
  ISOPOUND_REQUIRE_RECORDS();
  for (const char* name :
       {"thesis-3storey-bw-yielding.yaml", "thesis-3storey-peak-oriented-pdelta.yaml"}) {
    const ModelConfig yielding = test::load_shipped_config(name);
    BuildingConfig elastic = yielding.building;
    for (FloorConfig& f : elastic.floors) f.hysteresis = StoryHysteresisConfig{};
    std::ostringstream a, b;
    print_modes2d(a, yielding.building);
    print_modes2d(b, elastic);
    EXPECT_EQ(a.str(), b.str()) << name;
    EXPECT_NE(a.str().find("Isolated, isolators at their initial stiffness"), std::string::npos);
  }
}

}  // namespace
}  // namespace isopound
