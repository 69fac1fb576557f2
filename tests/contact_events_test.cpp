// Contact events inside a step (issue 8): the witness function's interior crossings, a single
// mass grazing a wall, fixed stepping under the contact's step limit, and the stepper's soft
// spots (Newton on the residual only, the mass matrix, a failed cut step, pounding set-up).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "solver/core/analysis.h"
#include "solver/core/newmark.h"
#include "solver/elements/contact.h"
#include "solver/elements/witness.h"
#include "solver/materials/impact_law.h"
#include "solver/structures/building2d.h"
#include "solver/structures/pounding2d.h"
#include "test_elements.h"
#include "tests/model_test_support.h"

namespace isopound {
namespace {

using test::still;

// The first zero crossing of f on [0, 1] in the given direction by dense sampling and
// bisection: an independent computation of what first_status_change must find.
template <class F>
double first_crossing_by_sampling(F f, bool upward) {
  const int n = 100000;
  double prev = f(0.0);
  for (int i = 1; i <= n; ++i) {
    const double t = static_cast<double>(i) / n, value = f(t);
    const bool crossed = upward ? (prev <= 0 && value > 0) : (prev > 0 && value <= 0);
    if (crossed) {
      double lo = t - 1.0 / n, hi = t;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        ((f(mid) > 0) == upward ? hi : lo) = mid;
      }
      return 0.5 * (lo + hi);
    }
    prev = value;
  }
  return 1.0;
}

// p(theta) as the Hermite basis sum, written out independently of witness.cpp.
double hermite(const WitnessStep& w, double t) {
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * w.d0 + (t3 - 2 * t2 + t) * w.h * w.r0 + (-2 * t3 + 3 * t2) * w.d1 +
         (t3 - t2) * w.h * w.r1;
}

TEST(Witness, OpenStepWithAnInteriorMaximumAboveZeroIsAnOnset) {
  // Both ends 1 mm open, approaching at 0.1 m/s and receding at 0.1 m/s over 0.1 s: the cubic
  // peaks at +1.5 mm in the middle (symmetric: p(1/2) = d + h (r0 - r1) / 8).
  const WitnessStep w{-1e-3, 0.1, -1e-3, -0.1, 0.1};
  EXPECT_NEAR(witness_value(w, 0.5), -1e-3 + 0.1 * 0.2 / 8, 1e-15);
  const double expected = first_crossing_by_sampling([&](double t) { return hermite(w, t); }, true);
  const double theta = first_status_change(w, /*closed=*/false);
  EXPECT_LT(expected, 0.5);
  EXPECT_NEAR(theta, expected, 1e-9);
  EXPECT_NEAR(witness_value(w, theta), 0.0, 1e-15);
  EXPECT_GT(witness_rate(w, theta), 0.0);  // approaching at the onset
  // The end values alone show nothing: the same step with a peak below 0 has no event.
  const WitnessStep low{-3e-3, 0.1, -3e-3, -0.1, 0.1};
  EXPECT_EQ(first_status_change(low, false), 1.0);
}

TEST(Witness, ClosedStepWithAnInteriorMinimumBelowZeroIsASeparation) {
  // In contact at both ends (0.2 mm), leaving at 0.05 m/s and re-entering: a dip to -0.05 mm.
  const WitnessStep w{2e-4, -0.05, 2e-4, 0.05, 0.04};
  EXPECT_LT(witness_value(w, 0.5), 0.0);
  const double expected =
      first_crossing_by_sampling([&](double t) { return hermite(w, t); }, false);
  EXPECT_NEAR(first_status_change(w, /*closed=*/true), expected, 1e-9);
  // A dip that stays within the tolerance is no event.
  EXPECT_EQ(first_status_change(w, true, 4e-4), 1.0);
}

TEST(Witness, AStepThatStartsOnTheWrongSide) {
  // Open but already 1e-9 m inside and going deeper: the onset is now.
  EXPECT_EQ(first_status_change({1e-9, 0.1, 1e-3, 0.1, 0.01}, false), 0.0);
  // Open, a hair inside after a separation cut, leaving: nothing happens.
  EXPECT_EQ(first_status_change({1e-13, -0.1, -1e-3, -0.1, 0.01}, false), 1.0);
  // Closed, a hair outside after an onset cut, entering: nothing happens.
  EXPECT_EQ(first_status_change({-1e-13, 0.1, 1e-3, 0.1, 0.01}, true), 1.0);
}

// A contact driven directly: a committed open state 1 mm from a rigid wall, then a trial that
// ends 1 mm away again while the cubic pokes through the wall inside the step.
TEST(Contact1DEvents, OnsetInsideAStepThatEndsOpen) {
  ImpactLawConfig c;
  c.law = "kelvin_voigt";
  c.mass_1 = 1e3;
  c.mass_2 = 1e3;
  const double gap = 0.01;
  Contact1D contact("wall", {0, 1.0}, {}, gap, make_impact_law(c), 500.0, 100.0);
  Eigen::VectorXd u(1), v(1);
  u << gap - 1e-3;
  v << 0.1;
  contact.begin_step(0.0, true);
  contact.set_trial(u, v);
  contact.commit();
  const double h = 0.1;
  contact.begin_step(h, false);
  v << -0.1;
  contact.set_trial(u, v);
  EXPECT_EQ(contact.force(), 0.0);  // open at the step's end
  const WitnessStep w{-1e-3, 0.1, -1e-3, -0.1, h};
  const double expected = first_crossing_by_sampling([&](double t) { return hermite(w, t); }, true);
  EXPECT_NEAR(contact.event_fraction(), expected, 1e-9);
}

// A linear oscillator (T = 2 s, undamped, amplitude A) grazing a rigid wall at gap g < A on
// the right, elastic contact (linear law): every approach reaches the wall at the speed
// omega sqrt(A^2 - g^2) (energy), the first one and the re-contact after the swing back.
struct Graze {
  int impacts;
  int counted;
  double max_impact_velocity;
};

Graze graze(double dt, double phase, double duration) {
  const double m = 1e3, omega = std::numbers::pi, k = m * omega * omega;
  const double amplitude = 0.1, gap = 0.0995;  // v_imp = omega sqrt(A^2 - g^2) = 0.0314 m/s
  Model model;
  model.mass = Eigen::MatrixXd::Constant(1, 1, m);
  model.damping = Eigen::MatrixXd::Zero(1, 1);
  model.stiffness = Eigen::MatrixXd::Constant(1, 1, k);
  model.influence = Eigen::VectorXd::Ones(1);
  model.dofs = {{"mass", 0, 0}};
  ImpactLawConfig c;
  c.law = "linear";
  c.k = 1e8;
  c.mass_1 = m;
  c.mass_2 = 1e6;
  auto wall = std::make_unique<Contact1D>("wall", ContactBody{0, 1.0}, ContactBody{}, gap,
                                          make_impact_law(c), effective_mass(m, 1e6), 100.0);
  const Contact1D* probe = wall.get();
  model.elements.push_back(std::move(wall));
  RunOptions o;
  o.output.histories = false;
  o.analysis.stepping = AnalysisConfig::Stepping::kFixed;
  o.analysis.dt = dt;
  // u = A sin(omega t + phase): the graze falls anywhere inside a step.
  o.initial_displacement = Eigen::VectorXd::Constant(1, amplitude * std::sin(phase));
  o.initial_velocity = Eigen::VectorXd::Constant(1, amplitude * omega * std::cos(phase));
  run_analysis(model, still(duration, dt), o);
  return {probe->impacts(), probe->counted_impacts(), probe->max_impact_velocity()};
}

TEST(GrazingMass, ImpactFoundAtEveryStepWithTheClosedFormVelocity) {
  const double v_exact = std::numbers::pi * std::sqrt(0.1 * 0.1 - 0.0995 * 0.0995);
  // The graze lasts ~0.02 s beyond the wall line; steps of 0.05-0.2 s (1/40 to 1/10 of the
  // period) would straddle it with both ends open.
  for (const double dt : {0.01, 0.05, 0.1, 0.2}) {
    for (const double phase : {0.1, 0.37, 0.81}) {
      SCOPED_TRACE("dt " + std::to_string(dt) + " phase " + std::to_string(phase));
      // 2.6 s: the first approach and, after the swing back, the re-contact.
      const Graze g = graze(dt, phase, 2.6);
      EXPECT_EQ(g.impacts, 2);
      EXPECT_EQ(g.counted, 2);
      // 1 %: the acceptance bound; the energy of the trapezoidal rule is exact for a linear
      // oscillator, so only the location of the onset (delta = 0) enters the speed.
      EXPECT_NEAR(g.max_impact_velocity / v_exact, 1.0, 0.01);
    }
  }
}

// Fixed stepping respects the contact's step limit: a 1 ms fixed step over a 28 ms
// Kelvin-Voigt contact would give ~28 steps per contact; limited to T_c/100 the apparent
// restitution matches e as closely as adaptive stepping does (1e-4, pounding_test.cpp).
TEST(FixedStepping, HonoursTheContactStepLimit) {
  const double m1 = 340e3, m2 = 500e3;
  Model model;
  model.mass = Eigen::Vector2d(m1, m2).asDiagonal();
  model.damping = Eigen::Matrix2d::Zero();
  model.stiffness = Eigen::Matrix2d::Zero();
  model.influence = Eigen::Vector2d::Ones();
  model.dofs = {{"m1", 0, 0}, {"m2", 0, 0}};
  ImpactLawConfig c;
  c.law = "kelvin_voigt";
  c.e = 0.7;
  c.k = 2.5e9;
  c.mass_1 = m1;
  c.mass_2 = m2;
  model.elements.push_back(
      std::make_unique<Contact1D>("c", ContactBody{0, 1.0}, ContactBody{1, -1.0}, 0.01,
                                  make_impact_law(c), effective_mass(m1, m2), 100.0));
  RunOptions o;
  o.analysis.stepping = AnalysisConfig::Stepping::kFixed;
  o.analysis.dt = 1e-3;
  o.output.interval = 0.0;
  o.initial_velocity = Eigen::Vector2d(1.0, 0.0);
  const AnalysisResult r = run_analysis(model, still(0.2, 1e-3), o);
  const std::size_t cols = r.history.columns.size();
  const double* last = &r.history.values[r.history.values.size() - cols];
  EXPECT_NEAR(last[2 + 3] - last[2 + 2], 0.7, 1e-4);  // (v2 - v1) / v0
  // 200 steps of 1 ms, of which the ~28 ms contact takes >= 100 instead of 28.
  EXPECT_GT(r.stats.steps, 200 - 28 + 90);
}

// --- stepper soft spots ---

// A linear spring that reports a wildly wrong tangent: Newton's corrections are then tiny
// while the residual stays large. Such a step must not count as converged.
class WrongTangentSpring final : public test::QuietElement {
 public:
  WrongTangentSpring() : QuietElement("spring") {}
  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd&) override { u_ = u[0]; }
  void add_force(Eigen::VectorXd& f) const override { f[0] += 1e6 * u_; }
  void add_tangent(Eigen::MatrixXd& K, double) const override { K(0, 0) += 1e30; }
  double power(const Eigen::VectorXd& v) const override { return 1e6 * u_ * v[0]; }
  double stored_energy() const override { return 0.5e6 * u_ * u_; }

 private:
  double u_ = 0.0;
};

Model one_dof(double mass) {
  Model model;
  model.mass = Eigen::MatrixXd::Constant(1, 1, mass);
  model.damping = Eigen::MatrixXd::Zero(1, 1);
  model.stiffness = Eigen::MatrixXd::Zero(1, 1);
  model.influence = Eigen::VectorXd::Ones(1);
  model.dofs = {{"x", 0, 0}};
  return model;
}

TEST(Newton, ATinyCorrectionWithALargeResidualIsNotConvergence) {
  Model model = one_dof(1e3);
  model.elements.push_back(std::make_unique<WrongTangentSpring>());
  NewmarkStepper stepper(model, {1e-9, 25});
  stepper.start(Eigen::VectorXd::Constant(1, 0.01), Eigen::VectorXd::Zero(1), 0.0);
  const StepOutcome out = stepper.try_step(0.01, 0.0);
  EXPECT_FALSE(out.converged);
  EXPECT_GT(stepper.residual().cwiseAbs().maxCoeff(), 1e-9 * 1e3 * 9.81);
}

TEST(MassMatrix, ADofWithoutMassIsAnInputError) {
  Model model = one_dof(0.0);
  try {
    run_analysis(model, still(0.1, 0.01), RunOptions{});
    FAIL() << "no error for a zero mass";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'x'"), std::string::npos) << e.what();
  }
  Model negative = one_dof(-5.0);
  EXPECT_THROW(NewmarkStepper(negative, {}), std::invalid_argument);
  Model nan = one_dof(std::nan(""));
  EXPECT_THROW(NewmarkStepper(nan, {}), std::invalid_argument);
}

// An element with an event at u = t_event on a DOF that moves at exactly 1 m/s (free mass, no
// force): the first frozen step cut to end at the event fails (NaN force), which halves it.
// The event must still be settled exactly once, where it is (u = t_event), never at the end of
// the halved step.
class EventProbe final : public Element {
 public:
  explicit EventProbe(double at) : at_(at) {}
  void begin_step(double h, bool freeze) override { frozen_ = freeze && h > 0; }
  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd&) override {
    u1_ = u[0];
    fail_ = frozen_ && failures_left_ > 0;
    if (fail_) --failures_left_;
  }
  void add_force(Eigen::VectorXd& f) const override {
    if (fail_) f[0] += std::nan("");
  }
  void add_tangent(Eigen::MatrixXd&, double) const override {}
  double power(const Eigen::VectorXd&) const override { return 0.0; }
  double stored_energy() const override { return 0.0; }
  void commit() override { u0_ = u1_; }
  void revert() override { u1_ = u0_; }
  double event_fraction() override {
    if (settled_ || !(u0_ < at_ && u1_ >= at_)) return 1.0;
    return (at_ - u0_) / (u1_ - u0_);
  }
  bool settle_event() override {
    settled_at_.push_back(u0_);
    settled_ = true;
    return false;
  }
  int output_count() const override { return 0; }
  std::string output_name(int) const override { return ""; }
  std::string output_unit(int) const override { return ""; }
  double output(int) const override { return 0.0; }
  const std::string& label() const override { return label_; }

  std::vector<double> settled_at_;

 private:
  double at_, u0_ = 0.0, u1_ = 0.0;
  bool frozen_ = false, fail_ = false, settled_ = false;
  int failures_left_ = 1;
  std::string label_ = "probe";
};

TEST(EventHandling, AFailedCutStepLeavesNoStaleEvent) {
  for (const auto stepping :
       {AnalysisConfig::Stepping::kFixed, AnalysisConfig::Stepping::kAdaptive}) {
    Model model = one_dof(1.0);
    auto probe = std::make_unique<EventProbe>(0.0123);
    const EventProbe* p = probe.get();
    model.elements.push_back(std::move(probe));
    RunOptions o;
    o.output.histories = false;
    o.analysis.stepping = stepping;
    o.analysis.dt = 0.01;
    o.initial_velocity = Eigen::VectorXd::Constant(1, 1.0);
    run_analysis(model, still(0.05, 0.01), o);
    ASSERT_EQ(p->settled_at_.size(), 1u);
    EXPECT_NEAR(p->settled_at_[0], 0.0123, 1e-12);
  }
}

// Two walls entries on one level, the first a flexible wall (it adds a structure to the
// model, which moves model.structures): the second entry must still find its level. Under
// AddressSanitizer the dangling reference of the old code was a heap-use-after-free.
TEST(PoundingSetUp, FlexibleWallBeforeASecondWallsEntry) {
  BuildingConfig b;
  b.name = "b";
  b.base_mass = 340e3;
  b.floors = {{340e3, 600e6, 3.2}, {250e3, 600e6, 3.2}};
  WallConfig flexible;
  flexible.left = false;
  flexible.gap_right = 0.1;
  flexible.stiffness = 1e9;
  flexible.damping_ratio = 0.05;
  WallConfig upper;
  upper.left = true;
  upper.right = false;
  upper.level = 2;
  upper.gap_left = 0.05;
  b.walls = {flexible, upper};
  Model model = make_model(b);
  const int roof = model.structures[0].level_dofs[2];
  add_walls(model, 0, b, 100.0);
  ASSERT_EQ(model.structures.size(), 2u);  // the building and the flexible wall
  // The upper wall's contact acts on the roof: pushing the roof 6 cm left closes its 5 cm gap.
  Contact1D* contact = nullptr;
  for (auto& e : model.elements)
    if (e->label().find("wall left (level 2)") != std::string::npos)
      contact = dynamic_cast<Contact1D*>(e.get());
  ASSERT_NE(contact, nullptr);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.size()), v = u;
  u[roof] = -0.06;
  contact->begin_step(0.0, true);
  contact->set_trial(u, v);
  EXPECT_NEAR(contact->penetration(), 0.01, 1e-12);
}

}  // namespace
}  // namespace isopound
