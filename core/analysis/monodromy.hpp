// The monodromy matrix of a periodic orbit (the Jacobian of its period map, period_map.hpp) and its
// eigenpairs, the Floquet multipliers (floquet.hpp), in the map's scaled states (x_i / s_i).
//
// Two ways, both by forward differences of the period map on its fixed discretisation (so the
// differences are smooth, grid_runge_kutta.hpp):
//   - all n multipliers: the full matrix, one period map per state (n + 1 maps);
//   - the leading ones: Arnoldi's method on the operator v -> M v, each product one period map
//     (a directional difference). A flapping vehicle's monodromy has a few multipliers of order
//     one (the body's phugoid- and short-period-like motions, the lowest wing modes) and many
//     that a period damps to almost nothing (the higher wing modes, the aerodynamic lag states),
//     so a Krylov space of 15-30 vectors holds the leading multipliers to 1e-6 where the full
//     matrix of the flexible magpie needs 107 maps. Converged when every wanted Ritz pair's
//     residual |h_{m+1,m} y_m| (the exact residual norm of the Ritz pair of the differenced
//     operator) is below `tol`; otherwise the full matrix is the fallback of the caller.
// The start vector of Arnoldi is fixed (a seeded sequence), so results are deterministic.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/analysis/period_map.hpp"

namespace orni {

/// Options of leadingMultipliers (docs/design.md 7.5).
struct ArnoldiOptions {
  int count = 12;           ///< leading multipliers wanted (a conjugate pair is kept whole), >= 1
  double tol = 1e-6;        ///< Ritz residual of each wanted pair (scaled states), (0, 1e-2]
  int max_dimension = 48;   ///< Krylov dimension limit, >= count + 1
  double fd_step = 1e-7;    ///< forward-difference step, scaled units times max(1, |z|_inf),
                            ///< (0, 1e-2]

  bool IsValid(std::string* why) const;
};

/// Eigenpairs of a monodromy matrix (all, or the leading ones).
struct MonodromyEigen {
  bool ok = false;                 ///< the pairs are valid (converged when Arnoldi)
  std::string message;             ///< how they were found, or why not
  bool complete = false;           ///< every multiplier (the full matrix) rather than the leading
  int state_count = 0;             ///< n
  Eigen::VectorXcd multipliers;    ///< by modulus, largest first
  Eigen::MatrixXcd vectors;        ///< eigenvectors in scaled states (columns, unit 2-norm)
  std::vector<double> residuals;   ///< Ritz residual per pair (0 for the full matrix)
  int krylov_dimension = 0;        ///< Arnoldi's final dimension (0 for the full matrix)
  long period_maps = 0;            ///< maps used
};

/// Full monodromy S^-1 dPhi/dx S (n x n) at the orbit start x (n) and parameters p (P) by
/// forward differences (n + 1 maps on the map's current discretisation). False with the reason
/// when a map fails. `maps` (may be null) receives the maps used.
bool monodromyByDifferences(PeriodMap& map, const std::vector<double>& x,
                            const std::vector<double>& p, double fd_step, Eigen::MatrixXd* M,
                            long* maps, std::string* why);

/// Eigenpairs of a full monodromy, sorted (complete = true).
MonodromyEigen eigenOfMonodromy(const Eigen::MatrixXd& M);

/// The leading multipliers at the orbit start x and parameters p by Arnoldi (see the file
/// comment). Throws std::invalid_argument for invalid options; a numerical failure or no
/// convergence within max_dimension is ok = false with the message.
MonodromyEigen leadingMultipliers(PeriodMap& map, const std::vector<double>& x,
                                  const std::vector<double>& p, const ArnoldiOptions& options);

}  // namespace orni
