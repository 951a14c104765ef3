// RAII wrapper around SUNDIALS ARKODE ERKStep (explicit Runge-Kutta, Dormand-Prince 5(4) by
// default; structure.md 5.2-5.3). Owns the SUNContext, the state vector and the integrator memory.
//
// The right-hand side is a plain function pointer (no virtual call, no std::function in the hot
// path). No exception crosses the C callback (style.md habit 7): the trampoline catches, stores
// the exception and returns an error code; advanceTo() re-throws it after the C call returns.
#pragma once

#include <exception>
#include <string>
#include <vector>

namespace orni {

/// dy/dt = f(t, y). Return 0 on success, > 0 for a recoverable failure (the step is retried with
/// a smaller size), < 0 to abort. Must not throw (the wrapper guards it anyway).
using RhsFunction = int (*)(double t, const double* y, double* ydot, void* user_data);

/// Butcher tables. kArk436 is the explicit table of Kennedy and Carpenter's ARK4(3)6L[2]SA: on the
/// flexible wing and in free flight, where the step is limited by the stability of the modes and
/// the tip-strip lag states rather than by accuracy, it needs a third fewer RHS evaluations than
/// Dormand-Prince for the same cycle means (measured on the magpie: 2933 vs 4441 evaluations for
/// 10 free cycles, 3423 vs 4441 tethered); on the rigid RFW rig Dormand-Prince is better (1363 vs
/// 1778).
enum class ErkMethod { kDormandPrince5, kVerner6, kFehlberg8, kBogackiShampine3, kArk436 };

struct IntegratorOptions {
  ErkMethod method = ErkMethod::kDormandPrince5;
  double rel_tol = 1e-6;
  std::vector<double> abs_tol;  ///< one per state, > 0
  long max_steps = 1000000;     ///< per advanceTo() call
  double max_step = 0.0;        ///< 0 = unlimited

  bool IsValid(int state_size, std::string* why) const;
};

enum class IntegratorStatus { kOk, kFailed };

class ErkIntegrator {
 public:
  ErkIntegrator(int state_size, RhsFunction rhs, void* user_data, const IntegratorOptions& opts);
  ~ErkIntegrator();
  ErkIntegrator(const ErkIntegrator&) = delete;
  ErkIntegrator& operator=(const ErkIntegrator&) = delete;

  /// Restart at t0 from y0 (state_size values).
  void reset(double t0, const double* y0);
  /// Integrate to tout (interpolating if the integrator stepped past it). On failure the status
  /// is kFailed and lastError() says why; an exception thrown by the RHS is re-thrown.
  IntegratorStatus advanceTo(double tout);

  const double* state() const;  ///< state at time()
  double time() const { return t_; }
  int size() const { return n_; }
  long steps() const;
  long rhsEvaluations() const;
  long stepAttempts() const;
  const std::string& lastError() const { return last_error_; }

 private:
  friend struct ErkCallback;
  int n_;
  RhsFunction rhs_;
  void* user_;
  void* context_ = nullptr;  // SUNContext
  void* y_ = nullptr;        // N_Vector
  void* atol_ = nullptr;     // N_Vector
  void* mem_ = nullptr;      // ERKStep memory
  double t_ = 0.0;
  std::exception_ptr pending_;
  std::string last_error_;
  IntegratorOptions opts_;
};

}  // namespace orni
