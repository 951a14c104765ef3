// What every ODE integration of the project is given (core/integrate): the right-hand side as a
// plain function pointer (no virtual call, no std::function in the hot path), the linear implicit
// part of an implicit-explicit split, and the tolerances and step limits (docs/theory.md 9.2).
// The integrators themselves: OdeIntegrator (SUNDIALS ARKODE, ode_integrator.hpp) and
// GridRungeKutta (a recorded step grid, grid_runge_kutta.hpp).
#pragma once

#include <string>
#include <vector>

namespace orni {

/// dy/dt = f(t, y). Return 0 on success, > 0 for a recoverable failure (the step is retried with
/// a smaller size), < 0 to abort. Must not throw (the integrator guards it anyway).
using RhsFunction = int (*)(double t, const double* y, double* ydot, void* user_data);

/// x = (I - gamma L)^{-1} b for the implicit part L (n values each); for an implicit part that is
/// not linear, x - gamma f_I(x) = b, with x holding a starting guess on entry (the stage's
/// predictor). Return 0 on success, > 0 for a recoverable failure (the step is retried smaller),
/// < 0 to abort. Must not throw.
using LinearSolveFunction = int (*)(double gamma, const double* b, double* x, void* user_data);

/// The linear implicit part L of an implicit-explicit split y' = f_E(t, y) + L y. `apply` computes
/// ydot = L y; L must depend neither on t nor on y (ARKStep is told the implicit part is linear
/// with a constant Jacobian).
/// Called with the state at the start of an integration and after every accepted step; L may
/// change there (never inside a step, so every step is one additive Runge-Kutta step of a fixed
/// split f = (f - L y) + L y, whatever L is). Returns 0, or non-zero to stop the integration.
using StepFunction = int (*)(double t, const double* y, void* user_data);

struct LinearImplicitPart {
  RhsFunction apply = nullptr;
  LinearSolveFunction solve = nullptr;
  StepFunction update = nullptr;  ///< optional: re-linearise L about the accepted state
};

/// Tolerances and step limits of an OdeIntegrator (the method is an IntegrationMethod).
struct IntegratorOptions {
  double rel_tol = 1e-6;
  std::vector<double> abs_tol;  ///< one per state, > 0
  long max_steps = 1000000;     ///< per advanceTo() call
  double max_step = 0.0;        ///< 0 = unlimited

  bool IsValid(int state_size, std::string* why) const;
};

enum class IntegratorStatus { kOk, kFailed };

}  // namespace orni
