// OptimizerOptions: the options of one optimisation (docs/design.md 7.5: plain struct, documented
// defaults, IsValid). Light header (no NLopt, no model) so that the study files can hold them; the
// driver is optimizer.hpp.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace orni::opt {

/// The NLopt algorithms the driver offers (all derivative-free: every evaluation is a simulation).
enum class Algorithm {
  kCobyla,  ///< NLOPT_LN_COBYLA: linear approximations, inequality constraints (default)
  kBobyqa,  ///< NLOPT_AUGLAG (augmented Lagrangian) around NLOPT_LN_BOBYQA (quadratic models,
            ///< bounds only); needs at least 2 variables
  kIsres,   ///< NLOPT_GN_ISRES (global, evolution strategy with stochastic ranking, constraints),
            ///< then a local NLOPT_LN_COBYLA polish from the best point found
};

/// "cobyla", "bobyqa", "isres".
const char* toString(Algorithm a);
/// The algorithm of that name, or nullopt.
std::optional<Algorithm> parseAlgorithm(std::string_view name);

/// Options of the driver. The optimiser works on the variables scaled to the unit box
/// (u = (x - lower) / (upper - lower)), so the step and tolerance options are fractions of each
/// variable's range.
struct OptimizerOptions {
  Algorithm algorithm = Algorithm::kCobyla;
  /// Evaluations per start, every stage included (isres: global stage + polish), [2, 1000000].
  int max_evaluations = 100;
  /// Independent starts (multi-start): start 0 from the initial point, start k >= 1 from the k-th
  /// point of a Halton sequence in the box; isres starts differ in their seed. [1, 1000].
  int starts = 1;
  /// Worker threads over the starts, [1, 1024]; the results do not depend on it.
  int threads = 1;
  /// Seed of start k is seed + k (nlopt_srand; NLopt's generator is thread-local). [0, 2^31).
  long seed = 1;
  /// Initial step (COBYLA rhobeg, BOBYQA trust radius) as a fraction of each range, (0, 1].
  double initial_step = 0.1;
  /// Stop when a step moves every scaled variable by less than this (xtol_abs in the unit box),
  /// [0, 1); 0 = off.
  double xtol = 1e-4;
  /// Stop when the objective changes by less than this fraction (ftol_rel), [0, 1); 0 = off.
  double ftol_rel = 0.0;
  /// isres: evaluations of the COBYLA polish, [1, max_evaluations - 1]; 0 = max_evaluations / 4
  /// (at least 1).
  int polish_evaluations = 0;
  /// isres: population size, 0 = NLopt's default 20 (n + 1); else [2, 100000].
  int population = 0;
  /// An evaluation is feasible when it did not fail and every constraint g_i <= constraint_tol,
  /// [0, 1).
  double constraint_tol = 1e-6;
  /// Finite stand-ins handed to NLopt for a failed evaluation or a non-finite value (never NaN):
  /// objective failure_objective, every constraint failure_constraint (> 0, violated). Finite.
  double failure_objective = 1e3;
  double failure_constraint = 100.0;

  /// The polish budget of isres (polish_evaluations resolved).
  int polishEvaluations() const;
  /// True when every field is inside its range; otherwise false with the reason in *why.
  bool IsValid(std::string* why) const;
};

}  // namespace orni::opt
