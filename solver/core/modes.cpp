// Undamped modes by Eigen's generalized self-adjoint solver (Cholesky of M).
// Shapes are sign-normalised so that the largest entry is positive.
#include "solver/core/modes.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace isopound {

Modes compute_modes(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                    const Eigen::VectorXd& influence) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
  if (solver.info() != Eigen::Success)
    throw std::invalid_argument("modes: mass matrix is not positive definite");
  const Eigen::VectorXd& lambda = solver.eigenvalues();
  if (lambda.minCoeff() <= 0)
    throw std::invalid_argument("modes: stiffness is not positive definite (a mechanism)");
  Modes modes;
  const int n = static_cast<int>(lambda.size());
  modes.omega = lambda.cwiseSqrt();
  modes.period = (2.0 * std::numbers::pi) * modes.omega.cwiseInverse();
  modes.shape = solver.eigenvectors();
  for (int j = 0; j < n; ++j) {
    Eigen::Index imax;
    modes.shape.col(j).cwiseAbs().maxCoeff(&imax);
    if (modes.shape(imax, j) < 0) modes.shape.col(j) *= -1.0;
  }
  const double total = influence.dot(M * influence);
  modes.participation = modes.shape.transpose() * (M * influence);
  modes.effective_mass_ratio = modes.participation.cwiseAbs2() / total;
  return modes;
}

}  // namespace isopound
