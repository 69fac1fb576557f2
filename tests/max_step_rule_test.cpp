// The largest adaptive step's period rule (AnalysisConfig::max_step_rule): with participating
// modes the eccentric 3D building's step follows its shortest mode that carries effective mass,
// not the torsional mode without it; a 2D building keeps every mode and its step.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/core/analysis.h"
#include "solver/core/modes.h"
#include "solver/io/model_input.h"
#include "solver/structures/job.h"
#include "test_support.h"

namespace isopound {
namespace {

using Rule = AnalysisConfig::MaxStepRule;

ModelConfig config_file(const char* file) {
  return load_model_file((test::source_dir() / "configs" / file).string());
}

// The stiffness at rest, element tangents included: the matrix the rule takes its modes from,
// assembled here independently of max_step_period.
Eigen::MatrixXd stiffness_at_rest_here(Model& model) {
  Eigen::MatrixXd k = model.stiffness;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.size());
  for (auto& e : model.elements) {
    e->set_trial(zero, zero);
    e->add_tangent(k, 0.0);
    e->revert();
  }
  return k;
}

// Effective mass ratio of every mode along a unit ground motion in x and in y, the larger.
Eigen::VectorXd ratio_xy(const Model& model, const Modes& modes) {
  Eigen::VectorXd r(modes.period.size());
  for (int j = 0; j < r.size(); ++j) {
    const Eigen::VectorXd phi = modes.shape.col(j);
    double best = 0.0;
    for (const Eigen::VectorXd* iota : {&model.influence, &model.influence_y}) {
      if (iota->size() != model.size() || iota->isZero()) continue;
      const double gamma = phi.dot(model.mass * *iota);
      best = std::max(best, gamma * gamma / iota->dot(model.mass * *iota));
    }
    r[j] = best;
  }
  return r;
}

GroundMotion short_pair() {
  GroundMotion m;
  m.name = "sine pair";
  m.dt = 0.005;
  for (int k = 0; k <= 100; ++k) {
    m.acceleration.push_back(std::sin(0.05 * k));
    m.acceleration_y.push_back(0.5 * std::sin(0.07 * k));
  }
  return m;
}

TEST(MaxStepRule, EccentricBuildingStepFollowsTheFirstParticipatingMode) {
  const ModelConfig c = config_file("3d-eccentric-v30.yaml");
  // The 3D input defaults to the participating rule.
  EXPECT_EQ(c.analysis.max_step_rule, Rule::kParticipating);
  EXPECT_DOUBLE_EQ(c.analysis.participation_threshold, 1e-5);
  Model model = build_model(c);
  const Modes modes = compute_modes(stiffness_at_rest_here(model), model.mass, model.influence);
  const Eigen::VectorXd ratio = ratio_xy(model, modes);
  const int n = static_cast<int>(modes.period.size());
  // Periods descend with the index: the shortest mode is the last. It is torsional (its
  // kinetic energy phi^T M phi = 1 mostly on the rotation DOFs) and carries almost no mass
  // along x or y; the next one does (these are the facts the rule exploits).
  const Eigen::VectorXd last = modes.shape.col(n - 1);
  double rotation_share = 0.0;
  const Eigen::VectorXd m_last = model.mass * last;
  for (int i = 0; i < n; ++i)
    if (model.dofs[i].kind == DofKind::kRotation) rotation_share += last[i] * m_last[i];
  EXPECT_GT(rotation_share, 0.5);
  EXPECT_LT(ratio[n - 1], 1e-5);
  EXPECT_GE(ratio[n - 2], 1e-5);
  EXPECT_NEAR(modes.period[n - 1], 0.0611, 0.0005);  // the issue's 0.061 s

  const double all = max_step_period(model, Rule::kAllModes, 0.0);
  const double participating = max_step_period(model, Rule::kParticipating, 1e-5);
  EXPECT_DOUBLE_EQ(all, modes.period[n - 1]);
  EXPECT_DOUBLE_EQ(participating, modes.period[n - 2]);
  EXPECT_NEAR(participating, 0.0769, 0.0005);
  // A threshold above mode n-1's ratio moves the period to the next mode that reaches it.
  int next = n - 3;
  while (ratio[next] < 1.1 * ratio[n - 2]) --next;
  EXPECT_DOUBLE_EQ(max_step_period(model, Rule::kParticipating, 1.1 * ratio[n - 2]),
                   modes.period[next]);

  // The run's analysis interval: record interval / ceil(dt / (T / steps_per_period)), here
  // 0.005 s / 2 (participating) where every mode gave 0.005 s / 3.
  const GroundMotion motion = short_pair();
  RunOptions options = run_options(c);
  options.output.histories = false;
  const AnalysisResult r = run_analysis(model, motion, options);
  EXPECT_DOUBLE_EQ(r.stats.step_period, participating);
  EXPECT_DOUBLE_EQ(r.stats.interval, 0.005 / 2);
  Model model_all = build_model(c);
  options.analysis.max_step_rule = Rule::kAllModes;
  const AnalysisResult r_all = run_analysis(model_all, motion, options);
  EXPECT_DOUBLE_EQ(r_all.stats.step_period, all);
  EXPECT_DOUBLE_EQ(r_all.stats.interval, 0.005 / 3);
}

// Worst relative difference over the peaks the 3D summary prints (displacements of every DOF,
// translational absolute accelerations, drifts, the plan probes, the bearings' outputs).
double worst_peak_difference(const Model& model, const AnalysisResult& a, const AnalysisResult& b) {
  double worst = 0.0;
  const auto compare = [&](const Peak& p, const Peak& q) {
    if (q.value > 1e-9) worst = std::max(worst, std::abs(p.value - q.value) / q.value);
  };
  for (int i = 0; i < model.size(); ++i) {
    compare(a.displacement[i], b.displacement[i]);
    if (model.dofs[i].kind != DofKind::kRotation)
      compare(a.absolute_acceleration[i], b.absolute_acceleration[i]);
  }
  for (std::size_t s = 0; s < a.drift.size(); ++s) compare(a.drift[s], b.drift[s]);
  for (std::size_t p = 0; p < a.probes.size(); ++p) {
    compare(a.probes[p].x, b.probes[p].x);
    compare(a.probes[p].y, b.probes[p].y);
    compare(a.probes[p].resultant, b.probes[p].resultant);
  }
  for (std::size_t e = 0; e < a.element_outputs.size(); ++e)
    for (std::size_t k = 0; k < a.element_outputs[e].size(); ++k)
      compare(a.element_outputs[e][k], b.element_outputs[e][k]);
  return worst;
}

// The issue's accuracy point at the participating rule's default step (2.5 ms), on the first
// 10 s of the RSN1084 pair (the strong motion; the whole record is measured in
// bench/RESULTS.md): every printed peak within 0.5 % of a fixed 1e-4 s run (which agrees with
// fixed 5e-5 s to 6e-6 on the whole record), and the energy balance within 0.1 %.
TEST(MaxStepRule, EccentricBuildingPeaksAtTheParticipatingStepMatchAFineFixedStep) {
  ISOPOUND_REQUIRE_RECORDS();
  const ModelConfig c = config_file("3d-eccentric-v30.yaml");
  GroundMotion motion = load_ground_motion(c.ground_motion, true);
  const std::size_t samples = static_cast<std::size_t>(std::lround(10.0 / motion.dt)) + 1;
  motion.acceleration.resize(samples);
  motion.acceleration_y.resize(samples);
  RunOptions options = run_options(c);
  options.output.histories = false;
  Model model = build_model(c);
  const AnalysisResult fast = run_analysis(model, motion, options);
  EXPECT_DOUBLE_EQ(fast.stats.interval, 0.0025);
  options.analysis.stepping = AnalysisConfig::Stepping::kFixed;
  options.analysis.dt = 1e-4;
  Model fine_model = build_model(c);
  const AnalysisResult fine = run_analysis(fine_model, motion, options);
  const double worst = worst_peak_difference(model, fast, fine);
  EXPECT_LT(worst, 5e-3);
  EXPECT_GT(worst, 1e-5);  // the two runs do differ: the comparison is not vacuous
  EXPECT_LT(fast.energy.relative_error, 1e-3);
}

TEST(MaxStepRule, TwoDimensionalBuildingKeepsEveryModeAndItsStep) {
  const ModelConfig c = config_file("thesis-3storey-bw.yaml");
  EXPECT_EQ(c.analysis.max_step_rule, Rule::kAllModes);  // 2D default: the rule of before
  Model model = build_model(c);
  const Modes modes = compute_modes(stiffness_at_rest_here(model), model.mass, model.influence);
  const double all = max_step_period(model, Rule::kAllModes, 0.0);
  EXPECT_DOUBLE_EQ(all, modes.period.minCoeff());
  EXPECT_DOUBLE_EQ(shortest_period(model), all);
  // Every mode of the isolated 3-storey stick carries > 1e-5 of the mass, so even the
  // participating rule would keep its step.
  EXPECT_GT(ratio_xy(model, modes).minCoeff(), 1e-5);
  EXPECT_DOUBLE_EQ(max_step_period(model, Rule::kParticipating, 1e-5), all);

  GroundMotion motion = short_pair();
  motion.acceleration_y.clear();
  RunOptions options = run_options(c);
  options.output.histories = false;
  const AnalysisResult r = run_analysis(model, motion, options);
  EXPECT_DOUBLE_EQ(r.stats.step_period, all);
  const int per_sample = static_cast<int>(std::ceil(0.005 / (all / 25.0)));
  EXPECT_EQ(per_sample, 2);  // T_min 0.0796 s: 2 steps per 5 ms sample, as before the rule
  EXPECT_DOUBLE_EQ(r.stats.interval, 0.005 / per_sample);
}

TEST(MaxStepRule, InputKeys) {
  const std::string base = R"(
building:
  base: {mass: 340 t}
  floors: [{mass: 340 t, stiffness: 600 MN/m, height: 3.2 m},
           {mass: 250 t, stiffness: 600 MN/m, height: 3.2 m}]
  isolator: {model: linear, Tb: 2 s}
)";
  const auto load = [&](const std::string& analysis) {
    return load_model(YAML::Load(base + analysis), "inline.yaml", "/models");
  };
  EXPECT_EQ(load("").analysis.max_step_rule, Rule::kAllModes);
  const ModelConfig p =
      load("analysis: {max_step_rule: participating, participation_threshold: 1e-3}");
  EXPECT_EQ(p.analysis.max_step_rule, Rule::kParticipating);
  EXPECT_DOUBLE_EQ(p.analysis.participation_threshold, 1e-3);
  for (const char* bad : {"analysis: {max_step_rule: some_modes}",
                          "analysis: {max_step_rule: participating, participation_threshold: 1}",
                          "analysis: {max_step_rule: participating, participation_threshold: 0}"}) {
    try {
      load(bad);
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 7) << bad;
      EXPECT_NE(std::string(e.what()).find("analysis."), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace isopound
