// DOF partition and index-map extraction (docs/theory.md 2.6).
#include "core/structure/dof_partition.hpp"

#include <stdexcept>
#include <string>

namespace orni::structure {

std::vector<int> DofPartition::retained() const {
  std::vector<int> r = boundary_free;
  r.insert(r.end(), interior.begin(), interior.end());
  return r;
}

DofPartition makeDofPartition(const std::vector<bool>& active, const std::vector<int>& clamped_dofs,
                              const std::vector<int>& free_boundary_dofs) {
  const int n = static_cast<int>(active.size());
  enum Role : char { kInterior, kClamped, kFree };
  std::vector<char> role(static_cast<std::size_t>(n), kInterior);
  auto mark = [&](const std::vector<int>& dofs, Role r) {
    for (int d : dofs) {
      if (d < 0 || d >= n)
        throw std::invalid_argument("DOF partition: DOF id " + std::to_string(d) +
                                    " outside [0, " + std::to_string(n) + ")");
      role[static_cast<std::size_t>(d)] = r;
    }
  };
  mark(clamped_dofs, kClamped);
  mark(free_boundary_dofs, kFree);
  DofPartition p;
  p.dof_count = n;
  for (int d = 0; d < n; ++d) {
    if (!active[static_cast<std::size_t>(d)]) continue;
    switch (role[static_cast<std::size_t>(d)]) {
      case kInterior: p.interior.push_back(d); break;
      case kClamped: p.clamped.push_back(d); break;
      case kFree: p.boundary_free.push_back(d); break;
    }
  }
  return p;
}

SparseMatrix extractBlock(const SparseMatrix& a, const std::vector<int>& rows,
                          const std::vector<int>& cols) {
  std::vector<int> row_map(static_cast<std::size_t>(a.rows()), -1);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i > 0 && rows[i] <= rows[i - 1])
      throw std::invalid_argument("extractBlock: row list must be strictly ascending");
    row_map[static_cast<std::size_t>(rows[i])] = static_cast<int>(i);
  }
  SparseMatrix out(static_cast<int>(rows.size()), static_cast<int>(cols.size()));
  Eigen::Index nnz = 0;
  for (int c : cols) nnz += a.col(c).nonZeros();
  out.reserve(nnz);
  for (std::size_t j = 0; j < cols.size(); ++j) {
    out.startVec(static_cast<Eigen::Index>(j));
    for (SparseMatrix::InnerIterator it(a, cols[j]); it; ++it) {
      const int r = row_map[static_cast<std::size_t>(it.row())];
      if (r >= 0) out.insertBack(r, static_cast<Eigen::Index>(j)) = it.value();
    }
  }
  out.finalize();
  return out;
}

Eigen::MatrixXd expandRows(const Eigen::MatrixXd& reduced, const std::vector<int>& dofs,
                           int dof_count) {
  Eigen::MatrixXd full = Eigen::MatrixXd::Zero(dof_count, reduced.cols());
  for (std::size_t i = 0; i < dofs.size(); ++i)
    full.row(dofs[i]) = reduced.row(static_cast<Eigen::Index>(i));
  return full;
}

}  // namespace orni::structure
