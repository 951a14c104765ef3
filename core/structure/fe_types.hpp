// Common types of the wing finite-element model (docs/theory.md 2.6): 6 DOF per node
// (u, v, w, theta_x, theta_y, theta_z) in W components, global DOF = 6 * node + local.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>

namespace orni::structure {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Mat12 = Eigen::Matrix<double, 12, 12>;
using Mat18 = Eigen::Matrix<double, 18, 18>;

constexpr int kDofsPerNode = 6;

/// Local DOF index within a node.
enum NodeDof : int { kU = 0, kV = 1, kW = 2, kThetaX = 3, kThetaY = 4, kThetaZ = 5 };

/// Global DOF id of local DOF `dof` of node `node`.
constexpr int globalDof(int node, int dof) { return kDofsPerNode * node + dof; }

/// Mass matrix option (docs/theory.md 2.3 lumping policy).
enum class MassLumping {
  kConsistent,  ///< consistent beam and linear-triangle translational mass
  kLumped,      ///< row-sum translations, HRZ rotations (block-diagonal per node)
};

}  // namespace orni::structure
