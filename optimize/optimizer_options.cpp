#include "optimize/optimizer_options.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/model/field_table.hpp"

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
  // The keys of [optimize] and -j: the field table's ranges.
  const std::pair<const char*, double> keyed[] = {
      {"optimize.max_evaluations", max_evaluations},
      {"optimize.starts", starts},
      {"jobs", threads},
      {"optimize.seed", static_cast<double>(seed)},
      {"optimize.initial_step", initial_step},
      {"optimize.xtol", xtol},
      {"optimize.ftol_rel", ftol_rel},
      {"optimize.polish_evaluations", polish_evaluations},
      {"optimize.population", population},
      {"optimize.constraint_tol", constraint_tol}};
  for (const auto& [key, value] : keyed)
    if (!field(key).range.contains(value)) {
      const std::string name(field(key).key.substr(field(key).key.rfind('.') + 1));
      if (why) *why = name + " must be in " + field(key).range.interval();
      return false;
    }
  if (polish_evaluations >= max_evaluations)
    return fail("polish_evaluations must be in [0, max_evaluations - 1]");
  if (population == 1) return fail("population must be 0 (automatic) or in [2, 100000]");
  if (!std::isfinite(failure_objective)) return fail("failure_objective must be finite");
  if (!(std::isfinite(failure_constraint) && failure_constraint > 0.0))
    return fail("failure_constraint must be finite and > 0");
  return true;
}

}  // namespace orni::opt
