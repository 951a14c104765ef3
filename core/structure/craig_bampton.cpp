// Craig-Bampton basis and ADAMS-style orthonormalisation (docs/theory.md 3.1, 3.2).
#include "core/structure/craig_bampton.hpp"
#include "core/structure/product_blocking.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

namespace orni::structure {

CraigBamptonModel craigBampton(const SparseMatrix& stiffness, const SparseMatrix& mass,
                               const DofPartition& partition, const CraigBamptonOptions& options) {
  planProductsWithFixedCacheSizes();  // the same bits on every CPU (docs/theory.md 3.7)
  const std::vector<int>& interior = partition.interior;
  const std::vector<int>& bf = partition.boundary_free;
  const int ni = static_cast<int>(interior.size());
  const int nb = static_cast<int>(bf.size());
  if (ni == 0) throw std::invalid_argument("craigBampton: the interior DOF set is empty");
  if (stiffness.rows() != partition.dof_count || mass.rows() != partition.dof_count)
    throw std::invalid_argument("craigBampton: K, M and the partition sizes differ");

  const SparseMatrix k_ii = extractBlock(stiffness, interior, interior);
  const SparseMatrix m_ii = extractBlock(mass, interior, interior);
  const int m = options.max_modes < 0 ? ni : std::min(options.max_modes, ni);
  if (m < 1) throw std::invalid_argument("craigBampton: expected max_modes != 0");
  const EigenSolution modes = lowestEigenpairs(k_ii, m_ii, m, options.eigen);
  if (!modes.success)
    throw std::runtime_error("craigBampton: fixed-interface eigen-solution failed: " +
                             modes.message);

  CraigBamptonModel cb;
  cb.partition = partition;
  cb.interior_eigenvalues = modes.eigenvalues;
  const int n = nb + m;
  cb.basis = Eigen::MatrixXd::Zero(partition.dof_count, n);
  cb.stiffness = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < ni; ++i)
    cb.basis.row(interior[static_cast<std::size_t>(i)]).tail(m) = modes.vectors.row(i);
  cb.stiffness.bottomRightCorner(m, m) = modes.eigenvalues.asDiagonal();

  if (nb > 0) {
    // Constraint modes Psi_ib = -K_ii^{-1} K_ib (one sparse Cholesky, n_b right-hand sides).
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(k_ii);
    if (ldlt.info() != Eigen::Success)
      throw std::runtime_error("craigBampton: K_ii is singular (a rigid mode is not held)");
    const Eigen::MatrixXd k_ib = Eigen::MatrixXd(extractBlock(stiffness, interior, bf));
    const Eigen::MatrixXd psi_ib = -ldlt.solve(k_ib);
    const Eigen::MatrixXd k_bb = Eigen::MatrixXd(extractBlock(stiffness, bf, bf));
    Eigen::MatrixXd guyan = k_bb + k_ib.transpose() * psi_ib;
    cb.stiffness.topLeftCorner(nb, nb) = 0.5 * (guyan + guyan.transpose());
    for (int b = 0; b < nb; ++b) cb.basis(bf[static_cast<std::size_t>(b)], b) = 1.0;
    for (int i = 0; i < ni; ++i)
      cb.basis.row(interior[static_cast<std::size_t>(i)]).head(nb) = psi_ib.row(i);
  }
  const Eigen::MatrixXd mt = mass * cb.basis;
  const Eigen::MatrixXd m_cb = cb.basis.transpose() * mt;
  cb.mass = 0.5 * (m_cb + m_cb.transpose());
  return cb;
}

OrthonormalModes orthonormalise(const CraigBamptonModel& model,
                                const OrthonormalisationOptions& options) {
  OrthonormalModes out;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> mass_eig(model.mass);
  const Eigen::VectorXd& d = mass_eig.eigenvalues();
  const double d_max = d.maxCoeff();
  if (!(d_max > 0.0)) throw std::runtime_error("orthonormalise: M_CB has no positive direction");
  const double floor = options.mass_rank_relative * d_max;

  if (d.minCoeff() > floor) {
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(model.stiffness,
                                                                       model.mass);
    if (es.info() != Eigen::Success) throw std::runtime_error("orthonormalise: eigen-solve failed");
    out.eigenvalues = es.eigenvalues();
    out.coefficients = es.eigenvectors();
  } else {
    // Drop nearly singular mass directions, then a standard problem in the kept ones.
    std::vector<int> keep;
    for (Eigen::Index k = 0; k < d.size(); ++k)
      if (d(k) > floor) keep.push_back(static_cast<int>(k));
    out.dropped_mass_directions = static_cast<int>(d.size()) - static_cast<int>(keep.size());
    Eigen::MatrixXd q(d.size(), static_cast<Eigen::Index>(keep.size()));
    for (std::size_t j = 0; j < keep.size(); ++j)
      q.col(static_cast<Eigen::Index>(j)) =
          mass_eig.eigenvectors().col(keep[j]) / std::sqrt(d(keep[j]));
    const Eigen::MatrixXd k_hat = q.transpose() * model.stiffness * q;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (k_hat + k_hat.transpose()));
    out.eigenvalues = es.eigenvalues();
    out.coefficients = q * es.eigenvectors();
  }

  const double lambda_max = out.eigenvalues.cwiseAbs().maxCoeff();
  out.rigid.assign(static_cast<std::size_t>(out.eigenvalues.size()), false);
  for (Eigen::Index k = 0; k < out.eigenvalues.size(); ++k)
    if (std::abs(out.eigenvalues(k)) < options.rigid_snap_relative * lambda_max) {
      out.eigenvalues(k) = 0.0;
      out.rigid[static_cast<std::size_t>(k)] = true;
      ++out.rigid_count;
    }
  out.shapes = model.basis * out.coefficients;
  return out;
}

}  // namespace orni::structure
