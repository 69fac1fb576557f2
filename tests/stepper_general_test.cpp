// The stepper's general parts: LU for a non-symmetric element tangent (a linear element with
// f = A u, A non-symmetric: an exact Jacobian converges in one Newton correction and matches an
// independent Newmark solve), two-component ground load through the influence matrix.
#include <gtest/gtest.h>

#include "solver/core/newmark.h"
#include "test_elements.h"

namespace isopound {
namespace {

TEST(StepperGeneral, NonSymmetricTangentUsesLUAndMatchesDirectNewmark) {
  Model model;
  model.dofs = {{"x", 0, 0, DofKind::kTranslationX}, {"y", 0, 0, DofKind::kTranslationY}};
  model.mass = Eigen::Vector2d(2e5, 3e5).asDiagonal();
  model.stiffness = Eigen::Matrix2d{{4e7, 0.0}, {0.0, 5e7}};
  model.damping = Eigen::Matrix2d::Zero();
  model.influence = Eigen::Vector2d(1.0, 0.0);
  model.influence_y = Eigen::Vector2d(0.0, 1.0);
  Eigen::Matrix2d A{{1e6, 3e7}, {-2e7, 2e6}};  // strongly non-symmetric
  model.elements.push_back(std::make_unique<test::LinearPair>(A, false));
  NewmarkStepper stepper(model, {1e-12, 25});
  ASSERT_TRUE(stepper.uses_lu());
  stepper.start(GroundAcceleration(0.0, 0.0));

  // Independent average-acceleration Newmark of M a + (K + A) u = -M iota ag, ag = (1, -0.5).
  const Eigen::Matrix2d M = model.mass, Kt = model.stiffness + A;
  const double h = 0.01;
  const Eigen::Vector2d load = -(M * Eigen::Vector2d(1.0, -0.5));
  Eigen::Vector2d u = Eigen::Vector2d::Zero(), v = u, a = u;
  for (int k = 0; k < 50; ++k) {
    const StepOutcome out = stepper.try_step(h, GroundAcceleration(1.0, -0.5));
    ASSERT_TRUE(out.converged);
    EXPECT_LE(out.iterations, 1) << "an exact (LU) Jacobian needs one correction";
    stepper.accept();
    // (4/h^2 M + Kt) u1 = load + M (4/h^2 u + 4/h v + a)
    const Eigen::Matrix2d keff = 4.0 / (h * h) * M + Kt;
    const Eigen::Vector2d rhs = load + M * (4.0 / (h * h) * u + 4.0 / h * v + a);
    const Eigen::Vector2d u1 = keff.partialPivLu().solve(rhs);
    const Eigen::Vector2d a1 = 4.0 / (h * h) * (u1 - u) - 4.0 / h * v - a;
    v += 0.5 * h * (a + a1);
    u = u1;
    a = a1;
    EXPECT_NEAR(stepper.u()[0], u[0], 1e-9 * u.cwiseAbs().maxCoeff() + 1e-15);
    EXPECT_NEAR(stepper.u()[1], u[1], 1e-9 * u.cwiseAbs().maxCoeff() + 1e-15);
  }
  EXPECT_GT(u.cwiseAbs().minCoeff(), 1e-4);  // both components were loaded
}

}  // namespace
}  // namespace isopound
