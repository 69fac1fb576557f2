// Contacts between plans of any outline (issue 40): each overlap component of a pair is a slot,
// a PolygonContact of its own (solver/elements/plan_pair.h). Checked against the convex contact
// (a convex plan in a slot), against two 2D Kelvin–Voigt contacts in parallel (a U-shaped slab
// striking a wall with both legs), for passivity, and for which slot a component belongs to.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "solver/core/analysis.h"
#include "solver/elements/contact.h"
#include "solver/elements/plan_pair.h"
#include "solver/elements/polygon_contact.h"
#include "solver/materials/impact_law.h"
#include "tests/model_test_support.h"

namespace isopound {
namespace {

constexpr double kSlabMass = 340e3, kWallMass = 500e3, kSide = 10.0;
constexpr double kLeg = 2.0;  // the U's legs: kLeg wide, the notch kSide − 2 kLeg wide, 5 m deep

ConvexPolygon rectangle(double x0, double y0, double x1, double y1) {
  return ConvexPolygon{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A U-shaped slab centred at the origin (its bounding square kSide wide), legs towards +x.
SimplePolygon u_slab() {
  const double a = 0.5 * kSide, b = a - kLeg;
  return SimplePolygon{{-a, -a}, {a, -a}, {a, -b}, {0.0, -b}, {0.0, b}, {a, b}, {a, a}, {-a, a}};
}

SimplePolygon square_slab() {
  const double a = 0.5 * kSide;
  return SimplePolygon{{-a, -a}, {a, -a}, {a, a}, {-a, a}};
}

ConvexPolygon hull(const SimplePolygon& p) {
  return ConvexPolygon{
      p.box_min(), {p.box_max().x, p.box_min().y}, p.box_max(), {p.box_min().x, p.box_max().y}};
}

// A rigid wall whose face x = face_x looks towards −x, 1 m thick, 20 m long: never moves.
ConvexPolygon wall_shape(double face_x) {
  return rectangle(face_x, -10.0, face_x + 1.0, 10.0);
}

double polar_moment(double m) {
  return m * (kSide * kSide + kSide * kSide) / 12.0;
}

// A free slab (u, v, θ) on springs of period 2 s and 10 % damping.
Model slab_model() {
  Model m;
  m.dofs = {{"slab/x", 0, 0}, {"slab/y", 0, 0}, {"slab/theta", 0, 0}};
  const double kx = kSlabMass * std::pow(2 * std::numbers::pi / 2.0, 2);
  m.mass = Eigen::Matrix3d::Zero();
  m.mass(0, 0) = m.mass(1, 1) = kSlabMass;
  m.mass(2, 2) = polar_moment(kSlabMass);
  m.stiffness = Eigen::Matrix3d::Zero();
  m.stiffness(0, 0) = m.stiffness(1, 1) = kx;
  m.stiffness(2, 2) = kx * polar_moment(1.0);
  m.damping = 2 * 0.1 * (2 * std::numbers::pi / 2.0) * m.mass;
  m.influence = Eigen::Vector3d(1, 0, 0);
  return m;
}

PolygonBody moving(const ConvexPolygon& shape) {
  return {0, 1, 2, {0, 0}, shape, kSlabMass};
}
PolygonBody fixed(const ConvexPolygon& shape) {
  return {-1, -1, -1, {0, 0}, shape, kWallMass};
}

// The slots of a slab of outline `slab` against the wall at face_x, pushed into `m`.
std::shared_ptr<PlanPair> add_plan_contacts(Model& m, const SimplePolygon& slab, double face_x,
                                            int slots, const PolygonContactConfig& cfg) {
  const ConvexPolygon wall = wall_shape(face_x);
  auto pair = std::make_shared<PlanPair>(
      PlanPairBody{slab, {0, 0}, true}, PlanPairBody{SimplePolygon(wall.vertices()), {0, 0}, false},
      slots);
  for (int s = 0; s < slots; ++s)
    m.elements.push_back(std::make_unique<PolygonContact>(
        "slab-wall " + std::to_string(s + 1), moving(hull(slab)), fixed(wall), cfg, pair, s));
  return pair;
}

const PolygonContact& contact(const Model& m, int k) {
  return *static_cast<const PolygonContact*>(m.elements[k].get());
}

double rel(double a, double b) {
  return std::abs(a - b) / std::abs(b);
}

// A convex plan given as a plan pair (one slot) is the convex contact: the same overlap and
// witness; only the placement's rounding differs (SimplePolygon's own cos θ, sin θ and sums):
// measured 2.5e-7 on the forces, 6e-7 on the energies, 1.1e-7 on the displacements.
TEST(PlanContact, ConvexPlanInASlotAgreesWithTheConvexContact) {
  const double theta0 = 0.2;
  const double reach = 0.5 * kSide * (std::cos(theta0) + std::sin(theta0));
  RunOptions o;
  o.initial_displacement = Eigen::Vector3d(0, 0, theta0);
  o.initial_velocity = Eigen::Vector3d(1.2, 0.8, 0.0);
  Model convex = slab_model();
  convex.elements.push_back(std::make_unique<PolygonContact>(
      "c", moving(hull(square_slab())), fixed(wall_shape(reach + 0.02)), PolygonContactConfig{}));
  Model slotted = slab_model();
  add_plan_contacts(slotted, square_slab(), reach + 0.02, 1, PolygonContactConfig{});
  const AnalysisResult rc = run_analysis(convex, test::still(1.0, 1e-3), o);
  const AnalysisResult rs = run_analysis(slotted, test::still(1.0, 1e-3), o);
  ASSERT_EQ(contact(convex, 0).impacts(), contact(slotted, 0).impacts());
  ASSERT_GE(contact(convex, 0).impacts(), 1);
  for (int i : {0, 1, 3, 5, 9, 10})  // normal, tangential, indentation, velocity, energies
    EXPECT_LT(rel(rs.element_outputs[0][i].value, rc.element_outputs[0][i].value), 1e-5)
        << contact(convex, 0).output_name(i);
  for (int d = 0; d < 3; ++d)
    EXPECT_LT(rel(rs.displacement[d].value, rc.displacement[d].value), 1e-6) << d;
}

// Collinear vertices, as drawings have them (a square written with a vertex in the middle of
// each side, or as an L whose notch has no size), are the square's outline: the same results.
TEST(PlanContact, CollinearVerticesGiveTheSameResults) {
  const double a = 0.5 * kSide, theta0 = 0.2;
  const double reach = a * (std::cos(theta0) + std::sin(theta0));
  const SimplePolygon drawn{{-a, -a}, {0, -a}, {a, -a}, {a, 0}, {a, a}, {0, a}, {-a, a}, {-a, 0}};
  ASSERT_TRUE(drawn.convex());
  RunOptions o;
  o.initial_displacement = Eigen::Vector3d(0, 0, theta0);
  o.initial_velocity = Eigen::Vector3d(1.2, 0.8, 0.0);
  Model plain = slab_model(), with_collinear = slab_model();
  add_plan_contacts(plain, square_slab(), reach + 0.02, 1, PolygonContactConfig{});
  add_plan_contacts(with_collinear, drawn, reach + 0.02, 1, PolygonContactConfig{});
  const AnalysisResult r0 = run_analysis(plain, test::still(1.0, 1e-3), o);
  const AnalysisResult r1 = run_analysis(with_collinear, test::still(1.0, 1e-3), o);
  ASSERT_GE(contact(plain, 0).impacts(), 1);
  for (int i = 0; i < PolygonContact::kOutputCount; ++i)
    EXPECT_NEAR(r1.element_outputs[0][i].value, r0.element_outputs[0][i].value,
                1e-9 * std::abs(r0.element_outputs[0][i].value))
        << contact(plain, 0).output_name(i);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(r1.displacement[d].value, r0.displacement[d].value,
                1e-9 * r0.displacement[d].value);
}

// Legs first, square-on into a wall: each leg's overlap is kLeg × δ, two components, two
// Kelvin–Voigt contacts (k = k_N kLeg, the pair's m_eff and ξ) acting in parallel on the slab,
// which is a 1D mass with two Contact1D at the same gap.
TEST(PlanContact, USlabLegsFirstIsTwoKelvinVoigtContactsInParallel) {
  const double gap = 0.05, v0 = 1.0;
  PolygonContactConfig cfg;
  cfg.friction = false;
  cfg.keep_tension = true;  // Contact1D's Kelvin–Voigt keeps its tension
  Model m3 = slab_model();
  m3.damping.setZero();
  add_plan_contacts(m3, u_slab(), 0.5 * kSide + gap, 3, cfg);

  Model m1;
  m1.dofs = {{"slab/x", 0, 0}};
  m1.mass = Eigen::MatrixXd::Constant(1, 1, kSlabMass);
  m1.stiffness = Eigen::MatrixXd::Constant(1, 1, m3.stiffness(0, 0));
  m1.damping = Eigen::MatrixXd::Zero(1, 1);
  m1.influence = Eigen::VectorXd::Ones(1);
  ImpactLawConfig law;
  law.law = "kelvin_voigt";
  law.k = cfg.k_normal * kLeg;
  law.e = cfg.restitution;
  law.mass_1 = kSlabMass;
  law.mass_2 = kWallMass;
  for (int leg = 0; leg < 2; ++leg)
    m1.elements.push_back(std::make_unique<Contact1D>("leg", ContactBody{0, 1.0}, ContactBody{},
                                                      gap, make_impact_law(law),
                                                      effective_mass(kSlabMass, kWallMass), 100));

  RunOptions o3, o1;
  o3.initial_velocity = Eigen::Vector3d(v0, 0, 0);
  o1.initial_velocity = Eigen::VectorXd::Constant(1, v0);
  const AnalysisResult r3 = run_analysis(m3, test::still(0.15, 1e-3), o3);
  const AnalysisResult r1 = run_analysis(m1, test::still(0.15, 1e-3), o1);
  ASSERT_EQ(contact(m3, 0).impacts(), 1);
  ASSERT_EQ(contact(m3, 1).impacts(), 1);
  EXPECT_EQ(contact(m3, 2).impacts(), 0);  // no third component
  // The two legs, symmetric: equal forces, no turning.
  EXPECT_LT(rel(r3.element_outputs[0][0].value, r3.element_outputs[1][0].value), 1e-9);
  EXPECT_LT(r3.displacement[2].value * 0.5 * kSide, 1e-6 * r3.displacement[0].value);
  // Against the 1D pair (each contact's peak force, the slab's peak and rebound).
  EXPECT_GT(r1.element_outputs[0][0].value, 1e6);
  EXPECT_LT(rel(r3.element_outputs[0][0].value, r1.element_outputs[0][0].value), 1e-5);
  EXPECT_LT(rel(r3.displacement[0].value, r1.displacement[0].value), 1e-6);
  // Arrival at the wall on the springs (ω = π rad/s): v² = v0² − ω² gap².
  const double v_arrival = std::sqrt(v0 * v0 - std::pow(std::numbers::pi * gap, 2));
  EXPECT_LT(rel(contact(m3, 0).max_impact_velocity(), v_arrival), 1e-6);
  EXPECT_LT(rel(contact(m3, 1).max_impact_velocity(), v_arrival), 1e-6);
}

// Which slot a component belongs to: the order of the overlap's components is that of the piece
// pairs, but a slot in contact keeps its own component (by shared piece pairs and centroid).
TEST(PlanContact, AClosedSlotKeepsItsComponent) {
  const double face = 0.5 * kSide;
  const ConvexPolygon wall = wall_shape(face);
  PlanPair pair(PlanPairBody{u_slab(), {0, 0}, true},
                PlanPairBody{SimplePolygon(wall.vertices()), {0, 0}, false}, 2);
  const PlanPair::Placement6 both{0.01, 0, 0, 0, 0, 0};
  const Overlap leg0 = pair.overlap(0, both), leg1 = pair.overlap(1, both);
  ASSERT_GT(leg0.area, 0.0);
  ASSERT_GT(leg1.area, 0.0);
  EXPECT_NEAR(leg0.area, kLeg * 0.01, 1e-12);
  EXPECT_NEAR(leg1.area, kLeg * 0.01, 1e-12);
  EXPECT_GT(std::abs(leg0.p_WC.y - leg1.p_WC.y), 7.0);
  // Slot 1 in contact with its leg; turned so that only that leg still overlaps: slot 1 keeps it.
  pair.set_committed(1, true, both);
  const double turn = (leg1.p_WC.y > 0 ? 1.0 : -1.0) * -0.004;  // moves leg 1 towards +x
  const PlanPair::Placement6 one{0.0, 0, turn, 0, 0, 0};
  EXPECT_EQ(pair.overlap(0, one).area, 0.0);
  EXPECT_GT(pair.overlap(1, one).area, 0.0);
  EXPECT_LT(pair.separation(1, one).distance, 0.0);  // its leg's penetration
  // Slot 0's witness: the separation of the pieces slot 1's component is not made of (the other
  // leg, 4 mm x 4 m turned away, about 0.016 m from the wall).
  const Separation free = pair.separation(0, one);
  EXPECT_GT(free.distance, 0.0);
  EXPECT_LT(free.distance, 0.05);
  EXPECT_EQ(pair.most_components(), 2);
}

// Thrown at a wall turned and sliding, with friction and the U's legs and back in turn striking:
// every episode of every slot passive, the energy balance closed.
TEST(PlanContact, USlabObliqueImpactsArePassive) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-0.5, 0.5), speed(0.5, 1.5);
  for (int trial = 0; trial < 6; ++trial) {
    Model m = slab_model();
    const double theta0 = angle(rng);
    const double reach = 0.5 * kSide * (std::abs(std::cos(theta0)) + std::abs(std::sin(theta0)));
    add_plan_contacts(m, u_slab(), reach + 0.02, 3, PolygonContactConfig{});
    RunOptions o;
    o.initial_displacement = Eigen::Vector3d(0, 0, theta0);
    o.initial_velocity = Eigen::Vector3d(speed(rng), speed(rng) - 1.0, 0.3 * angle(rng));
    const AnalysisResult r = run_analysis(m, test::still(1.0, 1e-3), o);
    int struck = 0;
    for (int s = 0; s < 3; ++s) {
      const PolygonContact& c = contact(m, s);
      if (c.impacts() > 0) ++struck;
      // No slot's episode without a force (a free slot taking a part that another slot's
      // contact is still making: the witness rate across a change of hands, clamped).
      if (c.impacts() > 0) {
        EXPECT_GT(r.element_outputs[s][0].value, 0.0) << trial << " " << s;
      }
      if (c.episodes() > 0) {
        EXPECT_LE(c.max_episode_net_work_relative(), 1e-9) << "trial " << trial << " slot " << s;
      }
    }
    EXPECT_GE(struck, 1) << trial;
    EXPECT_LT(r.energy.relative_error, 5e-3) << trial;
  }
}

}  // namespace
}  // namespace isopound
