// Cholesky factorisation and solves of the small SPD systems of the right-hand side (the modal
// mass matrix of the wing, M x M, or the free-flight mass matrix, (3 + M) x (3 + M); M ~ 12).
// Square-root-free form A = L D L^T (unit lower L, diagonal D > 0) on the packed lower triangle,
// right-looking: a pivot costs one division and no square root (the pivots are a serial chain),
// and after each pivot the trailing columns are updated independently. Plain loops on a
// preallocated factor: at these sizes Eigen's dynamic-size LLT spends more on its blocking (one
// GEMV per column) and triangular-solve dispatch than on the arithmetic. No allocation after
// construction.
#pragma once

#include <Eigen/Core>

namespace orni {

class SmallCholesky {
 public:
  explicit SmallCholesky(int n = 0)
      : n_(n),
        L_(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n) * (n + 1) / 2)),
        inv_d_(Eigen::VectorXd::Zero(n)) {}

  int size() const { return n_; }
  /// Entries of a packed lower triangle: column j holds rows j .. n-1, columns one after another.
  static Eigen::Index packedSize(int n) { return static_cast<Eigen::Index>(n) * (n + 1) / 2; }

  /// Factor from the lower triangle of the n x n matrix `A`. False (and the factor unusable) when
  /// A is not numerically positive definite.
  template <class Derived>
  bool factor(const Eigen::MatrixBase<Derived>& A) {
    double* __restrict L = L_.data();
    for (int j = 0; j < n_; ++j)
      for (int i = j; i < n_; ++i) *L++ = A(i, j);
    return factorInPlace();
  }
  /// Factor from a packed lower triangle (packedSize(n) values, layout above).
  bool factorPacked(const double* packed) {
    double* __restrict L = L_.data();
    for (Eigen::Index k = 0; k < L_.size(); ++k) L[k] = packed[k];
    return factorInPlace();
  }

  /// x = A^{-1} x in place (n values).
  void solveInPlace(double* x) const {
    const int n = n_;
    const double* __restrict inv_d = inv_d_.data();
    for (int j = 0; j < n; ++j) {  // L y = b, column sweep
      const double yj = x[j];
      const double* Lj = column(j);
      for (int i = j + 1; i < n; ++i) x[i] -= Lj[i] * yj;
    }
    for (int j = 0; j < n; ++j) x[j] *= inv_d[j];  // D z = y
    for (int j = n - 1; j >= 0; --j) {  // L^T x = z, row j of L^T is column j of L
      const double* Lj = column(j);
      double s = x[j];
      for (int i = j + 1; i < n; ++i) s -= Lj[i] * x[i];
      x[j] = s;
    }
  }
  void solveInPlace(Eigen::VectorXd& x) const { solveInPlace(x.data()); }

 private:
  // Column j of the packed factor, indexed by the row i >= j.
  const double* column(int j) const { return L_.data() + j * n_ - j * (j + 1) / 2; }
  double* column(int j) { return L_.data() + j * n_ - j * (j + 1) / 2; }

  bool factorInPlace() {
    const int n = n_;
    for (int j = 0; j < n; ++j) {
      double* __restrict Lj = column(j);
      const double d = Lj[j];
      if (!(d > 0.0)) return false;
      const double inv = 1.0 / d;
      inv_d_[j] = inv;
      // Trailing update with l_kj = a_kj / d_j while column j still holds a_ij = l_ij d_j.
      for (int k = j + 1; k < n; ++k) {
        const double lkj = Lj[k] * inv;
        double* __restrict Lk = column(k);
        for (int i = k; i < n; ++i) Lk[i] -= Lj[i] * lkj;
      }
      for (int i = j + 1; i < n; ++i) Lj[i] *= inv;  // l_ij
    }
    return true;
  }

  int n_;
  Eigen::VectorXd L_;      // packed: d_j on the diagonal, l_ij below it
  Eigen::VectorXd inv_d_;  // 1 / d_j
};

}  // namespace orni
