// Accuracy per cost and energy balance of the default stepping on real records (RSN1084):
// every peak within 1 % of a fixed 1e-5 s run, >= 50x fewer steps than fixed 2e-5 s.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "solver/core/analysis.h"
#include "solver/excitation/ground_motion.h"
#include "solver/structures/building2d.h"
#include "tests/test_support.h"

namespace isopound {
namespace {

BuildingConfig thesis_building(int storeys, IsolatorConfig::Model isolator) {
  BuildingConfig b;
  b.name = std::to_string(storeys) + "-storey";
  b.base_mass = 340e3;
  for (int i = 0; i < storeys; ++i)
    b.floors.push_back({i + 1 < storeys ? 340e3 : 250e3, 600e6, 3.2});
  b.isolator.model = isolator;  // Tb 2 s, QW 5 %, uy 1 cm (the defaults)
  return b;
}

AnalysisResult analyse(const BuildingConfig& b, const GroundMotion& motion, double fixed_dt) {
  Model model = make_model(b);
  RunOptions options;
  options.output.histories = false;
  if (fixed_dt > 0) {
    options.analysis.stepping = AnalysisConfig::Stepping::kFixed;
    options.analysis.dt = fixed_dt;
  }
  return run_analysis(model, motion, options);
}

double worst_peak_error(const AnalysisResult& run, const AnalysisResult& ref, std::string& where) {
  double worst = 0.0;
  auto compare = [&](const std::vector<Peak>& a, const std::vector<Peak>& b, const char* what) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      const double e = std::abs(a[i].value / b[i].value - 1.0);
      if (e > worst) {
        worst = e;
        where = std::string(what) + " " + std::to_string(i);
      }
    }
  };
  compare(run.displacement, ref.displacement, "displacement");
  compare(run.drift, ref.drift, "drift");
  compare(run.absolute_acceleration, ref.absolute_acceleration, "absolute acceleration");
  compare(run.element_outputs[0], ref.element_outputs[0], "isolator output");
  return worst;
}

struct Case {
  const char* record;
  IsolatorConfig::Model isolator;
  const char* name;
};

class AccuracyPerCost : public ::testing::TestWithParam<Case> {};

TEST_P(AccuracyPerCost, DefaultPeaksWithinOnePercentOfFineFixedStepWithFiftyTimesFewerSteps) {
  ISOPOUND_REQUIRE_RECORDS();
  const Case c = GetParam();
  const GroundMotion motion = read_record((test::records_dir() / c.record).string());
  const BuildingConfig b = thesis_building(3, c.isolator);
  const AnalysisResult ref = analyse(b, motion, 1e-5);
  const AnalysisResult run = analyse(b, motion, 0.0);
  std::string where;
  const double worst = worst_peak_error(run, ref, where);
  EXPECT_LT(worst, 0.01) << "worst at " << where;
  // A fixed 2e-5 s run over the same duration takes duration / 2e-5 steps; count every
  // attempted step of the default run (rejected ones too).
  const double fixed_steps = std::round(run.stats.duration / 2e-5);
  const double default_steps = static_cast<double>(run.stats.steps + run.stats.rejected_steps);
  EXPECT_GE(fixed_steps / default_steps, 50.0) << default_steps << " steps";
  RecordProperty("worst_peak_error", std::to_string(worst));
  RecordProperty("step_ratio", std::to_string(fixed_steps / default_steps));
}

INSTANTIATE_TEST_SUITE_P(
    Rsn1084, AccuracyPerCost,
    ::testing::Values(Case{"RSN1084_NORTHR_SCS052.AT2", IsolatorConfig::Model::kBoucWen, "BW052"},
                      Case{"RSN1084_NORTHR_SCS142.AT2", IsolatorConfig::Model::kBoucWen, "BW142"},
                      Case{"RSN1084_NORTHR_SCS052.AT2", IsolatorConfig::Model::kBilinear, "BL052"},
                      Case{"RSN1084_NORTHR_SCS142.AT2", IsolatorConfig::Model::kBilinear, "BL142"}),
    [](const auto& info) { return std::string(info.param.name); });

class EnergyBalanceTest : public ::testing::TestWithParam<Case> {};

TEST_P(EnergyBalanceTest, BalanceErrorBelowOneThousandthOfInput) {
  ISOPOUND_REQUIRE_RECORDS();
  const Case c = GetParam();
  const GroundMotion motion = read_record((test::records_dir() / c.record).string());
  const AnalysisResult run = analyse(thesis_building(3, c.isolator), motion, 0.0);
  const EnergyBalance& e = run.energy;
  EXPECT_GT(e.input, 0.0);
  EXPECT_GT(e.hysteretic, 0.0);
  EXPECT_GT(e.viscous, 0.0);
  EXPECT_LT(e.relative_error, 1e-3);
  EXPECT_LT(e.max_relative_error, 1e-3);
  // The measure is sensitive to the time discretisation: the default step is half the record
  // interval, and a fixed step of the full interval (2x larger) must show about 4x the
  // imbalance (second order); > 3x leaves room for the non-asymptotic part.
  const AnalysisResult coarse = analyse(thesis_building(3, c.isolator), motion, motion.dt);
  EXPECT_GT(coarse.energy.max_relative_error, 3.0 * e.max_relative_error);
}

INSTANTIATE_TEST_SUITE_P(
    Rsn1084, EnergyBalanceTest,
    ::testing::Values(Case{"RSN1084_NORTHR_SCS052.AT2", IsolatorConfig::Model::kBoucWen, "BW052"},
                      Case{"RSN1084_NORTHR_SCS142.AT2", IsolatorConfig::Model::kBoucWen, "BW142"},
                      Case{"RSN1084_NORTHR_SCS052.AT2", IsolatorConfig::Model::kBilinear, "BL052"},
                      Case{"RSN1084_NORTHR_SCS142.AT2", IsolatorConfig::Model::kBilinear, "BL142"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(Modes, ThesisFixedBasePeriods) {
  // THEORY section 1: fixed-base fundamental periods 0.31 s (3-storey) and 0.50 s (5-storey).
  for (const auto& [storeys, period] : {std::pair{3, 0.31}, std::pair{5, 0.50}}) {
    const ShearStick s =
        fixed_base_superstructure(thesis_building(storeys, IsolatorConfig::Model::kBoucWen));
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(s.stiffness, s.mass);
    const double t1 = 2.0 * M_PI / std::sqrt(eig.eigenvalues()[0]);
    EXPECT_NEAR(t1, period, 0.005) << storeys << " storeys";
  }
}

}  // namespace
}  // namespace isopound
