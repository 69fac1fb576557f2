// Pounding of the thesis 3-storey Bouc-Wen base-isolated building (THEORY sections 1 and 4)
// through the whole solver (model assembly, stepper, contact events):
//  - PoundingBuildingConvergence: for each of the ten impact laws under RSN1084 (SCS052), every
//    peak of the default (adaptive) run is within 1 % of a converged fixed-step reference and the
//    default run needs >= 20x fewer steps than a fixed 2e-5 s run (the acceptance);
//    PoundingBuildingReference justifies the reference step for one law.
//  - PoundingBuildingGapShift: a 1 nm change of the gap changes no peak by more than 0.1 %.
//  - PoundingBuildingWalls: the walls cap the base displacement, a wall out of reach changes
//    nothing; a flexible wall moves and a very stiff one behaves like the rigid wall.
//  - PoundingBuildingNeighbour: slab-to-slab contacts at equal elevations, order independence
//    and mirror symmetry.
//  - PoundingBuildingModifiedKelvinVoigt: no tension, residual indentation.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "solver/core/analysis.h"
#include "solver/elements/contact.h"
#include "solver/excitation/ground_motion.h"
#include "solver/materials/impact_law.h"
#include "solver/structures/job.h"
#include "tests/peak_comparison.h"
#include "tests/test_support.h"

namespace isopound {
namespace {

using test::compare;
using test::Comparison;
using test::NamedPeak;
using test::relative_difference;

// Thesis chapter-4 pounding set-up (THEORY section 4): k = 2500 kN/mm, e = 0.7, wall 500 t.
constexpr double kGap = 0.10;        // m, moat gap on both sides of the base slab
constexpr double kWallMass = 500e3;  // kg
constexpr double kK = 2.5e9;         // N/m, linear-type laws
constexpr double kKh = 2.5e9;        // N/m^1.5, Hertz-type laws
constexpr double kE = 0.7;
constexpr const char* kRecord = "RSN1084_NORTHR_SCS052.AT2";

// The thesis 3-storey building (THEORY section 1): base 340 t, floors 340/340/250 t, 600 MN/m,
// 3.2 m; the defaults give the Bouc-Wen isolator (Tb 2 s, QW 5 %, uy 1 cm), Rayleigh 2 % at
// modes 1-2 and xi_b = 5 %. Fixed base: the same floors without base slab and isolators.
BuildingConfig thesis_building(const std::string& name, bool isolated = true) {
  BuildingConfig b;
  b.name = name;
  b.isolated = isolated;
  b.base_mass = isolated ? 340e3 : 0.0;
  for (int i = 0; i < 3; ++i) b.floors.push_back({i + 1 < 3 ? 340e3 : 250e3, 600e6, 3.2});
  return b;
}

ImpactLawConfig thesis_impact(const std::string& law) {
  ImpactLawConfig c;
  c.law = law;
  c.k = kK;
  c.k_h = kKh;
  c.e = kE;
  return c;
}

WallConfig moat_walls(const std::string& law, double gap) {
  WallConfig w;  // both sides, at the base slab (level 0), rigid
  w.gap_left = w.gap_right = gap;
  w.mass = kWallMass;
  w.impact = thesis_impact(law);
  return w;
}

ModelConfig walled_building(const std::string& law, double gap) {
  ModelConfig c;
  c.building = thesis_building("3-storey");
  c.building.walls.push_back(moat_walls(law, gap));
  c.output.histories = false;
  return c;
}

ModelConfig free_building() {
  ModelConfig c;
  c.building = thesis_building("3-storey");
  c.output.histories = false;
  return c;
}

ModelConfig fixed_step(ModelConfig c, double dt) {
  c.analysis.stepping = AnalysisConfig::Stepping::kFixed;
  c.analysis.dt = dt;  // event location stays on (the default)
  return c;
}

GroundMotion record() {
  return read_record((test::records_dir() / kRecord).string());
}

GroundMotion negated(GroundMotion g) {
  for (double& a : g.acceleration) a = -a;
  return g;
}

struct Outcome {
  Model model;
  AnalysisResult result;
  double seconds = 0.0;
};

// Every structure must have one story height per story that stories_of() will report
// (see the report: a flexible wall's single-DOF structure has none and stories_of() reads past
// the end). Checked here so that a model that would crash the analysis fails the test instead.
// Every story needs a level above it: a building has one story per floor, a moat-wall
// oscillator none (its DOF is a level without a story).
::testing::AssertionResult consistent_structures(const Model& model) {
  for (const StructureInfo& s : model.structures) {
    const std::size_t floors = s.level_dofs.size() - (s.has_base ? 1 : 0);
    if (s.story_heights.size() > floors)
      return ::testing::AssertionFailure()
             << "structure '" << s.name << "' has " << s.level_dofs.size() << " level(s) but "
             << s.story_heights.size() << " story height(s)";
  }
  return ::testing::AssertionSuccess();
}

Outcome analyse(const ModelConfig& config, const GroundMotion& motion) {
  Outcome r;
  r.model = build_model(config);
  EXPECT_TRUE(consistent_structures(r.model));
  const auto start = std::chrono::steady_clock::now();
  r.result = run_analysis(r.model, motion, run_options(config));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

const Contact1D* as_contact(const Model& model, std::size_t e) {
  return dynamic_cast<const Contact1D*>(model.elements[e].get());
}

// Indices of the contact elements whose label contains `tag` ("/wall " or "~").
std::vector<std::size_t> contacts(const Model& model, std::string_view tag) {
  std::vector<std::size_t> out;
  for (std::size_t e = 0; e < model.elements.size(); ++e)
    if (as_contact(model, e) != nullptr &&
        model.elements[e]->label().find(tag) != std::string::npos)
      out.push_back(e);
  return out;
}

constexpr int kForce = 0, kPenetration = 1, kImpacts = 2, kIndentation = 4;

double contact_output(const Outcome& r, std::size_t element, int output) {
  return r.result.element_outputs[element][output].value;
}

int total_impacts(const Outcome& r, std::string_view tag) {
  double n = 0;
  for (std::size_t e : contacts(r.model, tag)) n += contact_output(r, e, kImpacts);
  return static_cast<int>(std::lround(n));
}

// The acceptance peaks of structure `s`: base displacement (isolated), each story drift, each
// level's absolute acceleration; and, for the main building, each wall's peak impact force.
std::vector<NamedPeak> peaks_of(const Outcome& r, int s = 0) {
  const StructureInfo& info = r.model.structures[s];
  const AnalysisResult& a = r.result;
  std::vector<NamedPeak> p;
  if (info.has_base) p.push_back({"base displacement", a.displacement[info.base_dof()].value});
  for (std::size_t k = 0; k < a.stories.size(); ++k)
    if (a.stories[k].label.rfind(info.name + "/", 0) == 0)
      p.push_back({a.stories[k].label + " drift", a.drift[k].value});
  for (int dof : info.level_dofs)
    p.push_back({r.model.dofs[dof].label + " a_abs", a.absolute_acceleration[dof].value});
  if (s == 0)
    for (std::size_t e : contacts(r.model, "/wall "))
      p.push_back({r.model.elements[e]->label() + " force", contact_output(r, e, kForce)});
  return p;
}

std::vector<std::string> law_names() {
  std::vector<std::string> names;
  for (std::string_view n : impact_law_names()) names.emplace_back(n);
  return names;
}

std::string law_test_name(const ::testing::TestParamInfo<std::string>& info) {
  return info.param;
}

// ---------------------------------------------------------------------------------------------
// 1. Convergence of the default stepping, per law (the acceptance).
//
// Reference: fixed dt = 1e-5 s with event location (contact onset and separation are still cut
// exactly). PoundingBuildingReference shows for kelvin_voigt that halving it to 5e-6 s moves no
// peak by more than 2e-3 (measured: 9e-8; earlier measurements gave ~1e-4 against 2e-6 s), so
// the reference's own error is well below the 1 % being tested. Kelvin-Voigt is the law with the
// largest force jump at onset (c v_imp), whose absolute accelerations converge last (THEORY
// section 11), so it is the demanding law for the reference.

class PoundingBuildingConvergence : public ::testing::TestWithParam<std::string> {};

TEST_P(PoundingBuildingConvergence,
       DefaultPeaksWithinOnePercentOfFixedStepWithTwentyTimesFewerSteps) {
  ISOPOUND_REQUIRE_RECORDS();
  const std::string law = GetParam();
  const GroundMotion motion = record();
  const ModelConfig config = walled_building(law, kGap);
  const Outcome ref = analyse(fixed_step(config, 1e-5), motion);
  const Outcome def = analyse(config, motion);

  // The walls must actually be hit, or the test says nothing about pounding.
  ASSERT_GT(total_impacts(def, "/wall "), 0);
  ASSERT_GT(total_impacts(ref, "/wall "), 0);

  const Comparison c = compare(peaks_of(def), peaks_of(ref));
  EXPECT_LT(c.worst, 0.01) << law << ": worst at " << c.where;

  // A fixed 2e-5 s run over the same duration takes duration / 2e-5 steps; count every
  // attempted step of the default run (rejected ones too).
  const double fixed_steps = std::round(def.result.stats.duration / 2e-5);
  const long steps = def.result.stats.steps + def.result.stats.rejected_steps;
  const double ratio = fixed_steps / static_cast<double>(steps);
  EXPECT_GE(ratio, 20.0) << law << ": " << steps << " steps (" << def.result.stats.rejected_steps
                         << " rejected)";

  std::printf(
      "[convergence] %-22s | worst %.3e at %-34s | steps %7ld (rej %5ld) | ratio %6.1f | "
      "impacts %d | t_def %.2f s t_ref %.2f s\n",
      law.c_str(), c.worst, c.where.c_str(), steps, def.result.stats.rejected_steps, ratio,
      total_impacts(def, "/wall "), def.seconds, ref.seconds);
  RecordProperty("worst_peak_error", std::to_string(c.worst));
  RecordProperty("worst_peak", c.where);
  RecordProperty("step_ratio", std::to_string(ratio));
}

INSTANTIATE_TEST_SUITE_P(PoundingBuilding, PoundingBuildingConvergence,
                         ::testing::ValuesIn(law_names()), law_test_name);

TEST(PoundingBuildingReference, FixedStepOfTenMicrosecondsIsConvergedForKelvinVoigt) {
  ISOPOUND_REQUIRE_RECORDS();
  const GroundMotion motion = record();
  const ModelConfig config = walled_building("kelvin_voigt", kGap);
  const Outcome ref = analyse(fixed_step(config, 1e-5), motion);
  const Outcome fine = analyse(fixed_step(config, 5e-6), motion);
  ASSERT_GT(total_impacts(ref, "/wall "), 0);
  // Second-order Newmark: halving the step divides the error by ~4, so the 1e-5 s run is
  // within ~(4/3) of this difference of the limit; 2e-3 leaves the 1 % test a 5x margin.
  const Comparison c = compare(peaks_of(ref), peaks_of(fine));
  EXPECT_LT(c.worst, 2e-3) << "worst at " << c.where;
  std::printf("[reference] kelvin_voigt fixed 1e-5 vs 5e-6 s: worst %.3e at %s\n", c.worst,
              c.where.c_str());
}

// ---------------------------------------------------------------------------------------------
// 2. Shifting the gap by 1 nm (far below any physical or tolerance scale) must not change the
// results: the located events move by ~1e-9 / v_imp s, so any visible change would come from a
// discrete decision (a step taken or not, an event counted or not) flipping. 0.1 % is 10x below
// the accuracy the defaults promise and far above the continuous O(1e-8) effect.

class PoundingBuildingGapShift : public ::testing::TestWithParam<std::string> {};

TEST_P(PoundingBuildingGapShift, OneNanometreChangesNoPeakByMoreThanOneThousandth) {
  ISOPOUND_REQUIRE_RECORDS();
  const std::string law = GetParam();
  const GroundMotion motion = record();
  const Outcome a = analyse(walled_building(law, kGap), motion);
  const Outcome b = analyse(walled_building(law, kGap + 1e-9), motion);
  ASSERT_GT(total_impacts(a, "/wall "), 0);
  EXPECT_EQ(total_impacts(a, "/wall "), total_impacts(b, "/wall "));
  const Comparison c = compare(peaks_of(b), peaks_of(a));
  EXPECT_LT(c.worst, 1e-3) << law << ": worst at " << c.where;
  std::printf("[gap shift] %-22s | worst %.3e at %s\n", law.c_str(), c.worst, c.where.c_str());
}

INSTANTIATE_TEST_SUITE_P(PoundingBuilding, PoundingBuildingGapShift,
                         ::testing::ValuesIn(law_names()), law_test_name);

// ---------------------------------------------------------------------------------------------
// 3. The walls bring the expected physics.

class PoundingBuildingWallCap : public ::testing::TestWithParam<std::string> {};

TEST_P(PoundingBuildingWallCap, BaseDisplacementStopsAtGapPlusPenetration) {
  ISOPOUND_REQUIRE_RECORDS();
  const std::string law = GetParam();
  const GroundMotion motion = record();
  const Outcome free = analyse(free_building(), motion);
  const Outcome walled = analyse(walled_building(law, kGap), motion);
  const int base = walled.model.structures[0].level_dofs[0];
  // Without walls the slab goes well beyond the gap, so the walls must act.
  ASSERT_GT(free.result.displacement[base].value, kGap + 0.05);
  EXPECT_GT(total_impacts(walled, "/wall "), 0);
  // The slab can only pass the gap by penetrating a wall (plus, for modified Kelvin-Voigt, the
  // permanent indentation that widened the gap); 1e-6 m covers round-off of the penetration.
  double penetration = 0.0, indentation = 0.0;
  for (std::size_t e : contacts(walled.model, "/wall ")) {
    penetration = std::max(penetration, contact_output(walled, e, kPenetration));
    indentation = std::max(indentation, contact_output(walled, e, kIndentation));
  }
  EXPECT_GT(penetration, 0.0);
  if (law != "modified_kelvin_voigt") {
    EXPECT_EQ(indentation, 0.0);
  }
  EXPECT_LE(walled.result.displacement[base].value, kGap + indentation + penetration + 1e-6)
      << "penetration " << penetration << " indentation " << indentation;
  EXPECT_LT(walled.result.displacement[base].value, free.result.displacement[base].value);
}

INSTANTIATE_TEST_SUITE_P(PoundingBuilding, PoundingBuildingWallCap,
                         ::testing::ValuesIn(law_names()), law_test_name);

// A wall out of reach (2 m, beyond any displacement of this building) must leave the analysis
// untouched: same steps, bit-identical peaks up to 1e-12 relative, no impact.
TEST(PoundingBuildingWalls, WallOutOfReachChangesNothing) {
  ISOPOUND_REQUIRE_RECORDS();
  const GroundMotion motion = record();
  const Outcome free = analyse(free_building(), motion);
  ASSERT_LT(free.result.displacement[0].value, 1.0);
  for (const std::string& law : law_names()) {
    SCOPED_TRACE(law);
    const Outcome far = analyse(walled_building(law, 2.0), motion);
    EXPECT_EQ(total_impacts(far, "/wall "), 0);
    EXPECT_EQ(far.result.stats.steps, free.result.stats.steps);
    EXPECT_EQ(far.result.stats.rejected_steps, free.result.stats.rejected_steps);
    const AnalysisResult& a = far.result;
    const AnalysisResult& b = free.result;
    ASSERT_EQ(a.displacement.size(), b.displacement.size());
    for (std::size_t i = 0; i < a.displacement.size(); ++i) {
      EXPECT_LE(relative_difference(a.displacement[i].value, b.displacement[i].value), 1e-12) << i;
      EXPECT_LE(relative_difference(a.velocity[i].value, b.velocity[i].value), 1e-12) << i;
      EXPECT_LE(
          relative_difference(a.absolute_acceleration[i].value, b.absolute_acceleration[i].value),
          1e-12)
          << i;
    }
    ASSERT_EQ(a.drift.size(), b.drift.size());
    for (std::size_t i = 0; i < a.drift.size(); ++i) {
      EXPECT_LE(relative_difference(a.drift[i].value, b.drift[i].value), 1e-12) << i;
    }
    for (std::size_t k = 0; k < b.element_outputs[0].size(); ++k) {
      EXPECT_LE(relative_difference(a.element_outputs[0][k].value, b.element_outputs[0][k].value),
                1e-12)
          << "isolator output " << k;
    }
  }
}

// The DOF of the single-DOF structure of the wall on `side` ("left" or "right").
int wall_dof(const Model& model, const std::string& side) {
  for (const StructureInfo& s : model.structures)
    if (s.name.find("/wall " + side) != std::string::npos) return s.level_dofs.at(0);
  return -1;
}

// 4. A flexible wall (a single-DOF structure on the ground) moves when it is hit; as its
// stiffness grows it becomes the rigid wall.
TEST(PoundingBuildingWalls, FlexibleWallMovesWhenHitAndAVeryStiffWallActsRigid) {
  ISOPOUND_REQUIRE_RECORDS();
  const GroundMotion motion = record();
  const auto flexible = [](double gap, double stiffness) {
    ModelConfig c = walled_building("kelvin_voigt", gap);
    c.building.walls[0].stiffness = stiffness;
    c.building.walls[0].damping_ratio = 0.05;
    return c;
  };
  const Outcome hit = analyse(flexible(kGap, 1e9), motion);
  const Outcome missed = analyse(flexible(2.0, 1e9), motion);  // the same walls, out of reach
  ASSERT_EQ(hit.model.structures.size(), 3u);                  // building + one oscillator per wall
  ASSERT_GT(total_impacts(hit, "/wall "), 0);
  EXPECT_EQ(total_impacts(missed, "/wall "), 0);
  for (const char* side : {"left", "right"}) {
    SCOPED_TRACE(side);
    const int dof = wall_dof(hit.model, side);
    ASSERT_GE(dof, 0);
    const double moved = hit.result.displacement[dof].value;
    const double shaken = missed.result.displacement[wall_dof(missed.model, side)].value;
    std::printf("[flexible wall] %s: peak displacement hit %.4e m, ground motion only %.4e m\n",
                side, moved, shaken);
    EXPECT_GT(moved, 0.0);
    // The ground alone shakes a 0.14 s oscillator by a few mm at most; an impact of several MN on
    // a 1e9 N/m wall pushes it by mm to cm: being hit must at least double its peak.
    EXPECT_GT(moved, 2.0 * shaken);
    // Upper bound from the wall's own dynamics (linear, so ground and impact parts superpose):
    // a one-signed force pulse of peak F moves a damped oscillator by at most 2 F / k (the shock
    // spectrum of a step). The wall is hit by the force the contact reports, not more.
    const std::size_t e = contacts(hit.model, std::string("/wall ") + side).at(0);
    const double force = contact_output(hit, e, kForce);
    std::printf("[flexible wall] %s: peak impact force %.4e N, 2 F / k = %.4e m\n", side, force,
                2.0 * force / 1e9);
    EXPECT_LT(moved, 2.0 * force / 1e9 + shaken);
  }
  // Series springs: a 1e13 N/m wall adds 2.5e9/1e13 = 2.5e-4 of the contact compliance; its own
  // mode (1.4 ms) moves by ~m a_g / k ~ 1e-6 m. So the base displacement must match the rigid
  // wall's (same mass in m_eff) to well within 1 %.
  const Outcome stiff = analyse(flexible(kGap, 1e13), motion);
  const Outcome rigid = analyse(walled_building("kelvin_voigt", kGap), motion);
  const int base = rigid.model.structures[0].level_dofs[0];
  const double d = relative_difference(stiff.result.displacement[base].value,
                                       rigid.result.displacement[base].value);
  std::printf("[flexible wall] base displacement 1e13 N/m wall vs rigid: %.3e relative\n", d);
  EXPECT_LT(d, 0.01);
  EXPECT_GT(total_impacts(stiff, "/wall "), 0);
}

// ---------------------------------------------------------------------------------------------
// 5. A neighbouring fixed-base building, pounding slab to slab (built-in pulse: no record needed).

NeighbourConfig neighbour(const std::string& name, bool right, double gap) {
  NeighbourConfig n;
  n.building = thesis_building(name, /*isolated=*/false);
  n.right = right;
  n.gap = gap;
  n.impact = thesis_impact("kelvin_voigt");
  return n;
}

GroundMotion pulse() {
  return make_pulse(PulseParameters{});
}

TEST(PoundingBuildingNeighbour, FixedBaseNeighbourPoundsAtTheThreeFloorsOnly) {
  const GroundMotion motion = pulse();
  ModelConfig config = free_building();
  config.neighbours.push_back(neighbour("neighbour", /*right=*/true, 0.05));
  const Outcome both = analyse(config, motion);

  // Elevations: isolated base 0, floors 3.2/6.4/9.6 m; fixed-base neighbour floors 3.2/6.4/9.6 m.
  const std::vector<std::size_t> pairs = contacts(both.model, "~");
  ASSERT_EQ(pairs.size(), 3u);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    EXPECT_EQ(both.model.elements[pairs[k]]->label(),
              "3-storey~neighbour/floor " + std::to_string(k + 1));
  }
  EXPECT_EQ(contacts(both.model, "/wall ").size(), 0u);
  int contact_count = 0;
  for (std::size_t e = 0; e < both.model.elements.size(); ++e)
    contact_count += as_contact(both.model, e) != nullptr;
  EXPECT_EQ(contact_count, 3);

  ASSERT_EQ(both.model.structures.size(), 2u);
  EXPECT_GT(total_impacts(both, "~"), 0);

  // The neighbour is excited by the impacts: its response differs clearly from the same
  // building alone under the same pulse.
  ModelConfig alone_config;
  alone_config.building = thesis_building("neighbour", false);
  alone_config.output.histories = false;
  const Outcome alone = analyse(alone_config, motion);
  const std::vector<int>& with_dofs = both.model.structures[1].level_dofs;
  const std::vector<int>& alone_dofs = alone.model.structures[0].level_dofs;
  ASSERT_EQ(with_dofs.size(), alone_dofs.size());
  double largest_change = 0.0;
  for (std::size_t k = 0; k < with_dofs.size(); ++k) {
    const double with = both.result.absolute_acceleration[with_dofs[k]].value;
    const double without = alone.result.absolute_acceleration[alone_dofs[k]].value;
    EXPECT_GT(both.result.displacement[with_dofs[k]].value, 0.0);
    largest_change = std::max(largest_change, relative_difference(with, without));
    std::printf("[neighbour] floor %zu a_abs with pounding %.3f m/s2, alone %.3f m/s2\n", k + 1,
                with, without);
  }
  // Impacts of a heavy isolated building at up to ~1 m/s amplify the neighbour's floor
  // accelerations several times; 50 % is a loose floor for "excited by the impacts".
  EXPECT_GT(largest_change, 0.5);
}

// Every peak of a run by name: DOFs, stories, element outputs.
std::vector<NamedPeak> all_peaks(const Outcome& r) {
  std::vector<NamedPeak> p;
  const AnalysisResult& a = r.result;
  for (int i = 0; i < r.model.size(); ++i) {
    const std::string& dof = r.model.dofs[i].label;
    p.push_back({dof + " u", a.displacement[i].value});
    p.push_back({dof + " v", a.velocity[i].value});
    p.push_back({dof + " a_abs", a.absolute_acceleration[i].value});
  }
  for (std::size_t k = 0; k < a.stories.size(); ++k)
    p.push_back({a.stories[k].label + " drift", a.drift[k].value});
  for (std::size_t e = 0; e < r.model.elements.size(); ++e)
    for (int k = 0; k < r.model.elements[e]->output_count(); ++k)
      p.push_back({r.model.elements[e]->label() + " " + r.model.elements[e]->output_name(k),
                   a.element_outputs[e][k].value});
  std::sort(p.begin(), p.end(),
            [](const NamedPeak& x, const NamedPeak& y) { return x.name < y.name; });
  return p;
}

// Two identical fixed-base neighbours, one on each side at 5 cm. (a) Listing them in the other
// order changes nothing. (b) The physics is mirror symmetric: exchanging their sides and flipping
// the sign of the ground motion mirrors the response, so every peak (an absolute value) of every
// DOF, story and contact keeps its value under its name. Negation is exact in floating point and
// the assembly order is the same, so only round-off in sign-dependent branches could differ:
// 1e-9 relative allows for that but not for any physical asymmetry (e.g. a contact sign).
// (c) The check has teeth: exchanging the sides without flipping the motion is a different
// problem (the pulse is not symmetric), so the peaks of "west" and "east" must differ.
TEST(PoundingBuildingNeighbour, ListOrderAndMirrorSymmetry) {
  const GroundMotion motion = pulse();
  ModelConfig a = free_building();
  a.neighbours = {neighbour("west", false, 0.05), neighbour("east", true, 0.05)};
  ModelConfig reordered = a;
  reordered.neighbours = {a.neighbours[1], a.neighbours[0]};
  ModelConfig mirrored = a;
  mirrored.neighbours[0].right = true;   // "west" now stands on the right
  mirrored.neighbours[1].right = false;  // "east" on the left

  const Outcome ra = analyse(a, motion);
  ASSERT_EQ(contacts(ra.model, "~").size(), 6u);
  ASSERT_GT(total_impacts(ra, "3-storey~west/"), 0);
  ASSERT_GT(total_impacts(ra, "3-storey~east/"), 0);
  const std::vector<NamedPeak> reference = all_peaks(ra);

  const Comparison order = compare(all_peaks(analyse(reordered, motion)), reference);
  EXPECT_LT(order.worst, 1e-9) << "list order: worst at " << order.where;
  const Comparison mirror = compare(all_peaks(analyse(mirrored, negated(motion))), reference);
  EXPECT_LT(mirror.worst, 1e-9) << "mirror: worst at " << mirror.where;
  const Comparison unflipped = compare(all_peaks(analyse(mirrored, motion)), reference);
  EXPECT_GT(unflipped.worst, 1e-2) << unflipped.where;
  std::printf(
      "[neighbour symmetry] order %.3e (%s), mirror %.3e (%s), sides exchanged without flip %.3e "
      "(%s)\n",
      order.worst, order.where.c_str(), mirror.worst, mirror.where.c_str(), unflipped.worst,
      unflipped.where.c_str());
}

// ---------------------------------------------------------------------------------------------
// 6. Modified Kelvin-Voigt on the building: never tensile, leaves a permanent indentation.
// Histories are recorded at every step (output interval below the smallest contact step), and
// the same run with plain Kelvin-Voigt must show tension, so the check can fail.

std::vector<double> wall_force_history(const Outcome& r) {
  const History& h = r.result.history;
  std::vector<double> forces;
  for (std::size_t e : contacts(r.model, "/wall ")) {
    const std::string column = r.model.elements[e]->label() + " force [N]";
    const auto it = std::find(h.columns.begin(), h.columns.end(), column);
    EXPECT_NE(it, h.columns.end()) << column;
    if (it == h.columns.end()) continue;
    const std::size_t c = static_cast<std::size_t>(it - h.columns.begin());
    for (std::size_t row = 0; row < h.rows(); ++row)
      forces.push_back(h.values[row * h.columns.size() + c]);
  }
  return forces;
}

TEST(PoundingBuildingModifiedKelvinVoigt, NoTensionAndResidualIndentation) {
  ISOPOUND_REQUIRE_RECORDS();
  const GroundMotion motion = record();
  const auto with_histories = [](const std::string& law) {
    ModelConfig c = walled_building(law, kGap);
    c.output.histories = true;
    c.output.interval = 1e-4;  // s: at most one row per step; contact steps are ~2e-4 s
    return c;
  };
  const Outcome mkv = analyse(with_histories("modified_kelvin_voigt"), motion);
  const Outcome kv = analyse(with_histories("kelvin_voigt"), motion);
  ASSERT_GT(total_impacts(mkv, "/wall "), 0);

  const std::vector<double> f_mkv = wall_force_history(mkv);
  const std::vector<double> f_kv = wall_force_history(kv);
  ASSERT_FALSE(f_mkv.empty());
  const double min_mkv = *std::min_element(f_mkv.begin(), f_mkv.end());
  const double max_mkv = *std::max_element(f_mkv.begin(), f_mkv.end());
  const double min_kv = *std::min_element(f_kv.begin(), f_kv.end());
  std::printf("[modified KV] %zu force samples: min %.4e N, max %.4e N; plain KV min %.4e N\n",
              f_mkv.size(), min_mkv, max_mkv, min_kv);
  EXPECT_GE(min_mkv, 0.0);
  EXPECT_GT(max_mkv, 0.0);
  EXPECT_LT(min_kv, 0.0);  // KV pulls near separation (THEORY section 4, law 2)

  double indentation = 0.0;
  for (std::size_t e : contacts(mkv.model, "/wall ")) {
    indentation = std::max(indentation, contact_output(mkv, e, kIndentation));
  }
  std::printf("[modified KV] residual indentation %.4e m\n", indentation);
  EXPECT_GT(indentation, 0.0);
  for (std::size_t e : contacts(kv.model, "/wall ")) {
    EXPECT_EQ(contact_output(kv, e, kIndentation), 0.0);
  }
}

}  // namespace
}  // namespace isopound
