// Cholesky factorisation and solves of the small SPD systems of the right-hand side (the modal
// mass matrix of the wing, M x M, or the free-flight mass matrix, (3 + M) x (3 + M); M ~ 12).
// Plain loops on a preallocated factor: at these sizes Eigen's dynamic-size LLT spends more on
// its blocking (one GEMV per column) and triangular-solve dispatch than on the arithmetic. No
// allocation after construction.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace orni {

class SmallCholesky {
 public:
  explicit SmallCholesky(int n = 0)
      : n_(n), L_(Eigen::MatrixXd::Zero(n, n)), inv_diag_(Eigen::VectorXd::Zero(n)) {}

  int size() const { return n_; }

  /// Factor A = L L^T from the lower triangle of the n x n matrix `A` (column-major). False
  /// (and the factor unusable) when A is not numerically positive definite. Right-looking: after
  /// each pivot the trailing columns are updated independently (short dependency chains; the
  /// left-looking form waits on a dot product per entry).
  template <class Derived>
  bool factor(const Eigen::MatrixBase<Derived>& A) {
    const int n = n_;
    double* __restrict L = L_.data();
    for (int j = 0; j < n; ++j)
      for (int i = j; i < n; ++i) L[i + j * n] = A(i, j);
    for (int j = 0; j < n; ++j) {
      double* __restrict Lj = L + j * n;
      const double d = Lj[j];
      if (!(d > 0.0)) return false;
      const double inv = 1.0 / std::sqrt(d);
      inv_diag_[j] = inv;
      Lj[j] = d * inv;  // sqrt(d)
      for (int i = j + 1; i < n; ++i) Lj[i] *= inv;
      for (int k = j + 1; k < n; ++k) {
        const double lkj = Lj[k];
        double* __restrict Lk = L + k * n;
        for (int i = k; i < n; ++i) Lk[i] -= Lj[i] * lkj;
      }
    }
    return true;
  }

  /// x = A^{-1} x in place (n values).
  void solveInPlace(double* x) const {
    const int n = n_;
    const double* __restrict L = L_.data();
    const double* __restrict inv = inv_diag_.data();
    for (int j = 0; j < n; ++j) {  // L y = b, column sweep
      const double yj = x[j] * inv[j];
      x[j] = yj;
      const double* Lj = L + j * n;
      for (int i = j + 1; i < n; ++i) x[i] -= Lj[i] * yj;
    }
    for (int j = n - 1; j >= 0; --j) {  // L^T x = y, row j of L^T is column j of L
      const double* Lj = L + j * n;
      double s = x[j];
      for (int i = j + 1; i < n; ++i) s -= Lj[i] * x[i];
      x[j] = s * inv[j];
    }
  }
  void solveInPlace(Eigen::VectorXd& x) const { solveInPlace(x.data()); }

 private:
  int n_;
  Eigen::MatrixXd L_;
  Eigen::VectorXd inv_diag_;
};

}  // namespace orni
