// Spectra shift-invert generalised eigen-solution (docs/theory.md 3.3).
#include "core/structure/modal_solver.hpp"
#include "core/model/invariant.hpp"
#include "core/structure/product_blocking.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>

namespace orni::structure {
namespace {

// (K - sigma M)^{-1} x with Eigen::SimplicialLDLT: the operator interface SymGEigsShiftSolver
// needs (Scalar, rows, cols, set_shift, perform_op). Keeps references: K and M outlive it.
class LdltShiftInvert {
 public:
  using Scalar = double;

  LdltShiftInvert(const SparseMatrix& k, const SparseMatrix& m) : k_(k), m_(m) {}

  Eigen::Index rows() const { return k_.rows(); }
  Eigen::Index cols() const { return k_.cols(); }

  void set_shift(double sigma) {
    const SparseMatrix shifted = k_ - sigma * m_;
    solver_.compute(shifted);
    if (solver_.info() != Eigen::Success)
      throw std::invalid_argument("LdltShiftInvert: factorisation of K - sigma M failed");
  }

  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, k_.rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, k_.rows());
    y.noalias() = solver_.solve(x);
  }

 private:
  const SparseMatrix& k_;
  const SparseMatrix& m_;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> solver_;
};

template <typename OpType>
EigenSolution runSpectra(OpType& op, const SparseMatrix& mass, int count,
                         const EigenSolveOptions& o) {
  EigenSolution out;
  const int n = static_cast<int>(mass.rows());
  const int ncv = o.subspace_size > 0 ? std::min(n, o.subspace_size)
                                      : std::min(n, std::max(2 * count + 1, 20));
  using BOpType = Spectra::SparseSymMatProd<double>;
  BOpType bop(mass);
  try {
    Spectra::SymGEigsShiftSolver<OpType, BOpType, Spectra::GEigsMode::ShiftInvert> es(
        op, bop, count, ncv, o.shift);
    es.init();
    const Eigen::Index converged = es.compute(Spectra::SortRule::LargestMagn, o.max_iterations,
                                              o.tolerance, Spectra::SortRule::SmallestAlge);
    if (es.info() != Spectra::CompInfo::Successful || converged < count) {
      out.message = "Spectra: " + std::to_string(converged) + " of " + std::to_string(count) +
                    " eigenpairs converged";
      return out;
    }
    out.eigenvalues = es.eigenvalues();
    out.vectors = es.eigenvectors();
  } catch (const std::exception& e) {
    rethrowIfProgrammingError(e);  // core/model/invariant.hpp: a misuse of Spectra is a bug
    out.message = std::string("Spectra: ") + e.what();
    return out;
  }
  out.success = true;
  return out;
}

// Dense shift-invert form: M x = mu (K - sigma M) x with mu = 1 / (lambda - sigma). Factorising
// K - sigma M instead of M keeps the lowest modes accurate when M is badly conditioned (the
// skin's rotary inertia makes cond(M) ~ 1e12; Cholesky of M then loses ~1e-8 on lambda).
EigenSolution denseSolve(const SparseMatrix& stiffness, const SparseMatrix& mass, int count,
                         double sigma) {
  EigenSolution out;
  const Eigen::MatrixXd m = Eigen::MatrixXd(mass);
  const Eigen::MatrixXd shifted = Eigen::MatrixXd(stiffness) - sigma * m;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(m, shifted);
  if (es.info() != Eigen::Success) {
    out.message = "dense generalised eigen-solver failed (K - sigma M not positive definite?)";
    return out;
  }
  const Eigen::Index n = m.rows();
  out.eigenvalues.resize(count);
  out.vectors.resize(n, count);
  for (int j = 0; j < count; ++j) {
    const double mu = es.eigenvalues()(n - 1 - j);  // largest mu = lowest lambda
    if (!(mu > 0.0)) {
      out.message = "dense generalised eigen-solver: fewer than count finite eigenvalues";
      return out;
    }
    out.eigenvalues(j) = sigma + 1.0 / mu;
    out.vectors.col(j) = es.eigenvectors().col(n - 1 - j) / std::sqrt(mu);  // x^T M x = mu
  }
  out.success = true;
  return out;
}

// Deterministic sign: the largest-magnitude component of every vector is positive.
void normaliseSigns(Eigen::MatrixXd& vectors) {
  for (Eigen::Index j = 0; j < vectors.cols(); ++j) {
    Eigen::Index imax = 0;
    vectors.col(j).cwiseAbs().maxCoeff(&imax);
    if (vectors(imax, j) < 0.0) vectors.col(j) *= -1.0;
  }
}

EigenSolution dispatch(const SparseMatrix& stiffness, const SparseMatrix& mass, int count,
                       const EigenSolveOptions& options) {
  const int n = static_cast<int>(stiffness.rows());
  EigenMethod method = options.method;
  if (method == EigenMethod::kAuto)
    method = 2 * count + 1 > n ? EigenMethod::kDense : EigenMethod::kSparseShiftInvert;
  if (method == EigenMethod::kDense || count >= n)
    return denseSolve(stiffness, mass, count, options.shift);
  if (options.factorization == ShiftInvertFactorization::kSparseLu) {
    using OpType = Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse>;
    OpType op(stiffness, mass);
    return runSpectra(op, mass, count, options);
  }
  LdltShiftInvert op(stiffness, mass);
  return runSpectra(op, mass, count, options);
}

}  // namespace

EigenSolution lowestEigenpairs(const SparseMatrix& stiffness, const SparseMatrix& mass, int count,
                               const EigenSolveOptions& options) {
  planProductsWithFixedCacheSizes();  // the same bits on every CPU (docs/theory.md 3.7)
  const int n = static_cast<int>(stiffness.rows());
  if (stiffness.cols() != n || mass.rows() != n || mass.cols() != n)
    throw std::invalid_argument("lowestEigenpairs: K and M must be square of the same size");
  if (count < 1 || count > n)
    throw std::invalid_argument("lowestEigenpairs: expected 1 <= count <= " + std::to_string(n) +
                                ", got " + std::to_string(count));
  EigenSolution out = dispatch(stiffness, mass, count, options);
  if (out.success) normaliseSigns(out.vectors);
  return out;
}

}  // namespace orni::structure
