// RAII wrapper around SUNDIALS ARKODE ARKStep for an implicit-explicit split with a linear,
// constant implicit part (structure.md 5.2): y' = f_E(t, y) + L y. The stiff linear part (the
// wing's modal stiffness and damping) is integrated by the ESDIRK half of an additive Runge-Kutta
// pair, everything else explicitly. The implicit stage equations (I - gamma L) z = b are solved
// exactly by a user function, called from a one-shot SUNNonlinearSolver (no Newton iteration,
// SUNMatrix or SUNLinearSolver), so the whole step stays allocation-free.
//
// Same interface and error channels as ErkIntegrator: no exception crosses a C callback; the
// wrapper stores it and re-throws after the C call returns.
#pragma once

#include <exception>
#include <string>

#include "core/integrate/erk_integrator.hpp"

namespace orni {

/// x = (I - gamma L)^{-1} b for the implicit part L (n values each). Return 0 on success, > 0 for
/// a recoverable failure, < 0 to abort. Must not throw.
using LinearSolveFunction = int (*)(double gamma, const double* b, double* x, void* user_data);

/// The linear implicit part L of the split. `apply` computes ydot = L y; L must depend neither on
/// t nor on y (ARKStep is told the implicit part is linear with a constant Jacobian).
struct LinearImplicitPart {
  RhsFunction apply = nullptr;
  LinearSolveFunction solve = nullptr;
};

/// Additive Runge-Kutta pairs of Kennedy and Carpenter (explicit table + ESDIRK table).
enum class ImexMethod { kArk324, kArk436, kArk437, kArk548 };

class ImexIntegrator {
 public:
  /// `opts.method` (an ERK table) is ignored; `method` selects the additive pair.
  ImexIntegrator(int state_size, RhsFunction explicit_rhs, LinearImplicitPart implicit,
                 void* user_data, const IntegratorOptions& opts,
                 ImexMethod method = ImexMethod::kArk437);
  ~ImexIntegrator();
  ImexIntegrator(const ImexIntegrator&) = delete;
  ImexIntegrator& operator=(const ImexIntegrator&) = delete;

  void reset(double t0, const double* y0);
  IntegratorStatus advanceTo(double tout);

  const double* state() const;
  double time() const { return t_; }
  int size() const { return n_; }
  long steps() const;
  long rhsEvaluations() const;       ///< explicit-part evaluations (the expensive ones)
  long stageSolves() const { return stage_solves_; }  ///< (I - gamma L) solves
  long stepAttempts() const;
  const std::string& lastError() const { return last_error_; }

 private:
  friend struct ImexCallback;
  int n_;
  RhsFunction fe_;
  LinearImplicitPart fi_;
  void* user_;
  ImexMethod method_;
  void* context_ = nullptr;  // SUNContext
  void* y_ = nullptr;        // N_Vector
  void* atol_ = nullptr;     // N_Vector
  void* nls_ = nullptr;      // SUNNonlinearSolver (one exact linear solve per stage)
  void* work_ = nullptr;     // N_Vector: right-hand side of the stage solve
  long stage_solves_ = 0;
  void* mem_ = nullptr;      // ARKStep memory
  double t_ = 0.0;
  std::exception_ptr pending_;
  std::string last_error_;
  IntegratorOptions opts_;
};

}  // namespace orni
