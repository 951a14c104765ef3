// One handle for the two integrators of the flight simulations: explicit Runge-Kutta (ERKStep) or
// the implicit-explicit split with a linear implicit part (ARKStep). The simulation loops are the
// same for both; the choice is made once when the integrator is built.
#pragma once

#include <memory>
#include <string>

#include "core/integrate/erk_integrator.hpp"
#include "core/integrate/imex_integrator.hpp"

namespace orni {

class OdeIntegrator {
 public:
  /// Explicit: dy/dt = rhs(t, y) with the table opts.method.
  OdeIntegrator(int state_size, RhsFunction rhs, void* user_data, const IntegratorOptions& opts);
  /// Implicit-explicit: dy/dt = explicit_rhs(t, y) + L y (imex_integrator.hpp).
  OdeIntegrator(int state_size, RhsFunction explicit_rhs, LinearImplicitPart implicit,
                void* user_data, const IntegratorOptions& opts,
                ImexMethod method = ImexMethod::kArk437);

  void reset(double t0, const double* y0);
  IntegratorStatus advanceTo(double tout);
  const double* state() const;
  double time() const;
  long steps() const;
  long rhsEvaluations() const;  ///< of the (explicit part of the) right-hand side
  long stepAttempts() const;
  const std::string& lastError() const;
  /// "ARKODE ERKStep <table>" or "ARKODE ARKStep <pair> (IMEX, ...)", for the summaries.
  const std::string& methodName() const { return name_; }

 private:
  std::unique_ptr<ErkIntegrator> erk_;
  std::unique_ptr<ImexIntegrator> imex_;
  std::string name_;
};

}  // namespace orni
