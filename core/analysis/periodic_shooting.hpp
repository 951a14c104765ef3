// Periodic orbits of a T-periodically forced system by single shooting (period_map.hpp): find the
// state x at phase 0 and m free parameters p_f such that
//
//   R(z) = [ (Phi(x, p) - x) / s_x ;  g_c(x, p) / s_g ] = 0,   z = [x / s_x ; p_f / s_p],
//
// where g_c are m of the map's conditions (e.g. the altitude gained over a period: level flight).
// Newton's method on the scaled residual, the Jacobian from forward (optionally central)
// differences of the period map on a fixed discretisation (internal numerical differentiation),
// Broyden rank-one updates between full Jacobians, a backtracking line search on |R|, and one
// refresh of the discretisation once the orbit is close (so that the step grid belongs to the
// orbit found, not to the initial guess). Converged when max_i |R_i| <= residual_tol.
//
// Why single shooting: one forcing period is short against the slow body motions (the monodromy
// of a flapping vehicle has multipliers of order one or below: nothing to tame by splitting the
// period), so the Jacobian is well conditioned, its state block plus the identity is the monodromy
// matrix itself (Floquet analysis for free), and n + m unknowns stay few. Multiple shooting over K
// arcs costs the same right-hand sides per Jacobian but K times the unknowns and a larger linear
// solve.
//
// At the solution the Jacobian is recomputed (ShootingOptions::jacobian_at_solution): its state
// block plus the identity is the monodromy matrix in scaled states, S^-1 dPhi/dx S, whose
// eigenvalues are the Floquet multipliers (floquet.hpp).
//
// For continuation: ShootingSystem exposes the residual, the Jacobian and extra columns
// dR/d(p_j / s_p) of parameters that are not unknowns; solveShooting() starts from any (x, p).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/analysis/period_map.hpp"

namespace orni {

/// Options of one periodic-orbit solve (docs/design.md 7.5).
struct ShootingOptions {
  std::vector<int> free_parameters;  ///< indices of p solved for (distinct, < P)
  std::vector<int> conditions;       ///< indices of the conditions driven to zero (as many)
  double residual_tol = 1e-8;        ///< converged: max |scaled residual| <= tol, (0, 1e-2]
  int max_iterations = 40;           ///< Newton iterations, [1, 1000]
  int max_jacobians = 6;             ///< full finite-difference Jacobians in the solve, [1, 100]
  double fd_step = 1e-7;             ///< finite-difference step, scaled units (times
                                     ///< max(1, |z_j|)), (0, 1e-2]
  bool central_differences = false;  ///< central instead of forward differences (twice the maps)
  bool broyden = true;               ///< Broyden rank-one updates between full Jacobians
  /// Refresh the discretisation once, when the residual first falls below this (0 = never).
  double refresh_below = 1e-4;
  /// A fresh Jacobian when a step reduces |R| by less than this factor.
  double slow_contraction = 0.5;
  bool jacobian_at_solution = true;  ///< recompute the Jacobian at the solution (monodromy)
  /// States whose columns the first Jacobian takes by differences (empty = every state); the
  /// columns of the others are taken as decayed over one period (dPhi/dx_j = 0: fast, strongly
  /// damped states) and left to the Broyden updates. Parameter columns are always differenced.
  /// Later Jacobians are complete.
  std::vector<int> first_jacobian_states;
  /// A Jacobian to start from instead of the first finite-difference one ((n + m)^2, scaled; e.g.
  /// the last one of a neighbouring solve); empty = none.
  Eigen::MatrixXd initial_jacobian;
  /// Threads that take the finite-difference columns of a full Jacobian, [1, 64], each on its own
  /// copy of the map (PeriodMap::clone; a map without copies runs serially). Every column is the
  /// same function of (z, j) on every thread: the Jacobian has the same bits for any count.
  int jacobian_threads = 1;

  bool IsValid(int parameter_count, int condition_count, std::string* why) const;
};

enum class ShootingStatus { kConverged, kNotConverged, kFailed };
/// "converged", "not_converged", "failed".
const char* toString(ShootingStatus s);

/// One Newton iteration.
struct ShootingIteration {
  int iteration = 0;          ///< 0 = initial guess
  double residual_max = 0.0;  ///< max |R_i| at the accepted iterate
  double residual_norm = 0.0; ///< |R|_2
  double step_norm = 0.0;     ///< |dz|_2 (scaled) of the accepted step
  double damping = 1.0;       ///< line-search factor of the step
  bool fresh_jacobian = false;  ///< the step used a finite-difference Jacobian (not Broyden)
  bool refreshed = false;     ///< the discretisation was refreshed before this iterate's residual
  long period_maps = 0;       ///< period maps so far
};

struct ShootingSummary {
  ShootingStatus status = ShootingStatus::kFailed;
  std::string message;
  std::vector<double> x, p;    ///< the last iterate (the orbit's start state and parameters)
  std::vector<double> x_T, g;  ///< its end state and conditions
  double residual_max = 0.0;   ///< max |R_i| (scaled) at x, p
  double residual_norm = 0.0;  ///< |R|_2 (scaled)
  int iterations = 0;
  long period_maps = 0;        ///< every flow() call (residuals, differences, line search)
  int jacobians = 0;           ///< full finite-difference Jacobians (incl. the one at the solution)
  int partial_jacobians = 0;      ///< first Jacobians with decayed columns (not in `jacobians`)
  int broyden_updates = 0;
  int refreshes = 0;           ///< discretisation refreshes (incl. the initial one)
  /// Scaled Jacobian dR/dz, (n + m) x (n + m), at the solution when jacobian_at_solution and
  /// converged (jacobian_valid), else the last one used.
  Eigen::MatrixXd jacobian;
  bool jacobian_valid = false;
  /// Monodromy in scaled states, S^-1 dPhi/dx S = dR/dx + I (n x n), when jacobian_valid.
  Eigen::MatrixXd monodromy;
  std::vector<ShootingIteration> log;

  /// One line: status, residual, iterations, period maps, Jacobians.
  std::string BriefReport() const;
};

/// The scaled shooting residual and its derivatives (for solveShooting and continuation).
class ShootingSystem {
 public:
  /// `p` holds every parameter (P values): the free ones are the initial guess, the others fixed.
  ShootingSystem(PeriodMap& map, std::vector<int> free_parameters, std::vector<int> conditions,
                 std::vector<double> p);

  int stateCount() const { return n_; }
  int unknownCount() const { return n_ + static_cast<int>(free_.size()); }
  PeriodMap& map() { return map_; }
  /// Every parameter; the free ones as last unpacked.
  const std::vector<double>& parameters() const { return p_; }
  void setParameter(int j, double value) { p_[static_cast<std::size_t>(j)] = value; }
  /// Threads for the columns of jacobian() and partialJacobian()
  /// (ShootingOptions::jacobian_threads), >= 1.
  void setJacobianThreads(int threads) { threads_ = threads < 1 ? 1 : threads; }

  /// z = [x / s_x; p_free / s_p].
  Eigen::VectorXd pack(const double* x) const;
  /// x from z, and the free parameters of z into parameters().
  void unpack(const Eigen::VectorXd& z, double* x);

  /// R(z) (n + m), also keeping x_T and g of the run. False with the reason when the flow fails.
  bool residual(const Eigen::VectorXd& z, Eigen::VectorXd* R, std::string* why);
  /// Finite-difference Jacobian dR/dz at z (R = R(z)); with `extra` parameter indices also the
  /// columns dR/d(p_j / s_p) into *J_extra. False when a flow fails.
  bool jacobian(const Eigen::VectorXd& z, const Eigen::VectorXd& R, double step, bool central,
                Eigen::MatrixXd* J, std::string* why, const std::vector<int>& extra = {},
                Eigen::MatrixXd* J_extra = nullptr);
  /// The same with only the state columns `states` differenced (the parameter columns always);
  /// every other state column is -e_j (dPhi/dx_j = 0).
  bool partialJacobian(const Eigen::VectorXd& z, const Eigen::VectorXd& R, double step,
                       const std::vector<int>& states, Eigen::MatrixXd* J, std::string* why);
  /// End state and conditions of the last residual() call.
  const std::vector<double>& lastEndState() const { return x_T_; }
  const std::vector<double>& lastConditions() const { return g_; }
  long periodMaps() const { return maps_; }

 private:
  /// The map runs go to, with their parameters, buffers and count (this system's own members,
  /// or a worker thread's).
  struct Run {
    PeriodMap& map;
    std::vector<double>&p, &x, &x_T, &g;
    long& maps;
  };
  Run own() { return Run{map_, p_, x_, x_T_, g_, maps_}; }
  bool column(Run& run, const Eigen::VectorXd& z, const Eigen::VectorXd& R, Eigen::Index j,
              double step, bool central, Eigen::MatrixXd* J, std::string* why) const;
  /// dR/d(p_j / s_p) of a parameter that is not an unknown into column e of *J_extra.
  bool parameterColumn(Run& run, const Eigen::VectorXd& z, const Eigen::VectorXd& R, int j,
                       Eigen::Index e, double step, bool central, Eigen::MatrixXd* J_extra,
                       std::string* why) const;
  bool evaluate(Run& run, const Eigen::VectorXd& z, Eigen::VectorXd* R, std::string* why) const;
  bool evaluate(const Eigen::VectorXd& z, Eigen::VectorXd* R, std::string* why);
  void unpackInto(const Eigen::VectorXd& z, double* x, std::vector<double>* p) const;
  /// The columns `cols` of J (and the `extra` ones of *J_extra) on threads_ copies of the map;
  /// false (with *cloned = false) when the map has no copies.
  bool parallelJacobian(const Eigen::VectorXd& z, const Eigen::VectorXd& R, double step,
                        bool central, const std::vector<Eigen::Index>& cols, Eigen::MatrixXd* J,
                        std::string* why, const std::vector<int>& extra,
                        Eigen::MatrixXd* J_extra, bool* cloned);

  PeriodMap& map_;
  int n_;
  int threads_ = 1;
  std::vector<int> free_, cond_;
  std::vector<double> p_, x_, x_T_, g_;
  long maps_ = 0;
};

/// Solve for a periodic orbit from the guess (x0, p0) (n and P values; the parameters not freed by
/// `options` are held). Throws std::invalid_argument for invalid options; every numerical outcome
/// is in the summary.
ShootingSummary solveShooting(PeriodMap& map, const std::vector<double>& x0,
                              const std::vector<double>& p0, const ShootingOptions& options);

}  // namespace orni
