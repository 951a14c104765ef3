// The stage solver of the implicit-explicit method (internal to core/integrate): a
// SUNNonlinearSolver that solves ARKStep's linear stage equation in one step.
// ARKStep's stage equation (arkStep_NlsResidual) is zcor - sdata - gamma f_I(zpred + zcor) = 0;
// with f_I = L y that is z - gamma L z = zpred + sdata for z = zpred + zcor, solved exactly by the
// user's (I - gamma L)^{-1}. No Newton iteration, convergence test, SUNMatrix or SUNLinearSolver:
// what ARKStep's generic Newton path costs here (several weighted norms and vector updates per
// stage) is more than the modal solve itself. No allocation after construction.
#pragma once

#include <nvector/nvector_serial.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <exception>

#include "core/integrate/integrator_options.hpp"

namespace orni::detail {

class LinearStageSolver {
 public:
  /// `like`: a vector of the state's size and operations (the work vector is cloned from it).
  /// `solve(gamma, b, x, user)` is the implicit part's exact solve; an exception it throws is
  /// stored in *pending (no exception crosses SUNDIALS) and the solve fails.
  LinearStageSolver(SUNContext context, N_Vector like, LinearSolveFunction solve, void* user,
                    std::exception_ptr* pending);
  ~LinearStageSolver();
  LinearStageSolver(const LinearStageSolver&) = delete;
  LinearStageSolver& operator=(const LinearStageSolver&) = delete;

  /// The solver for ARKStepSetNonlinearSolver on the ARKStep memory `arkstep_mem`.
  SUNNonlinearSolver attachTo(void* arkstep_mem);
  long solves() const { return solves_; }  ///< (I - gamma L) solves so far

 private:
  friend struct StageCallback;
  int n_;
  LinearSolveFunction solve_;
  void* user_;
  std::exception_ptr* pending_;
  void* mem_ = nullptr;  // ARKStep memory
  N_Vector work_ = nullptr;  // right-hand side of the stage solve
  SUNNonlinearSolver nls_ = nullptr;
  long solves_ = 0;
};

}  // namespace orni::detail
