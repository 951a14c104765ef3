#include "core/integrate/linear_stage_solver.hpp"

#include <arkode/arkode_arkstep.h>

#include <stdexcept>

namespace orni::detail {

namespace {
SUNNonlinearSolver_Type rootFindType(SUNNonlinearSolver) { return SUNNONLINEARSOLVER_ROOTFIND; }
int acceptSysFn(SUNNonlinearSolver, SUNNonlinSolSysFn) { return SUN_NLS_SUCCESS; }
int acceptSetupFn(SUNNonlinearSolver, SUNNonlinSolLSetupFn) { return SUN_NLS_SUCCESS; }
int acceptSolveFn(SUNNonlinearSolver, SUNNonlinSolLSolveFn) { return SUN_NLS_SUCCESS; }
int acceptConvTest(SUNNonlinearSolver, SUNNonlinSolConvTestFn, void*) { return SUN_NLS_SUCCESS; }
int acceptMaxIters(SUNNonlinearSolver, int) { return SUN_NLS_SUCCESS; }
int curIter(SUNNonlinearSolver, int* iter) {
  *iter = 0;
  return SUN_NLS_SUCCESS;
}
int noConvFails(SUNNonlinearSolver, long* fails) {
  *fails = 0;
  return SUN_NLS_SUCCESS;
}
int freeSolver(SUNNonlinearSolver nls) {
  if (!nls) return SUN_NLS_SUCCESS;
  nls->content = nullptr;
  SUNNonlinSolFreeEmpty(nls);
  return SUN_NLS_SUCCESS;
}
}  // namespace

// The C callbacks (SUNNonlinSolSolve, SUNNonlinSolGetNumIters). Catch everything: no exception
// crosses SUNDIALS.
struct StageCallback {
  // ycor = (I - gamma L)^{-1} (zpred + sdata) - zpred.
  static int solveStage(SUNNonlinearSolver nls, N_Vector, N_Vector ycor, N_Vector, sunrealtype,
                        sunbooleantype, void*) {
    auto* self = static_cast<LinearStageSolver*>(nls->content);
    try {
      sunrealtype t = 0.0, gamma = 0.0;
      N_Vector zpred = nullptr, z = nullptr, fi = nullptr, sdata = nullptr;
      void* user = nullptr;
      if (ARKStepGetNonlinearSystemData(self->mem_, &t, &zpred, &z, &fi, &gamma, &sdata, &user) !=
          ARK_SUCCESS)
        return -1;
      const double* zp = N_VGetArrayPointer(zpred);
      const double* sd = N_VGetArrayPointer(sdata);
      double* b = N_VGetArrayPointer(self->work_);
      double* x = N_VGetArrayPointer(ycor);
      const int n = self->n_;
      for (int i = 0; i < n; ++i) {
        b[i] = zp[i] + sd[i];
        x[i] = zp[i];  // the predictor: a nonlinear stage solve's starting guess
      }
      const int rc = self->solve_(gamma, b, x, self->user_);
      if (rc != 0) return rc > 0 ? SUN_NLS_CONV_RECVR : -1;
      for (int i = 0; i < n; ++i) x[i] -= zp[i];
      ++self->solves_;
      return SUN_NLS_SUCCESS;
    } catch (...) {
      *self->pending_ = std::current_exception();
      return -1;
    }
  }
  static int numIters(SUNNonlinearSolver nls, long* iters) {
    *iters = static_cast<LinearStageSolver*>(nls->content)->solves_;
    return SUN_NLS_SUCCESS;
  }
};

LinearStageSolver::LinearStageSolver(SUNContext context, N_Vector like, LinearSolveFunction solve,
                                     void* user, std::exception_ptr* pending)
    : n_(static_cast<int>(N_VGetLength(like))), solve_(solve), user_(user), pending_(pending) {
  work_ = N_VClone(like);
  nls_ = SUNNonlinSolNewEmpty(context);
  if (!nls_ || !work_) {
    if (nls_) SUNNonlinSolFreeEmpty(nls_);
    if (work_) N_VDestroy(work_);
    throw std::runtime_error("SUNNonlinSolNewEmpty failed");
  }
  nls_->ops->gettype = &rootFindType;
  nls_->ops->solve = &StageCallback::solveStage;
  nls_->ops->free = &freeSolver;
  nls_->ops->setsysfn = &acceptSysFn;
  nls_->ops->setlsetupfn = &acceptSetupFn;
  nls_->ops->setlsolvefn = &acceptSolveFn;
  nls_->ops->setctestfn = &acceptConvTest;
  nls_->ops->setmaxiters = &acceptMaxIters;
  nls_->ops->getnumiters = &StageCallback::numIters;
  nls_->ops->getcuriter = &curIter;
  nls_->ops->getnumconvfails = &noConvFails;
  nls_->content = this;
}

LinearStageSolver::~LinearStageSolver() {
  SUNNonlinSolFree(nls_);
  N_VDestroy(work_);
}

SUNNonlinearSolver LinearStageSolver::attachTo(void* arkstep_mem) {
  mem_ = arkstep_mem;
  return nls_;
}

}  // namespace orni::detail
