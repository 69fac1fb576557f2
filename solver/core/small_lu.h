// LU factorisation with partial pivoting of a small dense matrix, and its solve: the operations of
// Eigen's PartialPivLU (3.4) for sizes up to 16, in the same order, so that every result is the
// same to the bit; without its dispatch, norm and permutation set-up, which cost more than the
// arithmetic at the sizes the stepper factors every Newton iteration (3 x 3 for one slab).
#pragma once

#include <Eigen/Dense>
#include <cmath>

namespace isopound {

struct SmallLu {
  // Eigen factors matrices up to this size unblocked (partial_lu_impl::UnBlockedBound); beyond it
  // its blocked algorithm rounds differently, so callers keep Eigen there.
  static constexpr int kMaxSize = 16;

  // In place: a (n x n, column-major, n <= kMaxSize) becomes L\U (L unit lower) with P a = L U,
  // P the row swaps k <-> transposition[k] applied for k = 0, 1, ... A zero pivot is kept (as
  // Eigen does): the solve then gives inf or NaN, which the stepper treats as a failed step.
  static void factor(Eigen::MatrixXd& a, int* transposition) {
    const int n = static_cast<int>(a.rows());
    for (int k = 0; k < n; ++k) {
      // The first row of the largest |a(i, k)|, i >= k (a NaN never wins, as in Eigen's visitor).
      int pivot = k;
      double biggest = std::abs(a(k, k));
      for (int i = k + 1; i < n; ++i)
        if (std::abs(a(i, k)) > biggest) {
          biggest = std::abs(a(i, k));
          pivot = i;
        }
      transposition[k] = pivot;
      if (biggest != 0.0) {
        if (pivot != k)
          for (int j = 0; j < n; ++j) std::swap(a(k, j), a(pivot, j));
        const double diagonal = a(k, k);
        for (int i = k + 1; i < n; ++i) a(i, k) /= diagonal;
      }
      for (int j = k + 1; j < n; ++j) {
        const double u = a(k, j);
        for (int i = k + 1; i < n; ++i) a(i, j) -= u * a(i, k);
      }
    }
  }

  // b <- (P^-1 L U)^-1 b with the factors of factor(). Eigen's triangular solves work in panels
  // of 8 columns: column updates inside a panel, then one product for the rows beyond it.
  static void solve(const Eigen::MatrixXd& lu, const int* transposition, Eigen::VectorXd& b) {
    const int n = static_cast<int>(lu.rows());
    constexpr int kPanel = 8;  // EIGEN_TUNE_TRIANGULAR_PANEL_WIDTH
    for (int k = 0; k < n; ++k) std::swap(b[k], b[transposition[k]]);
    // L y = P b, forward.
    for (int start = 0; start < n; start += kPanel) {
      const int end = start + kPanel < n ? start + kPanel : n;
      for (int i = start; i < end; ++i) {
        if (b[i] == 0.0) continue;
        for (int s = i + 1; s < end; ++s) b[s] -= b[i] * lu(s, i);
      }
      for (int s = end; s < n; ++s) {
        double c = 0.0;
        for (int j = start; j < end; ++j) c += lu(s, j) * b[j];
        b[s] += -c;
      }
    }
    // U x = y, backward.
    for (int stop = n; stop > 0; stop -= kPanel) {
      const int start = stop - kPanel > 0 ? stop - kPanel : 0;
      for (int i = stop - 1; i >= start; --i) {
        if (b[i] == 0.0) continue;
        b[i] /= lu(i, i);
        for (int s = start; s < i; ++s) b[s] -= b[i] * lu(s, i);
      }
      for (int s = 0; s < start; ++s) {
        double c = 0.0;
        for (int j = start; j < stop; ++j) c += lu(s, j) * b[j];
        b[s] += -c;
      }
    }
  }
};

}  // namespace isopound
