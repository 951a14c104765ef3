// Lowest eigenpairs of K phi = omega^2 M phi (docs/theory.md 3.1, 3.3): Spectra
// SymGEigsShiftSolver in shift-invert mode, or a dense solver for small problems.
#pragma once

#include <string>

#include "core/structure/fe_types.hpp"

namespace orni::structure {

enum class EigenMethod {
  kAuto,                 ///< dense if 2 count + 1 > n (Spectra cannot), else shift-invert
  kSparseShiftInvert,    ///< Spectra SymGEigsShiftSolver (ShiftInvert mode)
  kDense,                ///< dense M x = mu (K - sigma M) x (GeneralizedSelfAdjointEigenSolver)
};

enum class ShiftInvertFactorization {
  kSimplicialLdlt,  ///< (K - sigma M) by Eigen::SimplicialLDLT (AMD ordering): default, faster
  kSparseLu,        ///< Spectra::SymShiftInvert (Eigen::SparseLU), the docs/theory.md 3.3 recipe
};

struct EigenSolveOptions {
  EigenMethod method = EigenMethod::kAuto;
  ShiftInvertFactorization factorization = ShiftInvertFactorization::kSimplicialLdlt;
  double shift = -1.0;        ///< sigma, (rad/s)^2; slightly negative (docs/theory.md 3.3)
  int max_iterations = 1000;  ///< Spectra maxit
  double tolerance = 1e-10;   ///< Spectra relative tolerance
  int subspace_size = 0;      ///< ncv; 0 = min(n, max(2 count + 1, 20))
};

struct EigenSolution {
  bool success = false;
  std::string message;        ///< reason when !success
  Eigen::VectorXd eigenvalues;  ///< omega^2 (rad/s)^2, ascending
  Eigen::MatrixXd vectors;      ///< n x count, M-orthonormal
};

/// The `count` lowest eigenpairs (1 <= count <= n) of the symmetric pencil (K, M), both full
/// symmetric with M positive definite. Failure (no convergence, singular K - sigma M) is
/// reported in the result, not thrown.
EigenSolution lowestEigenpairs(const SparseMatrix& stiffness, const SparseMatrix& mass, int count,
                               const EigenSolveOptions& options = {});

}  // namespace orni::structure
