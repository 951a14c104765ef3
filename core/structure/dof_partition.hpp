// Partition of the global DOFs for the fixed-interface problem and Craig-Bampton
// (docs/theory.md 2.6, 3.1, 3.2): interior i, free boundary b_f, clamped boundary b_c; inactive
// DOFs belong to none of them. Sub-matrices are extracted through an index map.
#pragma once

#include <vector>

#include "core/structure/fe_types.hpp"

namespace orni::structure {

struct DofPartition {
  int dof_count = 0;                ///< 6 * nodes
  std::vector<int> interior;        ///< i: active, not boundary (ascending global ids)
  std::vector<int> boundary_free;   ///< b_f: active boundary DOFs left free (ascending)
  std::vector<int> clamped;         ///< b_c: active boundary DOFs held at zero (ascending)

  /// Retained DOFs r = b_f then i (the order of the Craig-Bampton coordinates).
  std::vector<int> retained() const;
};

/// Builds the partition. `clamped_dofs` and `free_boundary_dofs` are global ids (any order,
/// duplicates allowed); a DOF in both is free; inactive DOFs are dropped. Throws
/// std::invalid_argument for an id outside [0, active.size()).
DofPartition makeDofPartition(const std::vector<bool>& active, const std::vector<int>& clamped_dofs,
                              const std::vector<int>& free_boundary_dofs = {});

/// A(rows, cols) as a new sparse matrix; `rows` must be strictly ascending (cols any order).
SparseMatrix extractBlock(const SparseMatrix& a, const std::vector<int>& rows,
                          const std::vector<int>& cols);

/// Scatter of a matrix over the DOF list `dofs` into dof_count rows (zeros elsewhere).
Eigen::MatrixXd expandRows(const Eigen::MatrixXd& reduced, const std::vector<int>& dofs,
                           int dof_count);

}  // namespace orni::structure
