#include "core/integrate/integrator_options.hpp"

namespace orni {

bool IntegratorOptions::IsValid(int state_size, std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (!(rel_tol > 0.0 && rel_tol < 1.0)) return fail("rel_tol must be in (0, 1)");
  if (static_cast<int>(abs_tol.size()) != state_size)
    return fail("abs_tol must have one entry per state");
  for (double a : abs_tol)
    if (!(a > 0.0)) return fail("abs_tol entries must be > 0");
  if (max_steps < 1) return fail("max_steps must be >= 1");
  if (max_step < 0.0) return fail("max_step must be >= 0");
  return true;
}

}  // namespace orni
