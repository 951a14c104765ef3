#include "optimize/optimizer_options.hpp"

#include <algorithm>
#include <cmath>

namespace orni::opt {

const char* toString(Algorithm a) {
  switch (a) {
    case Algorithm::kCobyla: return "cobyla";
    case Algorithm::kBobyqa: return "bobyqa";
    case Algorithm::kIsres: return "isres";
  }
  return "cobyla";
}

std::optional<Algorithm> parseAlgorithm(std::string_view name) {
  for (Algorithm a : {Algorithm::kCobyla, Algorithm::kBobyqa, Algorithm::kIsres})
    if (name == toString(a)) return a;
  return std::nullopt;
}

int OptimizerOptions::polishEvaluations() const {
  if (polish_evaluations > 0) return polish_evaluations;
  return std::max(1, max_evaluations / 4);
}

bool OptimizerOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (max_evaluations < 2 || max_evaluations > 1000000)
    return fail("max_evaluations must be in [2, 1000000]");
  if (starts < 1 || starts > 1000) return fail("starts must be in [1, 1000]");
  if (threads < 1 || threads > 1024) return fail("threads must be in [1, 1024]");
  if (seed < 0 || seed >= 2147483648L) return fail("seed must be in [0, 2^31)");
  if (!(initial_step > 0.0 && initial_step <= 1.0)) return fail("initial_step must be in (0, 1]");
  if (!(xtol >= 0.0 && xtol < 1.0)) return fail("xtol must be in [0, 1)");
  if (!(ftol_rel >= 0.0 && ftol_rel < 1.0)) return fail("ftol_rel must be in [0, 1)");
  if (polish_evaluations < 0 || polish_evaluations >= max_evaluations)
    return fail("polish_evaluations must be in [0, max_evaluations - 1]");
  if (population != 0 && (population < 2 || population > 100000))
    return fail("population must be 0 (automatic) or in [2, 100000]");
  if (!(constraint_tol >= 0.0 && constraint_tol < 1.0))
    return fail("constraint_tol must be in [0, 1)");
  if (!std::isfinite(failure_objective)) return fail("failure_objective must be finite");
  if (!(std::isfinite(failure_constraint) && failure_constraint > 0.0))
    return fail("failure_constraint must be finite and > 0");
  return true;
}

}  // namespace orni::opt
