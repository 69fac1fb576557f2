// The stepper's own small linear algebra (SmallLu, SmallLlt, CompressedRows) must give Eigen's
// results to the bit: the analyses' results were checked against Eigen's, and a cheaper product or
// solve must not move them. Two documented exceptions, checked to their rounding: SmallLlt's solve
// multiplies by reciprocals (small_llt.h), and a diagonal update is solved from an inverse
// (diagonal_update.h). Random matrices of every size the shortcuts take, with the zeros, ties and
// row swaps that decide the order of the operations.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "solver/core/compressed_rows.h"
#include "solver/core/diagonal_update.h"
#include "solver/core/small_llt.h"
#include "solver/core/small_lu.h"

namespace isopound {
namespace {

// A matrix with a share of exact zeros (blocks of a stiffness matrix) and repeated magnitudes
// (ties in the pivot search), scaled over decades so that rounding differs between orders.
Eigen::MatrixXd random_matrix(std::mt19937& rng, int rows, int cols, double zero_share) {
  std::uniform_real_distribution<double> value(-1.0, 1.0), share(0.0, 1.0);
  std::uniform_int_distribution<int> decade(-3, 3);
  Eigen::MatrixXd a(rows, cols);
  for (int j = 0; j < cols; ++j)
    for (int i = 0; i < rows; ++i)
      a(i, j) = share(rng) < zero_share ? 0.0 : value(rng) * std::pow(10.0, decade(rng));
  if (rows > 2 && cols > 1) a(1, 0) = -a(0, 0);  // a tie for the first pivot
  return a;
}

Eigen::VectorXd random_vector(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = value(rng) * (1.0 + i);
  return x;
}

void expect_same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (Eigen::Index i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << what << ", entry " << i;
}

TEST(SmallLu, SolvesAsEigensPartialPivLuBitForBit) {
  std::mt19937 rng(5);
  for (int n = 1; n <= SmallLu::kMaxSize; ++n)
    for (int trial = 0; trial < 20; ++trial) {
      // Mostly dense, some with many zeros (a diaphragm's 3 x 3 blocks), all nonsingular.
      Eigen::MatrixXd a = random_matrix(rng, n, n, trial % 4 == 0 ? 0.5 : 0.1);
      a.diagonal().array() += 0.25;  // keeps the random ones away from singular
      const Eigen::VectorXd b = random_vector(rng, n);
      const Eigen::VectorXd eigen = Eigen::PartialPivLU<Eigen::MatrixXd>(a).solve(b);
      std::vector<int> pivots(n);
      Eigen::MatrixXd lu = a;
      SmallLu::factor(lu, pivots.data());
      Eigen::VectorXd x = b;
      SmallLu::solve(lu, pivots.data(), x);
      expect_same_bits(x, eigen, "n " + std::to_string(n) + ", trial " + std::to_string(trial));
      // And it is a solution (the comparison above would pass for two equal wrong answers).
      EXPECT_LE((a * x - b).norm(), 1e-9 * (a.norm() * x.norm() + b.norm()));
    }
}

// Symmetric positive definite matrices as the stepper's K_hat: a mass-like diagonal over decades
// plus stiffness couplings (B B^T), some entries exactly zero; the factor must be Eigen's LLT to
// the bit, and a matrix that is not positive definite must fail as there. The solve multiplies by
// the pivots' reciprocals (one more rounding per pivot): within a few ulps of Eigen's solve,
// measured against the condition number, and a solution.
TEST(SmallLlt, FactorsAsEigensLltBitForBitAndSolvesToItsRounding) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> decade(-2, 6);
  for (int n = 1; n <= SmallLlt::kMaxSize; ++n)
    for (int trial = 0; trial < 200; ++trial) {
      const Eigen::MatrixXd b = random_matrix(rng, n, n, trial % 4 == 0 ? 0.5 : 0.1);
      Eigen::MatrixXd a = b * b.transpose();
      for (int i = 0; i < n; ++i) a(i, i) += std::pow(10.0, decade(rng));
      const Eigen::VectorXd rhs = random_vector(rng, n);
      const std::string what = "n " + std::to_string(n) + ", trial " + std::to_string(trial);
      const Eigen::LLT<Eigen::MatrixXd> eigen(a);
      ASSERT_EQ(eigen.info(), Eigen::Success) << what;
      Eigen::MatrixXd l = a;
      double inverse_pivots[SmallLlt::kMaxSize];
      ASSERT_TRUE(SmallLlt::factor(l, inverse_pivots)) << what;
      const Eigen::MatrixXd eigen_l = eigen.matrixL();
      for (int j = 0; j < n; ++j)
        for (int i = j; i < n; ++i) EXPECT_EQ(l(i, j), eigen_l(i, j)) << what << ", L " << i << j;
      Eigen::VectorXd x = rhs;
      SmallLlt::solve(l, inverse_pivots, x);
      // Both solves' errors are bounded by ~n eps cond(A) |x| (backward stability): their
      // difference too. 2n extra roundings of 0.5 ulp each, amplified at most by cond(A).
      const Eigen::VectorXd reference = eigen.solve(rhs);
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a);
      const double condition = svd.singularValues()(0) / svd.singularValues()(n - 1);
      EXPECT_LE((x - reference).norm(),
                4.0 * n * std::numeric_limits<double>::epsilon() * condition * reference.norm())
          << what;
      EXPECT_LE((a * x - rhs).norm(), 1e-9 * (a.norm() * x.norm() + rhs.norm())) << what;
      // Not positive definite (a negative pivot at the last row): both refuse.
      Eigen::MatrixXd indefinite = a;
      indefinite(n - 1, n - 1) = -1.0;
      EXPECT_NE(Eigen::LLT<Eigen::MatrixXd>(indefinite).info(), Eigen::Success) << what;
      EXPECT_FALSE(SmallLlt::factor(indefinite, inverse_pivots)) << what;
    }
}

// A matrix that differs from A in one diagonal entry (the stepper's tangent with a single
// isolator to the ground), solved from A's inverse: as the updated matrix's own Cholesky
// factorisation solves it, to the rounding of both (each within ~n eps cond |x|, the update's
// amplification bounded by 2); a softening d that brings the matrix near singular is refused.
TEST(DiagonalUpdate, SolvesAsTheUpdatedMatrixsOwnFactor) {
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> decade(-2, 6);
  std::uniform_real_distribution<double> share(-0.7, 3.0);
  int refused = 0, solved = 0;
  for (int n = 1; n <= SmallLlt::kMaxSize; ++n)
    for (int trial = 0; trial < 200; ++trial) {
      const Eigen::MatrixXd b = random_matrix(rng, n, n, trial % 4 == 0 ? 0.5 : 0.1);
      Eigen::MatrixXd a = b * b.transpose();
      for (int i = 0; i < n; ++i) a(i, i) += std::pow(10.0, decade(rng));
      const int j = trial % n;
      const Eigen::MatrixXd inverse = a.inverse();
      CompressedRows inverse_rows;
      inverse_rows.assign(inverse);
      // d from -0.7 to 3 times 1 / (A^-1)_jj: still positive definite (above -1), refused below
      // -0.5; and d = 0 (A itself) now and then.
      const double d = trial % 10 == 0 ? 0.0 : share(rng) / inverse(j, j);
      Eigen::MatrixXd updated = a;
      updated(j, j) += d;
      const Eigen::VectorXd rhs = random_vector(rng, n);
      const std::string what = "n " + std::to_string(n) + ", trial " + std::to_string(trial);
      Eigen::VectorXd x = Eigen::VectorXd::Constant(n, 7.0);
      if (!solve_diagonal_update(inverse_rows, inverse, j, d, rhs, x)) {
        ++refused;
        EXPECT_LT(1.0 + d * inverse(j, j), 0.5) << what;
        EXPECT_EQ(x, Eigen::VectorXd::Constant(n, 7.0)) << what;
        continue;
      }
      ++solved;
      const Eigen::VectorXd reference = Eigen::LLT<Eigen::MatrixXd>(updated).solve(rhs);
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd_a(a), svd_u(updated);
      const double condition = std::max(svd_a.singularValues()(0) / svd_a.singularValues()(n - 1),
                                        svd_u.singularValues()(0) / svd_u.singularValues()(n - 1));
      EXPECT_LE((x - reference).norm(),
                16.0 * n * std::numeric_limits<double>::epsilon() * condition * reference.norm())
          << what;
    }
  EXPECT_GT(refused, 0);
  EXPECT_GT(solved, 1000);
}

TEST(CompressedRows, ProductsAsEigensBitForBit) {
  std::mt19937 rng(9);
  // Up to Eigen's unblocked width (127 columns), and one beyond, where Eigen's product is kept.
  // Square up to 8 (kept whole, zeros included) as well as the rest.
  for (const int cols : {1, 2, 3, 4, 5, 6, 8, 9, 12, 31, 127, 130})
    for (const int rows : {1, 3, 4, 6, 8, 12}) {
      const Eigen::MatrixXd a = random_matrix(rng, rows, cols, 0.6);
      const Eigen::VectorXd x = random_vector(rng, cols), y0 = random_vector(rng, rows);
      CompressedRows rows_of_a;
      rows_of_a.reserve(rows, cols);
      rows_of_a.assign(a);
      const std::string what = std::to_string(rows) + " x " + std::to_string(cols);
      Eigen::VectorXd eigen(rows), ours(rows);
      eigen.noalias() = a * x;
      rows_of_a.multiply(x, ours);
      expect_same_bits(ours, eigen, what + " y = A x");
      eigen = y0;
      eigen.noalias() += a * x;
      ours = y0;
      rows_of_a.add_product(x, ours);
      expect_same_bits(ours, eigen, what + " y += A x");
      eigen = y0;
      eigen.noalias() -= a * x;
      ours = y0;
      rows_of_a.subtract_product(x, ours);
      expect_same_bits(ours, eigen, what + " y -= A x");
    }
}

}  // namespace
}  // namespace isopound
