// Rubber bumpers on 3D moat walls (issue 27; docs/impact-laws.md, "Bumpers on moat walls (3D)"):
// the rubber strip's law against closed forms, a free impact's dissipation against e, zero
// thickness = the bare wall, from/to, passivity per contact episode with bottoming, bad input,
// and (records) XY-5 with 10 cm bumpers at defaults against a converged fixed step.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>

#include "peak_comparison.h"
#include "solver/core/analysis.h"
#include "solver/elements/polygon_contact.h"
#include "solver/excitation/ground_motion.h"
#include "solver/io/model_input.h"
#include "solver/io/report3d.h"
#include "solver/materials/bumper_law.h"
#include "solver/structures/bumper_layer3d.h"
#include "solver/structures/job.h"
#include "solver/structures/pounding3d.h"
#include "test_support.h"
#include "tests/model_test_support.h"

namespace isopound {
namespace {

constexpr double kSlabMass = 340e3, kSide = 10.0, kNormal = 2.58e10;

MoatBumper3DConfig rubber(double thickness, const std::string& law = "linear", double e = 0.8) {
  MoatBumper3DConfig b;
  b.on = {true, true, true, true};
  b.thickness = thickness;
  b.law = law;
  b.modulus = 10e6;
  b.height = 0.5;
  b.e = e;
  return b;
}

// A square slab (side kSide, centred at the origin) translating in plan: DOFs u, v.
PolygonBody slab() {
  const double a = 0.5 * kSide;
  return {0, 1, -1, {0, 0}, ConvexPolygon{{-a, -a}, {a, -a}, {a, a}, {-a, a}}, kSlabMass};
}

// The rubber strip of `b` whose front face is at x = face (looking towards −x), 20 m long,
// fixed (an immovable wall: m_eff = the slab's mass).
PolygonBody strip_at(double face, const MoatBumper3DConfig& b) {
  const double s = b.max_strain * b.thickness;
  return {-1,
          -1,
          -1,
          {0, 0},
          ConvexPolygon{{face, -10.0}, {face + s, -10.0}, {face + s, 10.0}, {face, 10.0}},
          std::numeric_limits<double>::infinity()};
}

PolygonContactConfig rubber_contact(const MoatBumper3DConfig& b) {
  PolygonContactConfig cfg;
  cfg.friction = false;
  cfg.length_law = bumper_rubber_law(b, kNormal);
  return cfg;
}

// F_N of a face-on state: the slab δ past the strip's face, approaching at `rate` (the onset's
// v_imp is that rate too, the state being the contact's first).
double face_on_force(const MoatBumper3DConfig& b, double delta, double rate) {
  PolygonContact c("c", slab(), strip_at(0.5 * kSide + 0.01, b), rubber_contact(b));
  c.begin_step(1e-4, false);
  c.set_trial(Eigen::Vector2d(0.01 + delta, 0), Eigen::Vector2d(rate, 0));
  return c.snapshot().normal_force;
}

// The overlap is L δ (L = kSide): linear F_N = (E h / t) L δ (1 + ζ δ̇/v_imp), Hertz-type
// F_N = E h L (δ/t)^1.5 (1 + ζ δ̇/v_imp), with v_imp = δ̇ at the onset.
TEST(Bumper3DRubber, FaceOnForceIsTheClosedForm) {
  const double delta = 0.02, rate = 0.3;
  for (const char* law : {"linear", "hertz"}) {
    SCOPED_TRACE(law);
    const MoatBumper3DConfig b = rubber(0.1, law);
    const double expected_static =
        std::string(law) == "linear"
            ? b.modulus * b.height / b.thickness * kSide * delta
            : b.modulus * b.height * kSide * std::pow(delta / b.thickness, 1.5);
    EXPECT_NEAR(face_on_force(b, delta, 0.0), expected_static, 1e-9 * expected_static);
    const double zeta = hunt_crossley_factor(b.e);
    EXPECT_NEAR(face_on_force(b, delta, rate), expected_static * (1 + zeta),
                1e-9 * expected_static);
  }
}

using test::still;

// A free slab thrown face-on at v0 into a soft, thick linear rubber that never bottoms out,
// through run_analysis at defaults: the peak indentation of the undamped law (e = 1) is
// v0 √(m / (k L)), k = E h / t, and with e = 0.8 the contact dissipates ½ m v0² (1 − e²) (the
// Hunt–Crossley factor's exact restitution, independent of the stiffness).
TEST(Bumper3DRubber, SoftThickRubberFreeImpactMatchesTheLinearLaw) {
  const double v0 = 1.0;
  for (const double e : {1.0, 0.8}) {
    SCOPED_TRACE("e = " + std::to_string(e));
    MoatBumper3DConfig b = rubber(1.0, "linear", e);  // k L = 50 MN/m: 8 cm at 1 m/s, s = 60 cm
    Model m;
    m.dofs = {{"slab (x)", 0, 0}, {"slab (y)", 0, 0}};
    m.mass = kSlabMass * Eigen::MatrixXd::Identity(2, 2);
    m.stiffness = Eigen::MatrixXd::Zero(2, 2);
    m.damping = Eigen::MatrixXd::Zero(2, 2);
    m.influence = Eigen::VectorXd::Zero(2);
    m.elements.push_back(std::make_unique<PolygonContact>(
        "c", slab(), strip_at(0.5 * kSide + 0.01, b), rubber_contact(b)));
    RunOptions o;
    o.initial_velocity = Eigen::Vector2d(v0, 0);
    const AnalysisResult r = run_analysis(m, still(1.0, 1e-3), o);
    const auto* c = static_cast<const PolygonContact*>(m.elements[0].get());
    EXPECT_EQ(c->impacts(), 1);
    EXPECT_EQ(c->episodes(), 1);
    const double k = b.modulus * b.height / b.thickness * kSide;
    if (e == 1.0) {
      const double peak = v0 * std::sqrt(kSlabMass / k);
      EXPECT_NEAR(r.element_outputs[0][3].value, peak, 2e-3 * peak);
    }
    const double dissipated = 0.5 * kSlabMass * v0 * v0 * (1 - e * e);
    EXPECT_NEAR(c->output(10), dissipated, 1e-2 * 0.5 * kSlabMass * v0 * v0);
  }
}

ModelConfig load_text(const std::string& text) {
  return load_model(YAML::Load(text), "inline.yaml", "/models");
}

// The thesis building (3 storeys, 3 x 3 bays of 5.5 m) with walls.
std::string walled_building(const std::string& walls, const std::string& extra = "") {
  return R"(structures:
  - name: building
    grid: {bays_x: [5.5 m, 5.5 m, 5.5 m], bays_y: [5.5 m, 5.5 m, 5.5 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 3, height: 3.2 m, mass: 340 t, roof_mass: 250 t}
    base: {mass: 340 t}
    bearing: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm}
    damping: {type: none}
)" + extra +
         "    walls: " + walls + "\n";
}

struct Outcome {
  Model model;
  AnalysisResult result;
};

Outcome run(const ModelConfig& c, double t_end = 3.3) {
  RunOptions o;
  o.output.histories = false;
  o.analysis.t_end = t_end;
  Outcome r{build_model(c), {}};
  r.result = run_analysis(r.model, make_pulse(PulseParameters{}), o);  // along x only
  return r;
}

std::vector<test::NamedPeak> level_peaks(const AnalysisResult& r) {
  std::vector<test::NamedPeak> p;
  for (std::size_t i = 0; i < r.displacement.size(); ++i) {
    p.push_back({"u " + std::to_string(i), r.displacement[i].value});
    p.push_back({"a " + std::to_string(i), r.absolute_acceleration[i].value});
  }
  return p;
}

int impacts_of(const Model& m, const std::string& label) {
  for (const auto& e : m.elements)
    if (e->label() == label) return static_cast<const PolygonContact&>(*e).impacts();
  ADD_FAILURE() << "no contact " << label;
  return -1;
}

// Thickness 0 builds no bumper: every peak equals the bare wall's (to 1e-9: they are the same).
TEST(Bumper3D, ZeroThicknessIsTheBareWall) {
  const std::string walls = "{sides: [east, west], gap: 8 cm}";
  const Outcome bare = run(load_text(walled_building(walls)));
  const Outcome zero = run(load_text(walled_building(
      "{sides: [east, west], gap: 8 cm, bumper: {thickness: 0 cm, E: 10 MPa, height: 50 cm, "
      "e: 0.8}}")));
  EXPECT_EQ(zero.model.elements.size(), bare.model.elements.size());
  EXPECT_GE(impacts_of(bare.model, "building/base|wall east"), 1);
  const test::Comparison c = test::compare(level_peaks(zero.result), level_peaks(bare.result));
  EXPECT_LE(c.worst, 1e-9) << c.where;
}

// from/to: a strip only over the east wall's extension beyond the slab (0 to 0.5 m of its
// 18.5 m face, the slab spanning 1 to 17.5 m) is never touched, and the slab meets the bare
// concrete as without it; a strip over the middle (5 to 13.5 m) takes the impacts instead.
TEST(Bumper3D, OutsideFromToTheSlabMeetsOnlyConcrete) {
  const std::string bumper =
      ", bumper: {sides: [east], thickness: 4 cm, E: 10 MPa, height: 50 cm, e: 0.8";
  const Outcome bare = run(load_text(walled_building("{sides: [east, west], gap: 8 cm}")));
  const Outcome aside = run(load_text(
      walled_building("{sides: [east, west], gap: 8 cm" + bumper + ", from: 0 m, to: 0.5 m}}")));
  const std::string east = "building/base|wall east";
  EXPECT_EQ(impacts_of(aside.model, east + " bumper"), 0);
  EXPECT_EQ(impacts_of(aside.model, east + " bumper bottomed"), 0);
  EXPECT_EQ(impacts_of(aside.model, east), impacts_of(bare.model, east));
  const test::Comparison c = test::compare(level_peaks(aside.result), level_peaks(bare.result));
  EXPECT_LE(c.worst, 1e-6) << c.where;
  const Outcome middle = run(load_text(
      walled_building("{sides: [east, west], gap: 8 cm" + bumper + ", from: 5 m, to: 13.5 m}}")));
  EXPECT_GE(impacts_of(middle.model, east + " bumper"), 1);
  EXPECT_EQ(impacts_of(middle.model, east), 0);
}

// Round-off of an episode's work (as tests/pounding3d_passivity_test.cpp): 1e-9 of its gross work.
constexpr double kRoundOff = 1e-9;

// An eccentric building turned 30° in plan under the x pulse hits its east and north walls with
// corners and turns; 3 cm of soft rubber (E 2 MPa) bottoms out. Every contact episode of every
// contact (concrete, rubber, bottomed rubber) does net work <= 0 on the structures.
TEST(Bumper3D, EveryContactEpisodeIsPassiveWithBottoming) {
  const Outcome r =
      run(load_text(walled_building(
              "{sides: all, gap: 8 cm, bumper: {thickness: 3 cm, E: 2 MPa, height: 50 cm, "
              "e: 0.7, mu_static: 0.9, mu_kinetic: 0.7}}",
              "    rotation: 30 deg\n    eccentricity: [1.5 m, 1 m]\n")),
          4.0);
  int episodes = 0, bottomed = 0;
  for (const auto& e : r.model.elements) {
    const auto* c = dynamic_cast<const PolygonContact*>(e.get());
    if (!c) continue;
    SCOPED_TRACE(c->label());
    episodes += c->episodes();
    if (c->label().ends_with(kBottomedLabel)) bottomed += c->impacts();
    if (c->episodes() > 0) {
      EXPECT_LE(c->max_episode_net_work_relative(), kRoundOff);
    }
    EXPECT_GE(c->friction_dissipated(), 0.0);
    EXPECT_GE(c->output(10), 0.0);  // impact-dissipated energy, J
  }
  EXPECT_GE(episodes, 4);
  EXPECT_GE(bottomed, 1);
  EXPECT_LT(r.result.energy.relative_error, 5e-3);
}

TEST(Bumper3D, BadInputNamesLineAndKey) {
  struct Bad {
    std::string bumper;
    std::string key;
    std::string what;
  };
  const Bad cases[] = {
      {"{thickness: 20 cm, E: 10 MPa, height: 50 cm, e: 0.8}", "thickness", "thinner than"},
      {"{thickness: 25 cm, E: 10 MPa, height: 50 cm, e: 0.8}", "thickness", "thinner than"},
      {"{thickness: -1 cm, E: 10 MPa, height: 50 cm, e: 0.8}", "thickness", ""},
      {"{thickness: 5 cm, E: 10 MPa, height: 50 cm, e: 0.8, from: 3 m, to: 2 m}", "to",
       "beyond 'from'"},
      {"{thickness: 5 cm, E: 10 MPa, height: 50 cm, e: 0.8, to: 19 m}", "to", "beyond the"},
      {"{thickness: 5 cm, E: 10 MPa, height: 50 cm, e: 0.8, from: 18.5 m}", "from", "beyond the"},
      {"{thickness: 5 cm, E: 10 MPa, e: 0.8}", "height", "missing"},
      {"{thickness: 5 cm, E: 10 MPa, height: 50 cm, e: 1.2}", "e", "(0, 1]"},
      {"{thickness: 5 cm, E: 10 MPa, height: 50 cm, e: 0.8, max_strain: 100 %}", "max_strain",
       "(0, 1)"},
      {"{thickness: 5 cm, E: 10 MPa, height: 50 cm, e: 0.8, mu_static: 0.5, mu_kinetic: 0.6}",
       "mu_kinetic", "mu_static"},
      {"{sides: [north], thickness: 5 cm, E: 10 MPa, height: 50 cm, e: 0.8}", "sides[0]",
       "no north wall"},
      {"{thickness: 5 cm, E: 10 MPa, height: 50 cm, e: 0.8, law: soft}", "law", "soft"},
  };
  for (const Bad& c : cases) {
    const std::string text =
        walled_building("{sides: [east, west], gap: 20 cm,\n            bumper: " + c.bumper + "}");
    try {
      load_text(text);
      ADD_FAILURE() << "no error for " << c.bumper;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 10) << e.what();
      EXPECT_EQ(e.key(), "structures[0].walls.bumper." + c.key) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.what), std::string::npos) << e.what();
    }
  }
}

// The fixed step of the convergence test, 0.005 s / this (measured converged to 0.1 %).
constexpr int kConvergedDivisor = 256;

// Convergence acceptance (issue 27): XY-5 with 10 cm bumpers (configs/xy5-bumpers-10cm.yaml) to
// 3.6 s, every peak of summary.json's buildings and contacts at the default adaptive stepping
// within 1 % of a fixed-step run at 0.005/256 s, which is converged: halving it moves no peak
// by more than 0.1 % (measured, docs/impact-laws.md).
TEST(Bumper3DConvergence, XY5With10cmBumpersDefaultsWithin1PercentOfFixedStep) {
  ISOPOUND_REQUIRE_RECORDS();
  ModelConfig c = test::load_shipped_config("xy5-bumpers-10cm.yaml");
  c.analysis.t_end = 3.6;
  c.output.histories = false;
  const JobResult adaptive = run_job(c);
  c.analysis.stepping = AnalysisConfig::Stepping::kFixed;
  c.analysis.dt = 0.005 / kConvergedDivisor;
  const JobResult fixed = run_job(c);
  std::map<std::string, std::pair<double, std::string>> p, q;
  test::peak_leaves(summary3d_json(adaptive), "", p);
  test::peak_leaves(contacts3d_json(adaptive), "", p);
  test::peak_leaves(summary3d_json(fixed), "", q);
  test::peak_leaves(contacts3d_json(fixed), "", q);
  ASSERT_EQ(p.size(), q.size());
  std::map<std::string, double> largest;  // per unit: peaks below 1e-6 of it are not compared
  for (const auto& [k, v] : q) largest[v.second] = std::max(largest[v.second], std::abs(v.first));
  test::Comparison worst;
  int compared = 0;
  for (const auto& [k, v] : q) {
    if (std::abs(v.first) <= 1e-6 * largest[v.second]) continue;
    const double d = test::relative_difference(p.at(k).first, v.first);
    if (d > worst.worst) worst = {d, k};
    ++compared;
  }
  EXPECT_GT(compared, 100);
  EXPECT_LE(worst.worst, 1e-2) << worst.where;
}

}  // namespace
}  // namespace isopound
