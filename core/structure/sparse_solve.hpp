// Direct solves of the sparse FE matrices of the nonlinear wing (the static Newton of
// von_karman.cpp and the transient Newton of wing_transient.cpp share them).
#pragma once

#include <Eigen/Core>

#include "core/structure/fe_types.hpp"

namespace orni::structure {

/// Solves a x = b for a symmetric a: LDL^T with AMD ordering, and LU when LDL^T fails or
/// gives a non-finite answer (an indefinite tangent). False when both fail.
bool solveSparseSymmetric(const SparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd* x);

/// Solves a x = b by sparse LU (COLAMD ordering): any square a. False when singular.
bool solveSparseGeneral(const SparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd* x);

}  // namespace orni::structure
