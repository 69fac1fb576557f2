// Pounding through the whole solver (stepper, contact element, events) against independent
// references: free two-mass collisions (tests/two_mass_reference.h) and a rigid-wall bounce.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "solver/core/analysis.h"
#include "solver/elements/contact.h"
#include "solver/materials/impact_law.h"
#include "tests/model_test_support.h"
#include "tests/two_mass_reference.h"

namespace isopound {
namespace {

constexpr double kM1 = 340e3, kM2 = 500e3, kV0 = 1.0, kK = 2.5e9, kKh = 2.5e9;

using test::still;

// Two free masses on a line, m1 at x = 0 moving at v0 towards m2 at rest, 1 cm apart.
struct Collision {
  double restitution;     // (v2 - v1) / v0 after the run
  double momentum_error;  // relative
  double dissipated;      // J, reported by the contact element
  double indentation;     // m
  double max_force;       // N, peak over the run
  int impacts;
  long steps;
};

Collision collide(const std::string& law, double e,
                  double steps_per_contact = AnalysisConfig{}.steps_per_contact) {
  Model model;
  model.mass = Eigen::Vector2d(kM1, kM2).asDiagonal();
  model.damping = Eigen::Matrix2d::Zero();
  model.stiffness = Eigen::Matrix2d::Zero();
  model.influence = Eigen::Vector2d::Ones();
  model.dofs = {{"m1", 0, 0}, {"m2", 0, 0}};
  ImpactLawConfig c;
  c.law = law;
  c.e = e;
  c.k = kK;
  c.k_h = kKh;
  c.mass_1 = kM1;
  c.mass_2 = kM2;
  auto contact =
      std::make_unique<Contact1D>("contact", ContactBody{0, 1.0}, ContactBody{1, -1.0}, 0.01,
                                  make_impact_law(c), effective_mass(kM1, kM2), steps_per_contact);
  const Contact1D* probe = contact.get();
  model.elements.push_back(std::move(contact));
  RunOptions o;
  o.analysis.steps_per_contact = steps_per_contact;
  o.output.interval = 0.0;
  o.initial_velocity = Eigen::Vector2d(kV0, 0.0);
  const AnalysisResult r = run_analysis(model, still(0.2, 1e-3), o);
  const std::size_t cols = r.history.columns.size();
  const double* last = &r.history.values[r.history.values.size() - cols];
  const double v1 = last[2 + 2], v2 = last[2 + 3];  // time, ag, u1, u2, v1, v2, ...
  Collision out;
  out.restitution = (v2 - v1) / kV0;
  out.momentum_error = std::abs(kM1 * v1 + kM2 * v2 - kM1 * kV0) / (kM1 * kV0);
  out.dissipated = probe->dissipated_energy();
  out.indentation = probe->indentation();
  out.max_force = r.element_outputs[0][0].value;
  out.impacts = probe->impacts();
  out.steps = r.stats.steps;
  return out;
}

class TwoMassSolver : public ::testing::TestWithParam<const char*> {};

TEST_P(TwoMassSolver, MatchesReferenceForEveryRestitution) {
  const std::string law = GetParam();
  for (const double e : {0.5, 0.6, 0.7, 0.8, 0.9}) {
    SCOPED_TRACE(law + " e = " + std::to_string(e));
    const test::TwoMassResult ref = test::reference_collision(law, e, kM1, kM2, kV0, kK, kKh);
    const Collision c = collide(law, e);
    EXPECT_EQ(c.impacts, 1);
    // 1e-3 on the apparent restitution (the acceptance bound), 1e-9 on momentum.
    EXPECT_NEAR(c.restitution, ref.restitution, 1e-3);
    EXPECT_LT(c.momentum_error, 1e-9);
    // Energy lost = 1/2 m_eff v0^2 (1 - e_app^2), and the contact reports it as dissipated.
    const double m_eff = kM1 * kM2 / (kM1 + kM2);
    const double kinetic = 0.5 * m_eff * kV0 * kV0;
    const double loss = kinetic * (1.0 - c.restitution * c.restitution);
    EXPECT_NEAR(c.dissipated, loss, 1e-3 * kinetic);
    EXPECT_NEAR(c.max_force / ref.max_force, 1.0, 5e-3);
    if (law == std::string("kelvin_voigt")) {
      EXPECT_NEAR(c.restitution, e, 1e-4);
    }
    if (law == std::string("modified_kelvin_voigt")) {
      EXPECT_NEAR(c.indentation / ref.permanent_indentation, 1.0, 1e-2);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Laws, TwoMassSolver,
                         ::testing::Values("linear", "kelvin_voigt", "modified_kelvin_voigt", "ye",
                                           "mahmoud_jankowski", "pant_wijeyewickrema", "hertz",
                                           "jankowski", "hertz_damp_muthukumar", "hertz_damp_ye"));

TEST(TwoMassSolver, ElasticLawsGiveRestitutionOne) {
  for (const char* law : {"linear", "hertz"})
    EXPECT_NEAR(collide(law, 0.7).restitution, 1.0, 1e-4) << law;
}

TEST(TwoMassSolver, RestitutionConvergesWithStepsPerContact) {
  // 4x the steps per contact: second order cuts the error 16x (>= 8x asked for KV); Hertz
  // (delta^1.5: a slope starting at 0) measured 6.4x, >= 5x asked; Jankowski's damping
  // ~ delta^(1/4) has an infinite slope at onset, which lowers the order (>= 3x asked).
  // 50 vs 200: at 25 steps per contact the error tolerance (1e-4) already refines the contact
  // steps itself (KV error 1.8e-4 instead of 5.1e-4), so 25 no longer is "25 per contact".
  for (const auto& [law, factor] :
       {std::pair{"kelvin_voigt", 8.0}, std::pair{"hertz", 5.0}, std::pair{"jankowski", 3.0}}) {
    const double ref = test::reference_collision(law, 0.7, kM1, kM2, kV0, kK, kKh).restitution;
    const double coarse = std::abs(collide(law, 0.7, 50).restitution - ref);
    const double fine = std::abs(collide(law, 0.7, 200).restitution - ref);
    EXPECT_LT(fine, coarse / factor) << law << " " << coarse << " " << fine;
  }
}

// A linear SDOF (T = 2 s, undamped) bouncing between rigid walls with KV, e = 1: no energy may
// be lost over >= 10 impacts; with e = 0.7 each impact dissipates and the balance still holds.
struct Bounce {
  double energy_error;
  double final_energy;
  double initial_energy;
  int impacts;
  AnalysisResult result;
};

Bounce bounce(const std::string& law, double e, double duration) {
  const double m = 340e3, k = m * std::pow(2.0 * M_PI / 2.0, 2), gap = 0.05, v0 = 1.0;
  Model model;
  model.mass = Eigen::MatrixXd::Constant(1, 1, m);
  model.damping = Eigen::MatrixXd::Zero(1, 1);
  model.stiffness = Eigen::MatrixXd::Constant(1, 1, k);
  model.influence = Eigen::VectorXd::Ones(1);
  model.dofs = {{"slab", 0, 0}};
  ImpactLawConfig c;
  c.law = law;
  c.e = e;
  c.mass_1 = m;
  c.mass_2 = 500e3;
  std::vector<const Contact1D*> walls;
  for (const double side : {1.0, -1.0}) {
    auto w = std::make_unique<Contact1D>(side > 0 ? "right" : "left", ContactBody{0, side},
                                         ContactBody{}, gap, make_impact_law(c),
                                         effective_mass(m, 500e3), 40.0);
    walls.push_back(w.get());
    model.elements.push_back(std::move(w));
  }
  RunOptions o;
  o.output.histories = true;
  o.initial_velocity = Eigen::VectorXd::Constant(1, v0);
  Bounce b;
  b.result = run_analysis(model, still(duration, 1e-3), o);
  const std::size_t cols = b.result.history.columns.size();
  const double* last = &b.result.history.values[b.result.history.values.size() - cols];
  const double u = last[2], v = last[3];
  b.initial_energy = 0.5 * m * v0 * v0;
  b.final_energy =
      0.5 * m * v * v + 0.5 * k * u * u + walls[0]->stored_energy() + walls[1]->stored_energy();
  b.energy_error = std::abs(b.final_energy - b.initial_energy) / b.initial_energy;
  b.impacts = walls[0]->impacts() + walls[1]->impacts();
  return b;
}

TEST(RigidWallBounce, KelvinVoigtWithRestitutionOneLosesNoEnergy) {
  const Bounce b = bounce("kelvin_voigt", 1.0, 12.0);
  EXPECT_GE(b.impacts, 10);
  EXPECT_LT(b.energy_error, 1e-4);  // the acceptance bound, on the final mechanical energy
  // The running balance (powers integrated in time) also closes.
  EXPECT_LT(b.result.energy.max_relative_error, 1e-3);
}

TEST(RigidWallBounce, DissipativeImpactsKeepTheBalance) {
  const Bounce b = bounce("kelvin_voigt", 0.7, 12.0);
  EXPECT_GE(b.impacts, 4);
  EXPECT_LT(b.final_energy, 0.5 * b.initial_energy);
  EXPECT_LT(b.result.energy.max_relative_error, 1e-3);
}

TEST(ModifiedKelvinVoigt, NeverTensileAndIndentationWidensTheGap) {
  const Bounce b = bounce("modified_kelvin_voigt", 0.6, 12.0);
  const History& h = b.result.history;
  // Columns: time, ag, u, v, a_abs, then per wall: force, penetration, impacts, v_imp, indentation,
  // energy.
  const std::size_t cols = h.columns.size();
  ASSERT_EQ(h.columns[5], "right force [N]");
  ASSERT_EQ(h.columns[9], "right indentation [m]");
  double previous_indentation = 0.0;
  int widened = 0;
  for (std::size_t r = 0; r < h.rows(); ++r) {
    const double* row = &h.values[r * cols];
    for (int w = 0; w < 2; ++w) {
      const double force = row[5 + 6 * w];
      EXPECT_GE(force, 0.0) << "row " << r;
    }
    // Right wall in contact only when u > gap + indentation (the indentation widens the gap).
    const double indentation = row[9];
    if (row[5] > 0) {
      EXPECT_GT(row[2], 0.05 + previous_indentation - 1e-12) << "row " << r;
    }
    if (indentation > previous_indentation) ++widened;
    previous_indentation = indentation;
  }
  EXPECT_GE(widened, 2);  // each impact on the right wall adds indentation
  EXPECT_GT(previous_indentation, 0.0);
}

}  // namespace
}  // namespace isopound
