// A linear solve with a matrix that differs from a known one in one diagonal entry, from the
// known one's inverse (Sherman-Morrison):
//   (A + d e_j e_j^T)^-1 r = y - d y_j / (1 + d (A^-1)_jj) (A^-1 e_j),   y = A^-1 r.
// The stepper's tangent when every element acts on one DOF (a single isolator to the ground, as
// in every 2D isolated building without contacts) is K_hat + d e_j e_j^T, K_hat fixed for a step
// size: its inverse is formed once, and each Newton correction is one dense product and an
// update (no factorisation, no triangular solves and their chains of dependent operations).
// The result equals a factorisation's to round-off relative to cond(A) |x| (the products of a
// computed inverse), amplified by at most 2: the update is refused when
// 1 + d (A^-1)_jj < 1/2, a softening d that brings the matrix near singular, which the caller
// then factors as it is.
#pragma once

#include <Eigen/Dense>

#include "solver/core/compressed_rows.h"

namespace isopound {

// x = (A + d e_j e_j^T)^-1 r from A^-1 (inverse, and the same matrix as inverse_rows for the
// product). False (x unchanged) when refused.
inline bool solve_diagonal_update(const CompressedRows& inverse_rows,
                                  const Eigen::MatrixXd& inverse, int j, double d,
                                  const Eigen::VectorXd& r, Eigen::VectorXd& x) {
  const double denominator = 1.0 + d * inverse(j, j);
  if (!(denominator >= 0.5)) return false;
  inverse_rows.multiply(r, x);
  if (d == 0.0) return true;
  const double c = d * x[j] / denominator;
  const double* column = &inverse(0, j);
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] -= c * column[i];
  return true;
}

}  // namespace isopound
