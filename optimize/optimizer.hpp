// The optimiser driver: NLopt (private to this library, docs/design.md 1) minimising a Problem
// (problem.hpp) over a box of variables, with inequality constraints, as a multi-start run.
//
// Method. The variables are scaled to the unit box. Algorithm (optimizer_options.hpp):
//   cobyla  NLOPT_LN_COBYLA from the start point;
//   bobyqa  NLOPT_AUGLAG with NLOPT_LN_BOBYQA as the subsidiary (bound-constrained) optimiser;
//   isres   NLOPT_GN_ISRES with max_evaluations - polish evaluations, then NLOPT_LN_COBYLA from
//           the best point of that stage (initial step a quarter of initial_step) with the rest.
// NLopt evaluates one point after another, so the parallelism is over starts: start 0 runs from
// the initial point, start k >= 1 from the k-th point of a Halton sequence in the box (isres
// starts also differ in their seed), `threads` starts at a time. Each start is
// sequential and deterministic (seed + k through nlopt_srand, whose generator is thread-local; its
// own ProblemWorkspace; its own cache), so the merged history (starts in order) is the same for
// any number of threads.
//
// Evaluations. NLopt asks for the objective and then the constraints at the same point; the
// driver evaluates once per point. A point identical (bit for bit) to an earlier point of the same
// start is answered from that start's cache (repeat_of). A point that the hooks can replay (a
// journal of an interrupted run) is taken from there. Failed evaluations (EvaluationStatus::kFailed
// or an exception from Problem::evaluate) and non-finite values reach NLopt as the finite
// penalties failure_objective / failure_constraint, never as NaN; they are never fatal.
//
// Result. The best evaluation over all starts: the feasible one (not failed, every g_i <=
// constraint_tol) with the least objective; when none is feasible, the one with the least
// constraint violation. Ties go to the earlier evaluation in the merged history. `converged` is
// true when the best is feasible and its start stopped on a tolerance (xtol, ftol) rather than on
// the evaluation budget or an error.
//
// Exceptions: std::invalid_argument for invalid options or box; an exception thrown by a hook (a
// journal that cannot be written) stops every start and is rethrown (docs/design.md 7.7: never
// across the C callback).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "optimize/optimizer_options.hpp"
#include "optimize/problem.hpp"

namespace orni::opt {

/// The box of the variables and the initial point (physical units).
struct VariableBox {
  std::vector<double> lower, upper;  ///< lower < upper, finite
  std::vector<double> initial;       ///< inside [lower, upper]
  int size() const { return static_cast<int>(lower.size()); }
  bool IsValid(std::string* why) const;
};

/// The stage of a start an evaluation belongs to.
enum class Stage { kLocal, kGlobal, kPolish };
/// "local", "global", "polish".
const char* toString(Stage s);

/// Where the result of an evaluation came from.
enum class EvaluationSource { kComputed, kCached, kReplayed };

/// One evaluation as the driver records it.
struct EvaluationRecord {
  int start = 0;         ///< start number
  int index = 0;         ///< 0-based within the start, in call order
  Stage stage = Stage::kLocal;
  std::vector<double> x;  ///< physical units
  Evaluation result;     ///< as handed to NLopt: finite (penalties for failures)
  bool feasible = false;
  double violation = 0.0;  ///< max(0, max_i g_i); failure_constraint for a failed evaluation
  int repeat_of = -1;      ///< index (same start) of the identical earlier point, or -1
  EvaluationSource source = EvaluationSource::kComputed;
};

/// How one start ended.
struct StartSummary {
  int start = 0;
  std::vector<double> x0;    ///< start point (physical)
  int nlopt_result = 0;      ///< nlopt_result of the last stage
  std::string termination;   ///< that code in words ("xtol reached", "evaluation budget", ...)
  bool converged = false;    ///< stopped on xtol / ftol (or success) rather than budget or error
  int evaluations = 0;
  int best = -1;             ///< index (within the start) of the start's best evaluation
};

struct OptimizerSummary {
  std::vector<EvaluationRecord> history;  ///< start 0's evaluations in order, then start 1's, ...
  std::vector<StartSummary> starts;
  int best = -1;           ///< index into history (-1 only without evaluations)
  bool feasible = false;   ///< history[best] is feasible
  bool converged = false;  ///< feasible, and its start converged
  int computed = 0, cached = 0, replayed = 0, failed = 0;
  double wall_time_s = 0.0;
  std::string message;     ///< one line: what was found

  const EvaluationRecord* bestRecord() const { return best >= 0 ? &history[best] : nullptr; }
  /// One line: algorithm outcome, best objective, feasibility, evaluations, time.
  std::string BriefReport() const;
};

/// Journal replay and observation (both optional; called from worker threads).
struct OptimizerHooks {
  /// The stored result of evaluation `index` of `start` when it was made at exactly `x`, else
  /// nullopt (then the point is computed). Must be thread-safe.
  std::function<std::optional<Evaluation>(int start, int index, const std::vector<double>& x)>
      replay;
  /// Called after every evaluation (computed, cached or replayed) with its record. Must be
  /// thread-safe; an exception stops the run and is rethrown by minimize().
  std::function<void(const EvaluationRecord&)> on_evaluation;
};

/// Start point of start k (physical): the initial point for k = 0, else the k-th point of the
/// Halton sequence (bases 2, 3, 5, ...) in the box.
std::vector<double> startPoint(const VariableBox& box, int start);

/// Runs start `start` alone, exactly as minimize() runs it (start point, seed, cache, hooks), and
/// returns its records in call order: a distributed run's worker computes one start of a multi-start
/// run (studies/runner/distributed/point_farm.hpp). Throws like minimize(), and rethrows an
/// exception thrown by a hook; std::invalid_argument when start is outside [0, options.starts).
std::vector<EvaluationRecord> runStart(const Problem& problem, const VariableBox& box,
                                       const OptimizerOptions& options,
                                       const OptimizerHooks& hooks, int start);

/// Run the optimisation. Throws std::invalid_argument for invalid options, box or problem sizes.
OptimizerSummary minimize(const Problem& problem, const VariableBox& box,
                          const OptimizerOptions& options, const OptimizerHooks& hooks = {});

}  // namespace orni::opt
