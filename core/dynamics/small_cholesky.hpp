// Cholesky factorisation and solves of the small SPD systems of the right-hand side (the modal
// mass matrix of the wing, M x M, or the free-flight mass matrix, (3 + M) x (3 + M); M ~ 24).
// Square-root-free form A = L D L^T (unit lower L, diagonal D > 0) from the lower triangle (a
// matrix or a packed triangle), right-looking: a pivot costs one division and no square root (the
// pivots are a serial chain). Plain loops on a preallocated factor: at these sizes Eigen's
// dynamic-size LLT spends more on its blocking (one GEMV per column) and triangular-solve
// dispatch than on the arithmetic. The factor is stored column-major with the column length
// padded to a multiple of 4 (one AVX2 register) so that every column update is whole vectors
// from an aligned row (the rows above the diagonal that this also updates are scratch, never
// read), and the pivots go in blocks of 4: one sweep over each later column applies the block's
// four updates, in the order of the pivot-by-pivot loop (same values, a quarter of the loop
// overhead). The back substitution runs by rows of L, so its multiply-adds are independent
// instead of one dependent chain. No allocation after construction.
#pragma once

#include <algorithm>

#include <Eigen/Core>

namespace orni {

class SmallCholesky {
 public:
  explicit SmallCholesky(int n = 0)
      : n_(n),
        ld_((n + kLanes - 1) / kLanes * kLanes),
        L_(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(ld_) * n)),
        inv_d_(Eigen::VectorXd::Zero(n)) {}

  int size() const { return n_; }
  /// Entries of a packed lower triangle: column j holds rows j .. n-1, columns one after another.
  static Eigen::Index packedSize(int n) { return static_cast<Eigen::Index>(n) * (n + 1) / 2; }

  /// Factor from the lower triangle of the n x n matrix `A`. False (and the factor unusable) when
  /// A is not numerically positive definite.
  template <class Derived>
  bool factor(const Eigen::MatrixBase<Derived>& A) {
    for (int j = 0; j < n_; ++j) {
      double* __restrict Lj = column(j);
      clearAbove(j, Lj);
      for (int i = j; i < n_; ++i) Lj[i] = A(i, j);
    }
    return factorInPlace();
  }
  /// Factor from a packed lower triangle (packedSize(n) values, layout above).
  bool factorPacked(const double* packed) {
    for (int j = 0; j < n_; ++j) {
      double* __restrict Lj = column(j);
      clearAbove(j, Lj);
      for (int i = j; i < n_; ++i) Lj[i] = *packed++;
    }
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
    // L^T x = z by rows of L (x_i final, then its term leaves every x_j, j < i): independent
    // updates instead of one dependent chain of n(n-1)/2 multiply-adds.
    for (int i = n - 1; i > 0; --i) {
      const double xi = x[i];
      const double* __restrict Li = L_.data() + i;  // row i: L(i, j) = Li[j ld]
      for (int j = 0; j < i; ++j) x[j] -= Li[static_cast<Eigen::Index>(j) * ld_] * xi;
    }
  }
  void solveInPlace(Eigen::VectorXd& x) const { solveInPlace(x.data()); }

 private:
  static constexpr int kLanes = 4;
  // Column j of the factor, indexed by the row i (rows i >= j are the lower triangle).
  const double* column(int j) const { return L_.data() + static_cast<Eigen::Index>(j) * ld_; }
  double* column(int j) { return L_.data() + static_cast<Eigen::Index>(j) * ld_; }

  // The rows of column j above the diagonal that the padded updates touch start from zero in
  // every factorisation (they are never read, but stay small finite numbers).
  static void clearAbove(int j, double* Lj) {
    for (int i = j & ~(kLanes - 1); i < j; ++i) Lj[i] = 0.0;  // at most kLanes - 1 entries
  }

  // Pivots in blocks of kLanes: the block's own columns are updated pivot by pivot, then every
  // later column gets the block's kLanes updates in one sweep (a rank-kLanes update), in the same
  // order per entry as the pivot-by-pivot loop, so the same values; the block's columns are
  // scaled to l_ij last (the updates use a_ij = l_ij d_j).
  bool factorInPlace() {
    const int n = n_, ld = ld_;
    for (int j0 = 0; j0 < n; j0 += kLanes) {
      const int j1 = std::min(j0 + kLanes, n);
      for (int j = j0; j < j1; ++j) {
        const double* __restrict Lj = column(j);
        const double d = Lj[j];
        if (!(d > 0.0)) return false;
        const double inv = 1.0 / d;
        inv_d_[j] = inv;
        for (int k = j + 1; k < j1; ++k) {
          const double lkj = Lj[k] * inv;
          double* __restrict Lk = column(k);
#pragma GCC ivdep
          for (int i = j0; i < ld; ++i) Lk[i] -= Lj[i] * lkj;
        }
      }
      if (j1 < n) {  // full block (only the last one can be shorter, and it has no later columns)
        const double* __restrict L0 = column(j0);
        const double* __restrict L1 = column(j0 + 1);
        const double* __restrict L2 = column(j0 + 2);
        const double* __restrict L3 = column(j0 + 3);
        for (int k = j1; k < n; ++k) {
          const double w0 = L0[k] * inv_d_[j0], w1 = L1[k] * inv_d_[j0 + 1];
          const double w2 = L2[k] * inv_d_[j0 + 2], w3 = L3[k] * inv_d_[j0 + 3];
          double* __restrict Lk = column(k);
#pragma GCC ivdep
          for (int i = k & ~(kLanes - 1); i < ld; ++i) {
            double v = Lk[i];
            v -= L0[i] * w0;
            v -= L1[i] * w1;
            v -= L2[i] * w2;
            v -= L3[i] * w3;
            Lk[i] = v;
          }
        }
      }
      for (int j = j0; j < j1; ++j) {  // l_ij (d_j is in inv_d_)
        double* __restrict Lj = column(j);
        const double inv = inv_d_[j];
#pragma GCC ivdep
        for (int i = j0; i < ld; ++i) Lj[i] *= inv;
      }
    }
    return true;
  }

  int n_;
  int ld_;                 // column stride: n rounded up to a multiple of kLanes
  Eigen::VectorXd L_;      // column-major, d_j on the diagonal, l_ij below it
  Eigen::VectorXd inv_d_;  // 1 / d_j
};

}  // namespace orni
