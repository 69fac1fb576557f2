// Static pushover (issue 23): a one-storey bilinear building's capacity curve is k up to V_y and
// alpha k after, within 1e-9; an elastic building's curve is the linear solution K u = lambda P.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/core/pushover.h"
#include "solver/structures/building2d.h"
#include "solver/structures/pushover2d.h"

namespace isopound {
namespace {

ModelConfig fixed_base(int floors, StoryHysteresisConfig h) {
  ModelConfig c;
  c.building.isolated = false;
  c.building.damping.type = SuperstructureDamping::Type::kModal;
  for (int i = 0; i < floors; ++i) {
    FloorConfig f;
    f.mass = 340e3;
    f.stiffness = 600e6;
    f.height = 3.2;
    f.hysteresis = h;
    c.building.floors.push_back(f);
  }
  return c;
}

TEST(Pushover, OneStoreyBilinearIsKUpToYieldThenAlphaK) {
  StoryHysteresisConfig h;
  h.law.model = HysteresisModel::kBilinear;
  h.yield_value = 0.005;  // d_y = 1.6 cm, V_y = 9.6 MN
  h.post_yield_ratio = 0.05;
  BuildingPushoverOptions o;
  o.target_drift_ratio = 0.02;  // 6.4 cm = 4 d_y
  o.steps = 37;                 // steps that do not land on the yield point
  const BuildingPushoverResult r = run_pushover2d(fixed_base(1, h), o);
  ASSERT_EQ(r.rows.size(), 38u);
  const double k = 600e6, dy = 0.016, vy = k * dy;
  for (const auto& row : r.rows) {
    const double d = row[0], v = row[2];
    const double expected = d <= dy ? k * d : vy + 0.05 * k * (d - dy);
    EXPECT_NEAR(v, expected, 1e-9 * vy) << "at " << d;
    EXPECT_NEAR(row[5], v, 1e-9 * vy);  // the storey shear is the base shear
  }
  EXPECT_NEAR(r.rows.back()[0], 0.064, 1e-15);
  ASSERT_GE(r.first_yield_row, 0);
  EXPECT_GE(r.rows[r.first_yield_row][0], dy);
  EXPECT_LT(r.rows[r.first_yield_row - 1][0], dy);
  EXPECT_EQ(r.capping_row, -1);  // hardening: no peak before the end
}

TEST(Pushover, ElasticBuildingFollowsTheLinearSolution) {
  const ModelConfig c = fixed_base(3, {});
  Model model = make_model(c.building);
  PushoverOptions o;
  o.pattern = model.mass * model.influence;
  o.control = Eigen::VectorXd::Zero(3);
  o.control[2] = 1.0;
  o.target = 0.05;
  o.steps = 5;
  const std::vector<PushoverStep> curve = run_pushover(model, o);
  const Eigen::VectorXd unit = model.stiffness.ldlt().solve(o.pattern);  // u for lambda = 1
  const double lambda = 0.05 / unit[2];
  EXPECT_NEAR(curve.back().lambda, lambda, 1e-9 * lambda);
  EXPECT_LT((curve.back().u - lambda * unit).norm(), 1e-12);
}

// A peak-oriented storey softens after capping: the curve turns down and the capping row marks
// the peak base shear (at the capping drift).
TEST(Pushover, PeakOrientedStoreyHasACappingPoint) {
  StoryHysteresisConfig h;
  h.law.model = HysteresisModel::kPeakOriented;
  h.yield_value = 0.005;
  h.post_yield_ratio = 0.05;
  h.law.peak_oriented.capping_drift_ratio = 0.02;
  h.law.peak_oriented.post_capping_ratio = 0.1;
  h.law.peak_oriented.residual_strength_ratio = 0.2;
  BuildingPushoverOptions o;
  o.target_drift_ratio = 0.04;
  o.steps = 100;
  const BuildingPushoverResult r = run_pushover2d(fixed_base(1, h), o);
  ASSERT_GE(r.capping_row, 0);
  EXPECT_NEAR(r.rows[r.capping_row][1], 0.02, 1e-12);
  const double k = 600e6, dy = 0.016, dc = 0.064;
  EXPECT_NEAR(r.rows[r.capping_row][2], k * dy + 0.05 * k * (dc - dy), 1e-6);
}

}  // namespace
}  // namespace isopound
