// What the nonlinear static solver (von_karman.hpp, solveNonlinearStatic) needs of a model's
// geometric nonlinearity: the internal force, strain energy and tangent beyond the linear K u,
// as functions of the displacement u (6 per node, W components). Two models provide it: the von
// Karman strains (von_karman.hpp) and the co-rotational wing (corotational.hpp).
#pragma once

#include <Eigen/Core>

#include "core/structure/fe_types.hpp"

namespace orni::structure {

class StaticNonlinearity {
 public:
  virtual ~StaticNonlinearity() = default;
  /// 6 n.
  virtual int dofCount() const = 0;
  /// The internal force beyond K u at u (N, N m).
  virtual Eigen::VectorXd internalForce(const Eigen::VectorXd& u) const = 0;
  /// The strain energy beyond 1/2 u^T K u at u (J).
  virtual double energy(const Eigen::VectorXd& u) const = 0;
  /// The tangent beyond K at u (6n x 6n, symmetric).
  virtual SparseMatrix tangent(const Eigen::VectorXd& u) const = 0;
};

}  // namespace orni::structure
