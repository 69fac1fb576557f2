// 3D buildings (THEORY section 5): the thesis building loaded from configs/, fixed-base periods
// against an independent shear stick, reduction to the 2D model, 90-degree symmetry of a pair,
// energy balance of the eccentric building, bad inputs. Bearings: the configs' coupled Bouc-Wen law
// with the configs' own bearing law (coupled Bouc-Wen).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/core/modes.h"
#include "solver/io/model_input.h"
#include "solver/io/report3d.h"
#include "solver/structures/building2d.h"
#include "solver/structures/building3d.h"
#include "solver/structures/job.h"
#include "test_support.h"

namespace isopound {
namespace {

ModelConfig thesis_config(const char* file = "3d-thesis-building.yaml") {
  ModelConfig c = load_model_file((test::source_dir() / "configs" / file).string());
  return c;
}

// The 2D stick of the same building: storey stiffness 16 x 12 E I / h^3 from the section.
double storey_stiffness_2d() {
  const double b = 0.45, E = 30e9, h = 3.2, I = b * b * b * b / 12.0;
  return 16.0 * 12.0 * E * I / (h * h * h);
}

// Fraction of mode j's kinetic energy phi_j^T M phi_j = 1 carried by DOFs of one kind.
double kind_fraction(const LinearModel3D& m, const Modes& modes, int j, DofKind kind) {
  const Eigen::VectorXd phi = modes.shape.col(j);
  const Eigen::VectorXd mphi = m.mass * phi;
  double f = 0.0;
  for (int i = 0; i < phi.size(); ++i)
    if (m.dofs[i].kind == kind) f += phi[i] * mphi[i];
  return f;
}

TEST(Building3D, FixedBasePeriodsMatchTheShearStick) {
  const ModelConfig c = thesis_config();
  ASSERT_EQ(c.structures3d.size(), 1u);
  const LinearModel3D m = linear_model3d(c.structures3d[0], false, true);
  const Modes modes = compute_modes(m.stiffness, m.mass, m.influence.col(0));
  // Independent: the 2D stick, 340/340/250 t, k = 16 * 12 E I / h^3 (600.7 MN/m).
  BuildingConfig b2;
  const double k = storey_stiffness_2d();
  b2.floors = {{340e3, k, 3.2}, {340e3, k, 3.2}, {250e3, k, 3.2}};
  const ShearStick stick = fixed_base_superstructure(b2);
  const Modes m2 = compute_modes(stick.stiffness, stick.mass, Eigen::VectorXd::Ones(3));
  // Modes 1 and 2 are the x and y first modes (equal periods, doubly symmetric).
  EXPECT_NEAR(modes.period[0], m2.period[0], 1e-9 * m2.period[0]);
  EXPECT_NEAR(modes.period[1], m2.period[0], 1e-9 * m2.period[0]);
  EXPECT_NEAR(modes.period[0], 0.31, 0.005);  // the thesis's 0.31 s
}

TEST(Building3D, IsolatedModesTranslationalThenTorsional) {
  const ModelConfig c = thesis_config();
  const LinearModel3D m = linear_model3d(c.structures3d[0], false, false);
  const Modes modes = compute_modes(m.stiffness, m.mass, m.influence.col(0));
  // T = 2 pi sqrt(m_total / K_post,total) = T_b for the rigid isolated building: near 2 s.
  EXPECT_NEAR(modes.period[0], 2.0, 0.1);
  for (int j : {0, 1})
    EXPECT_LT(kind_fraction(m, modes, j, DofKind::kRotation), 1e-9) << "mode " << j + 1;
  EXPECT_GT(kind_fraction(m, modes, 2, DofKind::kRotation), 1.0 - 1e-9);
}

// The thesis building with the 2D model's damping, excited along x only, against the 2D model.
TEST(Building3D, ReducesToThe2DModelAlongX) {
  ModelConfig c = thesis_config();
  Building3DConfig& b = c.structures3d[0];
  BuildingConfig b2;
  b2.base_mass = 340e3;
  const double k = storey_stiffness_2d();
  b2.floors = {{340e3, k, 3.2}, {340e3, k, 3.2}, {250e3, k, 3.2}};
  b2.isolator.model = IsolatorConfig::Model::kBoucWen;
  b2.isolator.strength_ratio = b.bearing.strength_ratio;
  // Non-classical damping: superstructure Rayleigh 2 % at the 3D fixed-base modes whose
  // periods are the 2D modes 1 and 2, isolation 5 %.
  const LinearModel3D fixed = linear_model3d(b, false, true);
  const Modes m3 = compute_modes(fixed.stiffness, fixed.mass, fixed.influence.col(0));
  const ShearStick stick = fixed_base_superstructure(b2);
  const Modes m2 = compute_modes(stick.stiffness, stick.mass, Eigen::VectorXd::Ones(3));
  int modes[2] = {0, 0};
  for (int want = 0; want < 2; ++want)
    for (int j = 0; j < m3.omega.size() && !modes[want]; ++j)
      if (std::abs(m3.omega[j] - m2.omega[want]) < 1e-9 * m2.omega[want]) modes[want] = j + 1;
  ASSERT_GT(modes[0], 0);
  ASSERT_GT(modes[1], 0);
  b.damping.type = Damping3DConfig::Type::kNonClassical;
  b.damping.mode_a = modes[0];
  b.damping.mode_b = modes[1];
  b.damping.ratio_a = b.damping.ratio_b = 0.02;
  b.damping.isolation_ratio = 0.05;

  const GroundMotion motion = make_pulse(PulseParameters{});  // along x only
  RunOptions o;
  o.analysis.stepping = AnalysisConfig::Stepping::kFixed;  // the same steps in both models
  o.analysis.dt = 1e-3;
  o.output.histories = false;
  Model model3 = build_model(c);
  const AnalysisResult r3 = run_analysis(model3, motion, o);
  Model model2 = make_model(b2);
  const AnalysisResult r2 = run_analysis(model2, motion, o);
  for (int level = 0; level < 4; ++level) {
    const int i = 3 * level;
    for (auto [p3, p2] :
         {std::pair{&r3.displacement, &r2.displacement}, std::pair{&r3.velocity, &r2.velocity},
          std::pair{&r3.absolute_acceleration, &r2.absolute_acceleration}}) {
      EXPECT_NEAR((*p3)[i].value, (*p2)[level].value, 1e-6 * (*p2)[level].value) << level;
      EXPECT_LE((*p3)[i + 1].value, 1e-10) << "y response, level " << level;
      EXPECT_LE((*p3)[i + 2].value, 1e-10) << "rotation, level " << level;
    }
  }
  EXPECT_NEAR(r3.energy.input, r2.energy.input, 1e-6 * r2.energy.input);
  EXPECT_NEAR(r3.energy.hysteretic, r2.energy.hysteretic, 1e-6 * r2.energy.hysteretic);
}

// Doubly symmetric building, pulse pair: at theta + 90 deg, x and y swap (THEORY eq. 5.12-5.13).
TEST(Building3D, QuarterTurnOfThePairSwapsXAndY) {
  ModelConfig c = thesis_config();
  c.ground_motion = GroundMotionConfig{};  // the built-in pulse pair
  c.output.histories = false;
  AnalysisResult r[2];
  for (int k = 0; k < 2; ++k) {
    c.ground_motion.angle = (25.0 + 90.0 * k) * std::numbers::pi / 180.0;
    r[k] = run_job(c).analysis;
  }
  ASSERT_EQ(r[0].displacement.size(), 12u);
  for (int level = 0; level < 4; ++level) {
    const int i = 3 * level;
    const double scale = std::max(r[0].displacement[i].value, r[0].displacement[i + 1].value);
    EXPECT_NEAR(r[1].displacement[i].value, r[0].displacement[i + 1].value, 1e-9 * scale);
    EXPECT_NEAR(r[1].displacement[i + 1].value, r[0].displacement[i].value, 1e-9 * scale);
    EXPECT_NEAR(r[1].displacement[i + 2].value, r[0].displacement[i + 2].value, 1e-9 * scale);
  }
  for (std::size_t p = 0; p < r[0].probes.size(); ++p)
    EXPECT_NEAR(r[1].probes[p].resultant.value, r[0].probes[p].resultant.value,
                1e-9 * std::max(r[0].probes[p].resultant.value, 1e-3))
        << p;  // CM and column resultants of a quarter-turn-symmetric building
}

// summary.json's 3D section uses the one peak shape of the 2D summary ({value, unit, time_s,
// positive, negative, ...}); its numbers are the analysis' own, and the envelope over columns is
// the largest column.
TEST(Building3D, SummaryPeaksHaveTheCommonShape) {
  ModelConfig c = thesis_config();
  c.ground_motion = GroundMotionConfig{};  // the built-in pulse pair
  c.ground_motion.angle = 0.4;
  c.output.histories = false;
  const JobResult job = run_job(c);
  const nlohmann::json j = summary3d_json(job);
  ASSERT_EQ(j.size(), 1u);
  const auto expect_peak = [](const nlohmann::json& p, const char* unit, const std::string& where) {
    ASSERT_TRUE(p.is_object()) << where;
    EXPECT_EQ(p.at("unit"), unit) << where;
    for (const char* k : {"value", "time_s", "positive", "negative"})
      EXPECT_TRUE(p.at(k).is_number()) << where << " " << k;
    EXPECT_DOUBLE_EQ(p.at("value").get<double>(),
                     std::max(p.at("positive").get<double>(), -p.at("negative").get<double>()))
        << where;
  };
  const nlohmann::json& base = j[0]["levels"][0];
  expect_peak(base["u"], "m", "base u");
  expect_peak(base["theta"], "rad", "base theta");
  EXPECT_DOUBLE_EQ(base["u"]["value"].get<double>(), job.analysis.displacement[0].value);
  expect_peak(base["centre_of_mass"]["displacement"]["resultant"], "m", "CM");
  expect_peak(base["centre_of_mass"]["absolute_acceleration"]["x"], "m/s2", "CM acc");
  expect_peak(base["corners"][0]["displacement"]["resultant"], "m", "corner");
  const nlohmann::json& storey = j[0]["storeys"][0];
  double largest = 0.0;
  for (const auto& column : storey["columns"]) {
    expect_peak(column["resultant"], "m", "column");
    expect_peak(column["drift_ratio"], "-", "column ratio");
    largest = std::max(largest, column["resultant"]["value"].get<double>());
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_DOUBLE_EQ(storey["envelope_over_columns"]["resultant"]["value"].get<double>(), largest);
  EXPECT_EQ(storey["corner_columns"].size(), 4u);  // A1, D1, A4, D4
  const nlohmann::json& bearing = j[0]["bearings"][0];
  expect_peak(bearing["force"], "N", "bearing force");
  expect_peak(bearing["deformation"], "m", "bearing deformation");
}

// Two buildings in one model: one at the origin, one placed at (40 m, 12 m) and turned by 90
// degrees (a square grid turned by a quarter is the same building, so its centre of mass moves
// exactly as the first's), plus a fixed-base building.
TEST(Building3D, SeveralStructuresPlacedInPlan) {
  ModelConfig c = thesis_config();
  c.ground_motion = GroundMotionConfig{};  // pulse pair
  c.ground_motion.angle = 0.3;
  c.output.histories = false;
  Building3DConfig moved = c.structures3d[0];
  moved.name = "moved";
  moved.position = {40.0, 12.0};
  moved.rotation = std::numbers::pi / 2;
  Building3DConfig fixed = c.structures3d[0];
  fixed.name = "fixed";
  fixed.isolated = false;
  fixed.position = {-40.0, 0.0};
  c.structures3d.push_back(moved);
  c.structures3d.push_back(fixed);
  const JobResult job = run_job(c);
  const AnalysisResult& r = job.analysis;
  ASSERT_EQ(job.model.size(), 12 + 12 + 9);
  // Centre-of-mass probes of the moved building equal the first's.
  const auto probe = [&](const std::string& label) -> const ProbePeaks& {
    for (std::size_t p = 0; p < job.model.probes.size(); ++p)
      if (job.model.probes[p].label == label &&
          job.model.probes[p].quantity == PlanProbe::Quantity::kDisplacement)
        return r.probes[p];
    ADD_FAILURE() << "no probe " << label;
    return r.probes[0];
  };
  for (const char* level : {"base", "floor 1", "floor 3"}) {
    const ProbePeaks& a = probe(std::string("building/") + level + "/CM");
    const ProbePeaks& b = probe(std::string("moved/") + level + "/CM");
    EXPECT_NEAR(b.x.value, a.x.value, 1e-9 * a.resultant.value) << level;
    EXPECT_NEAR(b.y.value, a.y.value, 1e-9 * a.resultant.value) << level;
    EXPECT_NEAR(b.resultant.value, a.resultant.value, 1e-9 * a.resultant.value) << level;
  }
  // The fixed-base building drifts (a storey-1 column relative to the ground) but has no base.
  EXPECT_GT(probe("fixed/floor 1/CM").resultant.value, 1e-4);
  EXPECT_FALSE(job.model.structures[2].has_base);
}

// The eccentric validation building under the RSN1084 pair at 30 degrees.
TEST(Building3D, EccentricBuildingEnergyBalance) {
  ISOPOUND_REQUIRE_RECORDS();
  ModelConfig c = thesis_config("3d-eccentric-v30.yaml");
  c.output.histories = false;
  const JobResult job = run_job(c);
  const EnergyBalance& e = job.analysis.energy;
  EXPECT_GT(e.input, 1e6);            // J: about 10 MJ
  EXPECT_LT(e.relative_error, 1e-3);  // the 0.1 %
  EXPECT_LT(e.max_relative_error, 1e-3);
  // Torsion: the eccentric building twists.
  EXPECT_GT(job.analysis.displacement[2].value, 1e-5);
}

}  // namespace
}  // namespace isopound
