// A small matrix stored by rows without its exact zeros, for the stepper's matrix-vector products
// (several a step): M, K, C and K_hat couple a level only with its neighbours, and Eigen's dense
// product spends more on zeros and on its dispatch than on the sums that matter.
//
// The products are those of Eigen (3.4) to the bit. For fewer than 128 columns, Eigen's
// column-major product sums each row's terms in column order from +0 and then adds alpha times
// that sum to the destination (alpha = 1 for y = A x and y += A x, -1 for y -= A x). Leaving
// out a zero term changes no such sum: c + (+-0) = c for c != 0, and a sum started at +0 is
// never -0. Wider matrices (Eigen sums them in blocks of columns) keep Eigen's product.
//
// Square matrices up to kMaxDense (a 2D building's M, C, K, K_hat) are kept whole, zeros
// included, the size a template argument: a zero term adds +-0 to a sum started at +0, which
// changes no sum either, while the unrolled rows cost a fraction of the indexed ones. (For a
// non-finite x, 0 x = NaN spreads to every row rather than to the rows that read it: a residual
// that is non-finite either way.)
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "solver/core/sized_dispatch.h"

namespace isopound {

class CompressedRows {
 public:
  // Storage for any rows x cols matrix, so that assign() of one that size never allocates.
  void reserve(Eigen::Index rows, Eigen::Index cols) {
    row_end_.reserve(static_cast<std::size_t>(rows));
    column_.reserve(static_cast<std::size_t>(rows * cols));
    value_.reserve(static_cast<std::size_t>(rows * cols));
    if (cols > kMaxColumns) wide_.resize(rows, cols);
    if (rows == cols && rows <= kMaxDense) dense_.reserve(static_cast<std::size_t>(rows * cols));
  }

  void assign(const Eigen::MatrixXd& a) {
    rows_ = a.rows();
    cols_ = a.cols();
    row_end_.clear();
    column_.clear();
    value_.clear();
    dense_size_ = 0;
    if (cols_ > kMaxColumns) {
      wide_ = a;
      return;
    }
    if (rows_ == cols_ && rows_ <= kMaxDense) {  // whole, by columns
      dense_size_ = static_cast<int>(rows_);
      dense_.assign(a.data(), a.data() + rows_ * cols_);
      return;
    }
    for (Eigen::Index i = 0; i < rows_; ++i) {
      for (Eigen::Index j = 0; j < cols_; ++j)
        if (a(i, j) != 0.0) {
          column_.push_back(static_cast<int>(j));
          value_.push_back(a(i, j));
        }
      row_end_.push_back(static_cast<int>(column_.size()));
    }
  }

  // y = A x
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    if (cols_ > kMaxColumns) {
      y.noalias() = wide_ * x;
      return;
    }
    each_row(x, [&](Eigen::Index i, double sum) { y[i] = sum; });
  }
  // y += A x
  void add_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    if (cols_ > kMaxColumns) {
      y.noalias() += wide_ * x;
      return;
    }
    each_row(x, [&](Eigen::Index i, double sum) { y[i] += sum; });
  }
  // y -= A x
  void subtract_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    if (cols_ > kMaxColumns) {
      y.noalias() -= wide_ * x;
      return;
    }
    each_row(x, [&](Eigen::Index i, double sum) { y[i] += -sum; });
  }

 private:
  static constexpr Eigen::Index kMaxColumns = 127;  // Eigen's unblocked product (cols < 128)

  static constexpr int kMaxDense = 8;

  // Every row's sum at once, column after column (each row still sums in column order from +0):
  // the rows go two by two through SSE2.
  template <int n, class Store>
  void dense_rows(const double* x, Store& store) const {
    const double* a = dense_.data();
    double sum[n];
    for (int i = 0; i < n; ++i) sum[i] = 0.0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) sum[i] += a[j * n + i] * x[j];
    for (int i = 0; i < n; ++i) store(i, sum[i]);
  }

  template <class Store>
  void each_row(const Eigen::VectorXd& x, Store&& store) const {
    const bool sized = dispatch_size(dense_size_, [&]<int kN>() {
      if constexpr (kN == 0)
        return false;
      else {
        dense_rows<kN>(x.data(), store);
        return true;
      }
    });
    if (sized) return;
    int k = 0;
    for (Eigen::Index i = 0; i < rows_; ++i) {
      double sum = 0.0;
      for (const int end = row_end_[i]; k < end; ++k) sum += value_[k] * x[column_[k]];
      store(i, sum);
    }
  }

  Eigen::Index rows_ = 0, cols_ = 0;
  std::vector<int> row_end_;  // row i's entries are [row_end_[i - 1], row_end_[i])
  std::vector<int> column_;
  std::vector<double> value_;
  Eigen::MatrixXd wide_;  // the matrix itself when it has more than kMaxColumns columns
  int dense_size_ = 0;    // n > 0: the matrix is n x n, whole in dense_ (by columns)
  std::vector<double> dense_;
};

}  // namespace isopound
