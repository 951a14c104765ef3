// Pseudo-arclength continuation of periodic orbits (docs/theory.md 10.5) over one parameter of a
// period map (period_map.hpp), with the Floquet multipliers of every point and the events where
// the branch folds or a multiplier leaves the unit circle.
//
// Unknowns y = [z; lambda / s_lambda], z the shooting unknowns of periodic_shooting.hpp (the
// orbit's start state and the free parameters, scaled) and lambda the continuation parameter (a
// parameter of the map that is not free). Equations H(y) = R(z; lambda) = 0, N = n + m of them in
// N + 1 unknowns: a curve. From a point y_k with unit tangent t_k (the null vector of
// DH = [dR/dz, dR/dlambda], oriented like t_{k-1}):
//   predictor  y_p = y_k + h t_k;
//   corrector  Newton on [H(y); t_k . (y - y_p)] = 0 from y_p with the matrix [DH(y_k); t_k^T]
//              and Broyden updates of its DH block (chord-Broyden; the last row is exact);
//   step       h grows by 1.5 when the corrector took fewer than `target_iterations`, shrinks by
//              0.7 above them, halves on failure down to `min_step`.
// At every accepted point DH is formed again, in one of two ways:
//   all multipliers (leading_multipliers = 0): by forward differences (N + 1 period maps); its
//     state block plus the identity is the monodromy matrix (all n multipliers: stable when every
//     |mu| < 1), its null vector the next tangent;
//   the leading ones (leading_multipliers = k > 0): only the columns of `slow_states`, the free
//     parameters and lambda are differenced, every other state column is taken as decayed over a
//     period (dPhi/dx_j = 0, as the periodic trim's first Jacobian); the tangent is the null vector
//     of that partial DH made exact by GMRES on [DH; t0^T] d = [-DH t0; 0] (one directional
//     difference of H per product, preconditioned by the partial matrix), and the k leading
//     multipliers come from Arnoldi (monodromy.hpp). About 40 maps a point on the flexible magpie
//     instead of 108. When Arnoldi or GMRES does not converge the point falls back to the full DH.
// Both depend on the point's y alone (the previous tangent only orients the new one), so a run
// resumed from a recorded point (resume_from: y, tangent, step) continues with the same numbers.
//
// Events, between consecutive points:
//   fold               the parameter component of the tangent changes sign (a turning point of
//                      the branch: a multiplier passes +1 there too);
//   branch_point       a real multiplier crosses +1 without a fold (transcritical or pitchfork);
//   period_doubling    a real multiplier crosses -1 (flip);
//   neimark_sacker     a complex pair crosses the unit circle (torus).
// Each is located by bisection on the arclength from the earlier point (predictor along its
// tangent, corrector with the arclength condition), to `locate_tol` in the parameter, and reported
// as an extra point with its event name. The continuation then goes on from the later point.
//
// The map may change only in `prepare`: called with the given start orbit before anything else,
// and with every corrected regular point; when it changes the map (e.g. a vehicle's skin friction
// moved to that orbit's airspeed, as a periodic trim's second pass does) the point is corrected
// again at its parameter. A resumed run (the caller sets the map as it was when the recorded
// point was accepted; the grid is chosen again at the recorded grid_origin; every tangent is a
// function of the Jacobian alone) reproduces an uninterrupted run's points bit for bit.
//
// Stops when the parameter leaves [lambda_min, lambda_max], after max_points points, or when the
// step falls below min_step (status not_converged, with the reason). No I/O; thread-compatible.
#pragma once

#include <complex>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/analysis/period_map.hpp"
#include "core/analysis/periodic_shooting.hpp"

namespace orni {

/// Options of continuePeriodicOrbits (docs/design.md 7.5).
struct ContinuationOptions {
  int parameter = 0;            ///< index of the continuation parameter lambda in p (not free)
  double lambda_min = 0.0;      ///< the branch is followed while lambda stays in [min, max]
  double lambda_max = 1.0;
  /// Initial arclength step, scaled units (|dy| with lambda over its parameter scale); the sign
  /// of the first step is the direction of `direction`.
  double initial_step = 0.05;
  double min_step = 1e-5;       ///< below: not_converged
  double max_step = 0.5;
  /// The three steps are steps of lambda / s_lambda rather than of the arclength: at the start
  /// they are divided by |t_lambda| of the first tangent (a branch along which the orbit moves
  /// fast in scaled states then still advances by about initial_step in the parameter).
  bool steps_in_parameter = false;
  int direction = +1;           ///< +1: first step towards larger lambda, -1 towards smaller
  int max_points = 30;          ///< points after the start (events not counted), [1, 100000]
  int max_corrector_iterations = 8;
  int target_iterations = 4;    ///< the step shrinks when the corrector takes more
  double residual_tol = 1e-8;   ///< max |R| (scaled) of an accepted point
  double fd_step = 1e-7;        ///< forward-difference step (scaled units, times max(1, |y_j|))
  bool locate_events = true;    ///< bisection on events (else they are only flagged)
  double locate_tol = 1e-6;     ///< events located to this in lambda (parameter units)
  int max_bisections = 60;
  /// Multipliers of every point: 0 = all n from the full Jacobian; k > 0 = the leading k by
  /// Arnoldi with the partial Jacobian and the GMRES tangent (file comment), [0, 100].
  int leading_multipliers = 0;
  /// With leading_multipliers > 0: the states whose Jacobian columns are differenced (the slow
  /// ones, e.g. the body's); empty = every state (the partial Jacobian is then the full one).
  std::vector<int> slow_states;
  /// With leading_multipliers > 0: the tangent's GMRES stops when |DH t|_2 <= tangent_tol (t unit,
  /// scaled units; the differenced DH itself is good to ~fd_step), within max_krylov products.
  double tangent_tol = 1e-7;
  int max_krylov = 48;          ///< also Arnoldi's dimension limit, [2, 400]

  bool IsValid(std::string* why) const;
};

/// One point of the branch.
struct ContinuationPoint {
  int index = 0;                 ///< 0 = start; events share the index of the point they precede
  std::string event;             ///< "" (a regular point) or the event name
  double lambda = 0.0;           ///< continuation parameter (its own units)
  std::vector<double> x, p;      ///< orbit start state and every parameter
  double arclength = 0.0;        ///< scaled arclength from the start
  double residual_max = 0.0;     ///< max |R| (scaled)
  int corrector_iterations = 0;
  long period_maps = 0;          ///< maps used so far (the whole run)
  Eigen::VectorXcd multipliers;  ///< all n, or the leading ones, by modulus (largest first)
  bool multipliers_complete = false;  ///< all n (the full Jacobian) rather than the leading ones
  double max_modulus = 0.0;
  Eigen::VectorXcd leading_vector;  ///< eigenvector of multipliers[0] (scaled states, unit norm)
  bool stable = false;           ///< max_modulus < 1
  double tangent_lambda = 0.0;   ///< parameter component of the unit tangent (scaled)
  Eigen::VectorXd y, tangent;    ///< scaled unknowns and unit tangent (resume)
  Eigen::VectorXd grid_origin;   ///< where the map's grid of this point was chosen (resume)
  double step = 0.0;             ///< the step the next point will try (resume)
  double step_scale = 1.0;       ///< factor of steps_in_parameter on the limits (resume)
};

enum class ContinuationStatus { kCompleted, kNotConverged, kFailed, kInterrupted };
/// "completed", "not_converged", "failed", "interrupted".
const char* toString(ContinuationStatus s);

struct ContinuationSummary {
  ContinuationStatus status = ContinuationStatus::kFailed;
  std::string message;
  std::vector<ContinuationPoint> points;  ///< start, regular points and located events in order
  long period_maps = 0;
  int events = 0;
};

/// Called with every point as it is accepted (the start, regular points, events); return false to
/// stop the run (status interrupted).
using ContinuationCallback = std::function<bool(const ContinuationPoint&)>;
/// Called on resume after the recorded point's grid is chosen again (at the recorded grid_origin)
/// and before its Jacobian: the caller moves the map from the state it had when that grid was
/// chosen to the state it had when the point was accepted.
using ContinuationResumeHook = std::function<void()>;
/// Called with the start orbit and with each corrected regular point (x, p, lambda, y set) before
/// its Jacobian: the caller may move a coefficient of the map that is frozen during a solve to
/// this orbit; true when it changed the map (the point is then corrected again).
using ContinuationPrepare = std::function<bool(const ContinuationPoint&)>;

/// Continue the periodic orbits of `map` from (x0, p0), an orbit already solved to the
/// residual tolerance at lambda = p0[options.parameter], with the free parameters and conditions
/// of `shooting` (its fd_step and central_differences are not used: options.fd_step is).
/// `resume_from`, when given, is a regular point of an earlier run (its y, tangent, step, index,
/// arclength): the run continues after it instead of from (x0, p0). Throws std::invalid_argument
/// for invalid options; every numerical outcome is in the summary.
ContinuationSummary continuePeriodicOrbits(PeriodMap& map, const std::vector<double>& x0,
                                           const std::vector<double>& p0,
                                           const ShootingOptions& shooting,
                                           const ContinuationOptions& options,
                                           const ContinuationCallback& on_point = {},
                                           const ContinuationPrepare& prepare = {},
                                           const ContinuationPoint* resume_from = nullptr,
                                           const ContinuationResumeHook& on_resume = {});

/// The event between two regular points a (earlier) and b, "" when none: fold (tangent_lambda
/// changes sign), else the type of the multiplier that crossed the unit circle.
std::string continuationEventBetween(const ContinuationPoint& a, const ContinuationPoint& b);

}  // namespace orni
