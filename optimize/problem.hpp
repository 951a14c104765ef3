// What the optimiser driver (optimizer.hpp) minimises: a Problem maps a design vector x (physical
// units, inside the variable box) to an objective and inequality constraints g_i(x) <= 0.
//
// Model vs data (docs/design.md 7.1): a Problem is immutable and shared by the starts of a
// multi-start run on several threads; each start owns a ProblemWorkspace (made by
// makeWorkspace()) that carries whatever state one start's evaluation sequence needs (the design
// problem keeps its warm start there). evaluate() and observe() must be safe to call concurrently
// on different workspaces.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace orni::opt {

/// How an evaluation ended. Feasibility is judged by the driver from the constraints.
enum class EvaluationStatus {
  kOk,      ///< the functions were evaluated (the point may still violate constraints)
  kFailed,  ///< no result (the model could not be built or evaluated): the driver hands NLopt
            ///< the finite penalties of OptimizerOptions
};
/// "ok", "failed".
const char* toString(EvaluationStatus s);

/// The result of one evaluation.
struct Evaluation {
  EvaluationStatus status = EvaluationStatus::kOk;
  double objective = 0.0;           ///< to minimise
  std::vector<double> constraints;  ///< Problem::constraintCount() values, feasible when <= 0
  /// Problem-specific results reported with the evaluation (e.g. the trim point), SI; NaN where
  /// not available. Problem::valueCount() values.
  std::vector<double> values;
  std::string message;              ///< one line: what happened (why infeasible or failed)
};

/// Per-start state of a problem (base class; a problem downcasts its own).
struct ProblemWorkspace {
  virtual ~ProblemWorkspace() = default;
};

class Problem {
 public:
  virtual ~Problem() = default;
  virtual int variableCount() const = 0;
  virtual int constraintCount() const = 0;
  virtual int valueCount() const { return 0; }

  /// A fresh workspace for one start.
  virtual std::unique_ptr<ProblemWorkspace> makeWorkspace() const {
    return std::make_unique<ProblemWorkspace>();
  }
  /// Evaluate at x (variableCount() values, inside the box). May throw: the driver records a
  /// failed evaluation with the exception's message.
  virtual Evaluation evaluate(const std::vector<double>& x, ProblemWorkspace& workspace) const = 0;
  /// Called after every evaluation of a start, in order, whether it was computed, answered from
  /// the start's cache of identical points or replayed from a journal: the place to update the
  /// workspace (so that a replayed run reaches the same state as the original). Default: nothing.
  virtual void observe(const std::vector<double>& /*x*/, const Evaluation& /*result*/,
                       ProblemWorkspace& /*workspace*/) const {}
};

}  // namespace orni::opt
