// Rubber bumpers in 3D (issue 27; docs/impact-laws.md, the two "(3D)" bumper sections): on moat
// walls, the rubber strip's law against closed forms, a free impact's dissipation against e, zero
// thickness = the bare wall, from/to, passivity per contact episode with bottoming, bad input, and
// (records) XY-5 with 10 cm bumpers at defaults against a converged fixed step; on a neighbour's
// face, the strips' geometry, zero thickness = the bare neighbour, the same rubber on either face
// head-on, passivity with bottoming, bad input.
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
#include "tests/bumper3d_support.h"
#include "tests/model_test_support.h"

namespace isopound {
namespace {

constexpr double kSlabMass = 340e3, kSide = 10.0, kNormal = 2.58e10;

Bumper3DConfig rubber(double thickness, const std::string& law = "linear", double e = 0.8) {
  Bumper3DConfig b;
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
PolygonBody strip_at(double face, const Bumper3DConfig& b) {
  const double s = b.max_strain * b.thickness;
  return {-1,
          -1,
          -1,
          {0, 0},
          ConvexPolygon{{face, -10.0}, {face + s, -10.0}, {face + s, 10.0}, {face, 10.0}},
          std::numeric_limits<double>::infinity()};
}

PolygonContactConfig rubber_contact(const Bumper3DConfig& b) {
  PolygonContactConfig cfg;
  cfg.friction = false;
  cfg.length_law = bumper_rubber_law(b, kNormal);
  return cfg;
}

// F_N of a face-on state: the slab δ past the strip's face, approaching at `rate` (the onset's
// v_imp is that rate too, the state being the contact's first).
double face_on_force(const Bumper3DConfig& b, double delta, double rate) {
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
    const Bumper3DConfig b = rubber(0.1, law);
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
    Bumper3DConfig b = rubber(1.0, "linear", e);  // k L = 50 MN/m: 8 cm at 1 m/s, s = 60 cm
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
  return test::thesis_building("", extra + "    walls: " + walls + "\n");
}

using Outcome = test::BumperOutcome;

Outcome run(const ModelConfig& c, double t_end = 3.3) {
  return test::run_bumper_model(c, make_pulse(PulseParameters{}), t_end);  // along x only
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

// --- Rubber on a neighbour's facing side (Building3DConfig::bumper) ---

// The thesis building (no walls) and a fixed-base 2-storey neighbour 4 cm east of it, the same
// grid; `building_extra` / `neighbour_extra` are keys added to each (indented 4).
std::string with_neighbour(const std::string& neighbour_extra,
                           const std::string& building_extra = "") {
  return test::building_beside_neighbour("{rectangle: [16.95 m, 16.95 m]}", building_extra,
                                         neighbour_extra);
}

const std::string kRubber = "{thickness: 2 cm, E: 5 MPa, height: 30 cm, e: 0.7";

// The strips of a slab face: a 10 x 6 m rectangle's east face gets the rubber outermost
// (x in [5 + t - s, 5 + t]) and the bottomed rubber against the face, over [from, to] from the
// face's lower end; a hexagon with a corner on its east side has no face there.
TEST(Bumper3DNeighbour, SlabFaceStripsLieOutsideTheFace) {
  Bumper3DConfig b = rubber(0.1);
  b.from = 1.0, b.to = 4.0;
  const std::vector<Vec2> plan = {{-5, -3}, {5, -3}, {5, 3}, {-5, 3}};
  const BumperStrips east = slab_bumper_strips(plan, 0, b);
  const auto box = [](const std::vector<Vec2>& p) {
    Vec2 lo = p[0], hi = p[0];
    for (const Vec2& q : p)
      lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)},
      hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
    return std::array<double, 4>{lo.x, hi.x, lo.y, hi.y};
  };
  const auto expect_box = [&](const std::vector<Vec2>& p, std::array<double, 4> want) {
    const auto got = box(p);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << k;
  };
  expect_box(east.rubber, {5.04, 5.1, -2.0, 1.0});
  expect_box(east.bottomed, {5.0, 5.04, -2.0, 1.0});
  b.from = 0.0, b.to = std::numeric_limits<double>::infinity();
  expect_box(slab_bumper_strips(plan, 1, b).rubber, {-5.1, -5.04, -3.0, 3.0});
  expect_box(slab_bumper_strips(plan, 2, b).rubber, {-5.0, 5.0, 3.04, 3.1});
  expect_box(slab_bumper_strips(plan, 3, b).bottomed, {-5.0, 5.0, -3.04, -3.0});
  const std::vector<Vec2> hexagon = {{-5, -3}, {3, -3}, {5, 0}, {3, 3}, {-5, 3}};
  EXPECT_THROW(slab_bumper_strips(hexagon, 0, b), std::invalid_argument);
  b.to = 7.0;  // beyond the 6 m face
  EXPECT_THROW(slab_bumper_strips(plan, 0, b), std::invalid_argument);
}

// Zero thickness builds no strip: every peak equals the bare neighbour's (the same model).
TEST(Bumper3DNeighbour, ZeroThicknessIsTheBareNeighbour) {
  const Outcome bare = run(load_text(with_neighbour("")));
  const Outcome zero = run(load_text(
      with_neighbour("    bumper: {thickness: 0 cm, E: 5 MPa, height: 30 cm, e: 0.7}\n")));
  EXPECT_EQ(zero.model.elements.size(), bare.model.elements.size());
  EXPECT_GE(impacts_of(bare.model, "building/floor 1|neighbour/floor 1"), 1);
  const test::Comparison c = test::compare(level_peaks(zero.result), level_peaks(bare.result));
  EXPECT_LE(c.worst, 1e-9) << c.where;
}

// Head-on (the x pulse, no eccentricity: the slabs translate in x only) the rubber strip on the
// neighbour's west face and the same strip on the building's east face press the same overlap:
// the model must not care whose DOFs carry it. The rubber takes the impacts, the concrete none.
TEST(Bumper3DNeighbour, RubberOnEitherFaceIsTheSameHeadOn) {
  const Outcome on_neighbour = run(load_text(with_neighbour("    bumper: " + kRubber + "}\n")));
  const Outcome on_building =
      run(load_text(with_neighbour("", "    bumper: " + kRubber + ", sides: [east]}\n")));
  const std::string floor1 = "building/floor 1|neighbour/floor 1";
  EXPECT_GE(impacts_of(on_neighbour.model, floor1 + " west bumper"), 1);
  EXPECT_GE(impacts_of(on_neighbour.model, floor1 + " west bumper bottomed"), 0);
  EXPECT_EQ(impacts_of(on_neighbour.model, floor1), 0);
  EXPECT_EQ(impacts_of(on_building.model, "neighbour/floor 1|building/floor 1 east bumper"),
            impacts_of(on_neighbour.model, floor1 + " west bumper"));
  // Along x (y and θ stay at round-off: their peaks are noise).
  const test::Comparison c = test::compare(test::x_peaks(on_building), test::x_peaks(on_neighbour));
  EXPECT_LE(c.worst, 1e-6) << c.where;
  // The bare neighbour is hit harder: the rubber softens the first-storey impacts.
  const Outcome bare = run(load_text(with_neighbour("")));
  const double a_rubber = test::x_peaks(on_neighbour)[3].value,
               a_bare = test::x_peaks(bare)[3].value;
  EXPECT_LT(a_rubber, a_bare);
}

// An eccentric building turned against its neighbour's rubber (2 cm, soft: it bottoms out) under
// the x pulse: every episode of every contact does net work <= 0, and the energy balance closes.
TEST(Bumper3DNeighbour, EveryContactEpisodeIsPassiveWithBottoming) {
  const Outcome r =
      run(load_text(with_neighbour(
              "    bumper: {thickness: 2 cm, E: 0.5 MPa, height: 30 cm, e: 0.6, mu_static: 0.9, "
              "mu_kinetic: 0.7}\n",
              "    eccentricity: [1.5 m, 1 m]\n")),
          4.0);
  int episodes = 0, bottomed = 0, rubber = 0;
  for (const auto& e : r.model.elements) {
    const auto* c = dynamic_cast<const PolygonContact*>(e.get());
    if (!c) continue;
    SCOPED_TRACE(c->label());
    episodes += c->episodes();
    if (c->label().ends_with(kBottomedLabel))
      bottomed += c->impacts();
    else if (c->label().ends_with(kBumperLabel))
      rubber += c->impacts();
    if (c->episodes() > 0) {
      EXPECT_LE(c->max_episode_net_work_relative(), kRoundOff);
    }
    EXPECT_GE(c->friction_dissipated(), 0.0);
    EXPECT_GE(c->output(10), 0.0);
  }
  EXPECT_GE(rubber, 2);
  EXPECT_GE(bottomed, 1);
  EXPECT_GE(episodes, 3);
  EXPECT_LT(r.result.energy.relative_error, 1e-3);
}

TEST(Bumper3DNeighbour, BadInputNamesLineAndKey) {
  struct Bad {
    std::string building_extra, neighbour_extra, key, what;
  };
  const Bad cases[] = {
      {"", "    bumper: {thickness: 4 cm, E: 5 MPa, height: 30 cm, e: 0.7}\n",
       "structures[1].bumper.thickness", "thinner than the gap"},
      {"", "    bumper: {thickness: 6 cm, E: 5 MPa, height: 30 cm, e: 0.7}\n",
       "structures[1].bumper.thickness", "thinner than the gap"},
      {"", "    bumper: {thickness: -1 cm, E: 5 MPa, height: 30 cm, e: 0.7}\n",
       "structures[1].bumper.thickness", ""},
      {"    bumper: {thickness: 5 cm, E: 5 MPa, height: 30 cm, e: 0.7}\n", "",
       "structures[0].bumper.sides", "missing required key 'sides'"},
      {"", "    bumper: {thickness: 5 cm, E: 5 MPa, height: 30 cm, e: 0.7, to: 20 m}\n",
       "structures[1].bumper.to", "face length"},
      {"", "    bumper: {sides: [up], thickness: 5 cm, E: 5 MPa, height: 30 cm, e: 0.7}\n",
       "structures[1].bumper.sides[0]", "up"},
      {"", "    bumper: {thickness: 5 cm, E: 5 MPa, e: 0.7}\n", "structures[1].bumper.height",
       "missing"},
      {"", "    bumper: {thickness: 5 cm, E: 5 MPa, height: 30 cm, e: 0.7, k: 1}\n",
       "structures[1].bumper.k", ""},
  };
  for (const Bad& c : cases) {
    SCOPED_TRACE(c.building_extra + c.neighbour_extra);
    try {
      load_text(with_neighbour(c.neighbour_extra, c.building_extra));
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_GT(e.line(), 0) << e.what();
      EXPECT_EQ(e.key(), c.key) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.what), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace isopound
