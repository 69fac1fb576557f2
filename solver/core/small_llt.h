// Cholesky factorisation A = L L^T of a small symmetric positive definite matrix, and its solve,
// for sizes up to 8: the stepper factors a 2D model's tangent (4 x 4 for three storeys) every
// Newton iteration of a nonlinear element, where Eigen's L1 norm, dispatch and product set-up
// cost more than the arithmetic.
//
// The factor is Eigen's LLT (3.4, SSE2 packets of two doubles) to the bit, the same operations
// in the same order. The solve is Eigen's but for one choice: it multiplies by the pivots'
// reciprocals, kept with the factor, instead of dividing by the pivots. The 2n divisions lay on
// the solve's dependency chain (a division costs ~13 cycles, a product 3); a product by a
// rounded reciprocal rounds twice, so x differs from Eigen's solve by a few ulps (relative
// 1e-15), far inside the Newton tolerance (since 2026-11-30; before, every result was Eigen's
// to the bit).
#pragma once

#include <Eigen/Dense>
#include <cmath>

#include "solver/core/sized_dispatch.h"

namespace isopound {

struct SmallLlt {
  // Up to one panel of Eigen's triangular solves (EIGEN_TUNE_TRIANGULAR_PANEL_WIDTH): beyond it
  // the solves go through matrix-vector products that round otherwise, so callers keep Eigen.
  static constexpr int kMaxSize = 8;

  // In place: the lower triangle of a (n x n, column-major, n <= kMaxSize) becomes L (the upper
  // triangle is not read and keeps its values). False at a pivot that is not > 0, as Eigen's
  // NumericalIssue (a NaN pivot passes, as there).
  // inverse_pivots (n entries) receives 1 / L_kk for solve().
  static bool factor(Eigen::MatrixXd& a, double* inverse_pivots) {
    return dispatch<Factor>(a.rows(), a.data(), inverse_pivots, nullptr);
  }

  // b <- (L L^T)^-1 b with the factor and the reciprocals of factor().
  static void solve(const Eigen::MatrixXd& l, const double* inverse_pivots, Eigen::VectorXd& b) {
    dispatch<Solve>(l.rows(), l.data(), inverse_pivots, b.data());
  }

 private:
  // The size as a template argument: the loops unroll (the operations and their order are the
  // same for every size).
  struct Factor {
    template <int n>
    static bool run(double* a, double* inverse_pivots, double*) {
      const auto at = [a](int i, int j) -> double& { return a[i + j * n]; };
#pragma GCC unroll 8
      for (int k = 0; k < n; ++k) {
        // Eigen: x = a_kk - |row k left of the diagonal|^2, summed in order (a strided row).
        double x = at(k, k);
        if (k > 0) {
          double squares = at(k, 0) * at(k, 0);
          for (int j = 1; j < k; ++j) squares += at(k, j) * at(k, j);
          x -= squares;
        }
        if (x <= 0.0) return false;
        x = std::sqrt(x);
        at(k, k) = x;
        inverse_pivots[k] = 1.0 / x;
        const int below = n - k - 1;
        if (k > 0 && below == 1) {
          // One row left: Eigen's product falls back to an inner product, dst += -1 * dot.
          double dot = at(k + 1, 0) * at(k, 0);
          for (int j = 1; j < k; ++j) dot += at(k + 1, j) * at(k, j);
          at(k + 1, k) += -1.0 * dot;
        } else if (k > 0) {
          // Eigen's column-major matrix-vector product: each row sums from 0 in column order.
          for (int i = k + 1; i < n; ++i) {
            double c = 0.0;
            for (int j = 0; j < k; ++j) c += at(i, j) * at(k, j);
            at(i, k) += -1.0 * c;
          }
        }
        for (int i = k + 1; i < n; ++i) at(i, k) /= x;
      }
      return true;
    }
  };

  struct Solve {
    template <int n>
    static bool run(const double* l, const double* inverse_pivots, double* b) {
      const auto at = [l](int i, int j) { return l[i + j * n]; };
      // L y = b, forward by columns. (Both loops unrolled whole: lane_sum's counts become
      // constants; GCC keeps the backward loop otherwise.)
#pragma GCC unroll 8
      for (int i = 0; i < n; ++i) {
        if (b[i] == 0.0) continue;
        b[i] *= inverse_pivots[i];
        for (int s = i + 1; s < n; ++s) b[s] -= b[i] * at(s, i);
      }
      // L^T x = y, backward by rows of L^T (columns of L): each row's sum as Eigen's vectorised
      // reduction of the contiguous products, two lanes.
#pragma GCC unroll 8
      for (int i = n - 1; i >= 0; --i) {
        const int count = n - 1 - i;
        if (count > 0) b[i] -= lane_sum(&l[(i + 1) + i * n], &b[i + 1], count);
        b[i] *= inverse_pivots[i];
      }
      return true;
    }
  };

  template <typename Op, typename Matrix, typename Pivots>
  static bool dispatch(Eigen::Index n, Matrix* a, Pivots* inverse_pivots, double* b) {
    // n = 0: nothing to do (callers keep Eigen beyond kMaxSize)
    return dispatch_size(n, [&]<int kN>() {
      if constexpr (kN == 0)
        return true;
      else
        return Op::template run<kN>(a, inverse_pivots, b);
    });
  }

  // sum_m p[m] q[m] in the order of Eigen's redux (LinearVectorizedTraversal, packets of 2, two
  // packet accumulators, then the lanes added, then the scalar tail).
  // Inlined into each sized solve, where the sizes are constants.
  [[gnu::always_inline]] static double lane_sum(const double* p, const double* q, int size) {
    if (size < 2) return p[0] * q[0];
    const int aligned2 = size / 4 * 4, aligned = size / 2 * 2;
    double r0 = p[0] * q[0], r1 = p[1] * q[1];
    if (aligned > 2) {
      double s0 = p[2] * q[2], s1 = p[3] * q[3];
      for (int m = 4; m < aligned2; m += 4) {
        r0 = r0 + p[m] * q[m];
        r1 = r1 + p[m + 1] * q[m + 1];
        s0 = s0 + p[m + 2] * q[m + 2];
        s1 = s1 + p[m + 3] * q[m + 3];
      }
      r0 = r0 + s0;
      r1 = r1 + s1;
      if (aligned > aligned2) {
        r0 = r0 + p[aligned2] * q[aligned2];
        r1 = r1 + p[aligned2 + 1] * q[aligned2 + 1];
      }
    }
    double sum = r0 + r1;
    for (int m = aligned; m < size; ++m) sum = sum + p[m] * q[m];
    return sum;
  }
};

}  // namespace isopound
