// Direct sparse solves shared by the nonlinear static and transient wing (sparse_solve.hpp).
#include "core/structure/sparse_solve.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

namespace orni::structure {

bool solveSparseGeneral(const SparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd* x) {
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu(a);
  if (lu.info() != Eigen::Success) return false;
  *x = lu.solve(b);
  return lu.info() == Eigen::Success && x->allFinite();
}

bool solveSparseSymmetric(const SparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd* x) {
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(a);
  if (ldlt.info() == Eigen::Success) {
    *x = ldlt.solve(b);
    if (ldlt.info() == Eigen::Success && x->allFinite()) return true;
  }
  return solveSparseGeneral(a, b, x);
}

}  // namespace orni::structure
