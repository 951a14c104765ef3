// Craig-Bampton reduction with free boundary DOFs b_f (docs/theory.md 3.1) and the ADAMS-style
// orthonormalisation (docs/theory.md 3.1). With b_f empty the basis is just the fixed-interface
// modes (docs/theory.md 3.2 default path).
#pragma once

#include <vector>

#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_types.hpp"
#include "core/structure/modal_solver.hpp"

namespace orni::structure {

struct CraigBamptonOptions {
  /// m, the fixed-interface modes kept; < 0 or >= interior size: all of them (dense solve).
  int max_modes = -1;
  EigenSolveOptions eigen;
};

/// Reduced model in the coordinates (u_bf, q_N): u = T (u_bf; q_N).
struct CraigBamptonModel {
  DofPartition partition;
  Eigen::VectorXd interior_eigenvalues;  ///< omega_k^2 of K_ii phi = omega^2 M_ii phi, ascending
  Eigen::MatrixXd basis;                 ///< T = [Psi, Phi_N], dof_count x (n_bf + m); zero rows
                                         ///< at clamped and inactive DOFs
  Eigen::MatrixXd stiffness;             ///< K_CB = blockdiag(K_bb + K_bi Psi_ib, Lambda)
  Eigen::MatrixXd mass;                  ///< M_CB = T^T M T (symmetrised)

  int boundaryCount() const { return static_cast<int>(partition.boundary_free.size()); }
  int size() const { return static_cast<int>(stiffness.rows()); }
};

/// Builds the CB model from the full symmetric K, M (dof_count square). Constraint modes by one
/// SimplicialLDLT of K_ii. Throws std::runtime_error if K_ii is singular or the eigen-solution
/// fails, std::invalid_argument for an empty interior.
CraigBamptonModel craigBampton(const SparseMatrix& stiffness, const SparseMatrix& mass,
                               const DofPartition& partition,
                               const CraigBamptonOptions& options = {});

struct OrthonormalisationOptions {
  double rigid_snap_relative = 1e-8;  ///< |lambda*| < this * max|lambda*| -> 0, marked rigid
  double mass_rank_relative = 1e-12;  ///< drop M_CB directions with eigenvalue < this * max
};

/// K_CB N = M_CB N Lambda*, N^T M_CB N = I; Phi* = T N (docs/theory.md 3.1).
struct OrthonormalModes {
  Eigen::VectorXd eigenvalues;   ///< lambda* (rad/s)^2, ascending, rigid ones exactly 0
  Eigen::MatrixXd coefficients;  ///< N
  Eigen::MatrixXd shapes;        ///< Phi* = T N, dof_count x count
  std::vector<bool> rigid;       ///< per mode
  int rigid_count = 0;
  int dropped_mass_directions = 0;  ///< nearly singular M_CB directions removed first
};

OrthonormalModes orthonormalise(const CraigBamptonModel& model,
                                const OrthonormalisationOptions& options = {});

}  // namespace orni::structure
