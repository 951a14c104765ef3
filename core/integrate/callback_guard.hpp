// The guard between a SUNDIALS callback and our right-hand side (docs/design.md 7.7; internal to
// core/integrate): no exception crosses the C call, a non-finite derivative is a recoverable
// failure (the integrator retries with a smaller step).
#pragma once

#include <nvector/nvector_serial.h>

#include <cmath>
#include <exception>

#include "core/integrate/integrator_options.hpp"

namespace orni::detail {

/// f(t, y) into ydot (n values). Returns f's code, 1 for a non-finite derivative, or -1 with the
/// exception stored in *pending.
inline int guardedRhs(RhsFunction f, sunrealtype t, N_Vector y, N_Vector ydot, int n, void* user,
                      std::exception_ptr* pending) {
  try {
    const int rc = f(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), user);
    if (rc != 0) return rc;
    const double* d = N_VGetArrayPointer(ydot);
    for (int i = 0; i < n; ++i)
      if (!std::isfinite(d[i])) return 1;
    return 0;
  } catch (...) {
    *pending = std::current_exception();
    return -1;
  }
}

/// After the C call returned: re-throw what a callback stored.
inline void rethrowPending(std::exception_ptr* pending) {
  if (!*pending) return;
  std::exception_ptr e = *pending;
  *pending = nullptr;
  std::rethrow_exception(e);
}

}  // namespace orni::detail
