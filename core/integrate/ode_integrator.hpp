// The ODE integrator of the flight simulations: an RAII wrapper around SUNDIALS ARKODE
// (docs/theory.md 9.2) that owns the SUNContext, the state vector and the stepper memory. The
// IntegrationMethod it is built with (integration_method.hpp) is the only difference between its
// runs: an explicit Runge-Kutta table (ERKStep) or the implicit-explicit split with a linear
// implicit part (ARKStep, the stage equations solved exactly in one step by
// linear_stage_solver.hpp, no Newton iteration, SUNMatrix or SUNLinearSolver). Set-up, advanceTo,
// the counters and the error path are one code for both; every step stays allocation-free.
//
// No exception crosses a C callback (docs/design.md 7.7, callback_guard.hpp): the callback catches,
// stores the exception and returns an error code; advanceTo() re-throws it after the C call
// returns. A non-finite derivative is a recoverable failure (the step is retried smaller).
#pragma once

#include <exception>
#include <memory>
#include <string>

#include "core/integrate/integration_method.hpp"
#include "core/integrate/integrator_options.hpp"

namespace orni {

namespace detail {
class LinearStageSolver;
struct ArkodeStepper;
}  // namespace detail

class OdeIntegrator {
 public:
  /// dy/dt = rhs(t, y), plus L y when `method` is implicit-explicit (rhs is then the explicit
  /// part). `user_data` goes to rhs and to the implicit part.
  OdeIntegrator(int state_size, RhsFunction rhs, void* user_data, const IntegrationMethod& method,
                const IntegratorOptions& opts);
  ~OdeIntegrator();
  OdeIntegrator(const OdeIntegrator&) = delete;
  OdeIntegrator& operator=(const OdeIntegrator&) = delete;

  /// Restart at t0 from y0 (state_size values).
  void reset(double t0, const double* y0);
  /// Integrate to tout (interpolating if the integrator stepped past it). On failure the status
  /// is kFailed and lastError() says why; an exception thrown by a callback is re-thrown.
  IntegratorStatus advanceTo(double tout);

  const double* state() const;  ///< state at time()
  /// dy/dt at time() from the dense output that gave state() (ARKODE's Hermite interpolant of
  /// the last step, differentiated): at an accepted step's end the right-hand side there, in
  /// between a polynomial through the two ends' values consistent with the step's increment.
  /// No right-hand side evaluation; valid until the next advanceTo. Null before the first step
  /// after reset (no interpolant yet).
  const double* derivative();
  double time() const { return t_; }
  int size() const { return n_; }
  long steps() const;
  long rhsEvaluations() const;  ///< of rhs (the explicit part: the expensive one)
  long stepAttempts() const;
  long stageSolves() const;     ///< (I - gamma L) solves; 0 for an explicit method
  /// Restarts from the last accepted step after a right-hand side failed past a stage solve
  /// (advanceTo; the implicit part with a post-step update only).
  int restarts() const { return restarts_; }
  const std::string& lastError() const { return last_error_; }
  const IntegrationMethod& method() const { return method_; }
  /// "ARKODE ERKStep <table>" or "ARKODE ARKStep <pair> (IMEX, ...)", for the summaries.
  std::string methodName() const { return method_.name(); }

 private:
  friend struct OdeCallback;
  int n_;
  RhsFunction rhs_;
  void* user_;
  IntegrationMethod method_;
  IntegratorOptions opts_;
  const detail::ArkodeStepper* stepper_;  // ERKStep or ARKStep calls, from method_
  void* context_ = nullptr;  // SUNContext
  void* y_ = nullptr;        // N_Vector
  void* atol_ = nullptr;     // N_Vector
  void* dky_ = nullptr;      // N_Vector: derivative()'s
  std::unique_ptr<detail::LinearStageSolver> stage_solver_;  // implicit-explicit only
  void* mem_ = nullptr;      // ERKStep or ARKStep memory
  double t_ = 0.0;
  double last_accepted_t_ = 0.0;  // of the last accepted step (post-step update hook)
  int restarts_ = 0;
  std::exception_ptr pending_;
  std::string last_error_;
  std::string arkode_message_;  // SUNDIALS's last error message (storeError), for last_error_
};

}  // namespace orni
