// Newton's block elimination of the linear DOFs (newmark.h): the same solution as factoring the
// whole matrix, checked on a chain against an independent Newmark solve and on the eccentric 3D
// building against the full factorisation; when it is used and when not.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/core/newmark.h"
#include "solver/io/model_input.h"
#include "solver/structures/job.h"
#include "test_elements.h"
#include "test_support.h"

namespace isopound {
namespace {

// A shear chain of n DOFs (DOF 0 on the ground), Rayleigh damping, the pair on DOFs 0 and 1.
Model chain(int n, bool declares) {
  Model model;
  for (int i = 0; i < n; ++i)
    model.dofs.push_back({"dof " + std::to_string(i), 0, 0, DofKind::kTranslationX});
  model.mass = Eigen::MatrixXd::Zero(n, n);
  model.stiffness = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    model.mass(i, i) = 2e5 + 1e4 * i;
    const double k = 4e8 - 1e7 * i;  // the spring below DOF i
    model.stiffness(i, i) += k;
    if (i > 0) {
      model.stiffness(i - 1, i - 1) += k;
      model.stiffness(i - 1, i) -= k;
      model.stiffness(i, i - 1) -= k;
    }
  }
  model.damping = 0.1 * model.mass + 2e-3 * model.stiffness;
  model.influence = Eigen::VectorXd::Ones(n);
  model.influence_y = Eigen::VectorXd::Zero(n);
  model.elements.push_back(
      std::make_unique<test::LinearPair>(Eigen::Matrix2d{{1e7, 3e8}, {-2e8, 2e7}}, declares));
  return model;
}

TEST(StepperBlocks, UsedOnlyWhenElementsDeclareDofsAndEnoughStayLinear) {
  Model declared = chain(12, true), undeclared = chain(12, false), small = chain(9, true);
  EXPECT_TRUE(NewmarkStepper(declared, {}).uses_block_elimination());
  EXPECT_FALSE(NewmarkStepper(declared, {1e-9, 25, false}).uses_block_elimination());
  EXPECT_FALSE(NewmarkStepper(undeclared, {}).uses_block_elimination());
  // 9 DOFs, 2 touched: 7 linear ones are too few to pay (and keep small models' arithmetic).
  EXPECT_FALSE(NewmarkStepper(small, {}).uses_block_elimination());
}

TEST(StepperBlocks, ChainMatchesAnIndependentNewmarkSolve) {
  const int n = 12;
  Model model = chain(n, true);
  NewmarkStepper stepper(model, {1e-12, 25});
  ASSERT_TRUE(stepper.uses_block_elimination());
  stepper.start(GroundAcceleration(0.0, 0.0));
  // Independent: (4/h^2 M + 2/h C + K + A) u1 = load + M (4/h^2 u + 4/h v + a) + C (2/h u + v).
  const Eigen::MatrixXd M = model.mass, C = model.damping;
  Eigen::MatrixXd Kt = model.stiffness;
  Kt.topLeftCorner<2, 2>() += Eigen::Matrix2d{{1e7, 3e8}, {-2e8, 2e7}};
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = u, a = u;
  for (int k = 0; k < 80; ++k) {
    const double h = k < 40 ? 0.01 : 0.004;  // two step sizes: two cached eliminations
    const double ag = std::sin(0.3 * k);
    const StepOutcome out = stepper.try_step(h, GroundAcceleration(ag, 0.0));
    ASSERT_TRUE(out.converged);
    EXPECT_LE(out.iterations, 1) << "an exact Jacobian needs one correction";
    stepper.accept();
    const Eigen::MatrixXd keff = 4.0 / (h * h) * M + 2.0 / h * C + Kt;
    const Eigen::VectorXd rhs = -M * Eigen::VectorXd::Constant(n, ag) +
                                M * (4.0 / (h * h) * u + 4.0 / h * v + a) + C * (2.0 / h * u + v);
    const Eigen::VectorXd u1 = keff.partialPivLu().solve(rhs);
    const Eigen::VectorXd a1 = 4.0 / (h * h) * (u1 - u) - 4.0 / h * v - a;
    v += 0.5 * h * (a + a1);
    u = u1;
    a = a1;
    // Both solve the same linear system; they differ by its round-off (condition ~1e4).
    EXPECT_LE((stepper.u() - u).cwiseAbs().maxCoeff(), 1e-10 * u.cwiseAbs().maxCoeff()) << k;
  }
  EXPECT_GT(u.cwiseAbs().minCoeff(), 1e-6);  // every DOF moved
}

// The eccentric building (16 coupled Bouc-Wen bearings on the 3 slab DOFs, 9 linear DOFs above)
// through its strong motion: every peak as with the whole matrix factored.
TEST(StepperBlocks, EccentricBuildingPeaksAsWithTheFullFactorisation) {
  ISOPOUND_REQUIRE_RECORDS();
  ModelConfig c =
      load_model_file((test::source_dir() / "configs" / "3d-eccentric-v30.yaml").string());
  c.output.histories = false;
  c.analysis.t_end = 10.0;
  const JobResult blocks = run_job(c);
  c.analysis.block_elimination = false;
  const JobResult full = run_job(c);
  const AnalysisResult &b = blocks.analysis, &f = full.analysis;
  ASSERT_EQ(b.stats.steps, f.stats.steps);
  // Newton converges on the residual whatever the direction: a wrong solve shows as iterations.
  EXPECT_EQ(b.stats.newton_iterations, f.stats.newton_iterations);
  // Round-off of two orders of elimination, carried by a hysteretic, non-chaotic response
  // (measured 2e-13 over the whole record); 1e-9 leaves room and still catches any real error.
  const auto near = [](const Peak& x, const Peak& y, const std::string& what) {
    EXPECT_NEAR(x.value, y.value, 1e-9 * std::abs(y.value) + 1e-15) << what;
  };
  for (std::size_t i = 0; i < f.displacement.size(); ++i) {
    near(b.displacement[i], f.displacement[i], "displacement " + std::to_string(i));
    near(b.absolute_acceleration[i], f.absolute_acceleration[i], "a_abs " + std::to_string(i));
  }
  for (std::size_t p = 0; p < f.probes.size(); ++p)
    near(b.probes[p].resultant, f.probes[p].resultant, blocks.model.probes[p].label);
  for (std::size_t e = 0; e < f.element_outputs.size(); ++e)
    for (std::size_t k = 0; k < f.element_outputs[e].size(); ++k)
      near(b.element_outputs[e][k], f.element_outputs[e][k], blocks.model.elements[e]->label());
  EXPECT_NEAR(b.energy.input, f.energy.input, 1e-9 * f.energy.input);
  EXPECT_GT(f.displacement[0].value, 0.1);  // the slab moved through the strong motion
}

}  // namespace
}  // namespace isopound
