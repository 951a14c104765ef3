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
  explicit SmallCholesky(int n = 0) : n_(n), L_(Eigen::MatrixXd::Zero(n, n)) {}

  int size() const { return n_; }

  /// Factor A = L L^T from the lower triangle of the n x n matrix `A` (column-major). False
  /// (and the factor unusable) when A is not numerically positive definite.
  template <class Derived>
  bool factor(const Eigen::MatrixBase<Derived>& A) {
    const int n = n_;
    double* __restrict L = L_.data();
    for (int j = 0; j < n; ++j) {
      double d = A(j, j);
      for (int k = 0; k < j; ++k) d -= L[j + k * n] * L[j + k * n];
      if (!(d > 0.0)) return false;
      const double ljj = std::sqrt(d);
      L[j + j * n] = ljj;
      const double inv = 1.0 / ljj;
      for (int i = j + 1; i < n; ++i) L[i + j * n] = A(i, j);
      for (int k = 0; k < j; ++k) {
        const double ljk = L[j + k * n];
        const double* __restrict Lk = L + k * n;
        double* __restrict Lj = L + j * n;
        for (int i = j + 1; i < n; ++i) Lj[i] -= Lk[i] * ljk;
      }
      for (int i = j + 1; i < n; ++i) L[i + j * n] *= inv;
    }
    return true;
  }

  /// x = A^{-1} x in place (n values).
  void solveInPlace(double* x) const {
    const int n = n_;
    const double* L = L_.data();
    for (int j = 0; j < n; ++j) {  // L y = b, column-oriented
      const double yj = x[j] / L[j + j * n];
      x[j] = yj;
      const double* Lj = L + j * n;
      for (int i = j + 1; i < n; ++i) x[i] -= Lj[i] * yj;
    }
    for (int j = n - 1; j >= 0; --j) {  // L^T x = y, row j of L^T is column j of L
      const double* Lj = L + j * n;
      double s = x[j];
      for (int i = j + 1; i < n; ++i) s -= Lj[i] * x[i];
      x[j] = s / L[j + j * n];
    }
  }
  void solveInPlace(Eigen::VectorXd& x) const { solveInPlace(x.data()); }

 private:
  int n_;
  Eigen::MatrixXd L_;
};

}  // namespace orni
