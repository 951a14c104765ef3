#include "core/integrate/imex_integrator.hpp"

#include <arkode/arkode_arkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "core/integrate/callback_guard.hpp"
#include "core/integrate/serial_vector_ops.hpp"

namespace orni {

namespace {
SUNContext asContext(void* p) { return static_cast<SUNContext>(p); }
N_Vector asVector(void* p) { return static_cast<N_Vector>(p); }
SUNNonlinearSolver asSolver(void* p) { return static_cast<SUNNonlinearSolver>(p); }

// The stage solver: a SUNNonlinearSolver that solves the linear stage equation in one step.
// ARKStep's stage equation (arkStep_NlsResidual) is zcor - sdata - gamma f_I(zpred + zcor) = 0;
// with f_I = L y that is z - gamma L z = zpred + sdata for z = zpred + zcor, solved exactly by the
// user's (I - gamma L)^{-1}. No Newton iteration, convergence test or SUNMatrix: what ARKStep's
// generic Newton path costs here (several weighted norms and vector updates per stage) is more
// than the modal solve itself.
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

// The C callbacks (ARKRhsFn and SUNNonlinSolSolve). Catch everything: no exception crosses
// SUNDIALS.
struct ImexCallback {
  static int call(ImexIntegrator* self, RhsFunction f, sunrealtype t, N_Vector y, N_Vector ydot) {
    return detail::guardedRhs(f, t, y, ydot, self->n_, self->user_, &self->pending_);
  }
  static int explicitRhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) {
    auto* self = static_cast<ImexIntegrator*>(user_data);
    return call(self, self->fe_, t, y, ydot);
  }
  static int implicitRhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) {
    auto* self = static_cast<ImexIntegrator*>(user_data);
    return call(self, self->fi_.apply, t, y, ydot);
  }
  // ycor = (I - gamma L)^{-1} (zpred + sdata) - zpred.
  static int solveStage(SUNNonlinearSolver nls, N_Vector, N_Vector ycor, N_Vector, sunrealtype,
                        sunbooleantype, void*) {
    auto* self = static_cast<ImexIntegrator*>(nls->content);
    try {
      sunrealtype t = 0.0, gamma = 0.0;
      N_Vector zpred = nullptr, z = nullptr, fi = nullptr, sdata = nullptr;
      void* user = nullptr;
      if (ARKStepGetNonlinearSystemData(self->mem_, &t, &zpred, &z, &fi, &gamma, &sdata, &user) !=
          ARK_SUCCESS)
        return -1;
      const double* zp = N_VGetArrayPointer(zpred);
      const double* sd = N_VGetArrayPointer(sdata);
      double* b = N_VGetArrayPointer(asVector(self->work_));
      double* x = N_VGetArrayPointer(ycor);
      const int n = self->n_;
      for (int i = 0; i < n; ++i) b[i] = zp[i] + sd[i];
      const int rc = self->fi_.solve(gamma, b, x, self->user_);
      if (rc != 0) return rc > 0 ? SUN_NLS_CONV_RECVR : -1;
      for (int i = 0; i < n; ++i) x[i] -= zp[i];
      ++self->stage_solves_;
      return SUN_NLS_SUCCESS;
    } catch (...) {
      self->pending_ = std::current_exception();
      return -1;
    }
  }
  static int numIters(SUNNonlinearSolver nls, long* iters) {
    *iters = static_cast<ImexIntegrator*>(nls->content)->stage_solves_;
    return SUN_NLS_SUCCESS;
  }
};

ImexIntegrator::ImexIntegrator(int state_size, RhsFunction explicit_rhs,
                               LinearImplicitPart implicit, void* user_data,
                               const IntegratorOptions& opts, ImexMethod method)
    : n_(state_size), fe_(explicit_rhs), fi_(implicit), user_(user_data), method_(method),
      opts_(opts) {
  std::string why;
  if (state_size < 1) throw std::invalid_argument("ImexIntegrator: state size must be >= 1");
  if (!fe_ || !fi_.apply || !fi_.solve)
    throw std::invalid_argument("ImexIntegrator: explicit rhs, implicit part and solve needed");
  if (!opts.IsValid(state_size, &why)) throw std::invalid_argument("ImexIntegrator: " + why);
  SUNContext c = nullptr;
  if (SUNContext_Create(nullptr, &c) != 0) throw std::runtime_error("SUNContext_Create failed");
  context_ = c;
  y_ = N_VNew_Serial(n_, c);
  atol_ = N_VNew_Serial(n_, c);
  if (!y_ || !atol_) throw std::runtime_error("N_VNew_Serial failed");
  detail::installSinglePassOps(asVector(y_));
  double* a = N_VGetArrayPointer(asVector(atol_));
  for (int i = 0; i < n_; ++i) a[i] = opts.abs_tol[static_cast<std::size_t>(i)];
  N_VConst(0.0, asVector(y_));
  work_ = N_VClone(asVector(y_));
  SUNNonlinearSolver nls = SUNNonlinSolNewEmpty(c);
  if (!nls || !work_) throw std::runtime_error("SUNNonlinSolNewEmpty failed");
  nls->ops->gettype = &rootFindType;
  nls->ops->solve = &ImexCallback::solveStage;
  nls->ops->free = &freeSolver;
  nls->ops->setsysfn = &acceptSysFn;
  nls->ops->setlsetupfn = &acceptSetupFn;
  nls->ops->setlsolvefn = &acceptSolveFn;
  nls->ops->setctestfn = &acceptConvTest;
  nls->ops->setmaxiters = &acceptMaxIters;
  nls->ops->getnumiters = &ImexCallback::numIters;
  nls->ops->getcuriter = &curIter;
  nls->ops->getnumconvfails = &noConvFails;
  nls->content = this;
  nls_ = nls;
}

ImexIntegrator::~ImexIntegrator() {
  if (mem_) ARKStepFree(&mem_);
  if (nls_) SUNNonlinSolFree(asSolver(nls_));
  if (work_) N_VDestroy(asVector(work_));
  if (atol_) N_VDestroy(asVector(atol_));
  if (y_) N_VDestroy(asVector(y_));
  if (context_) {
    SUNContext c = asContext(context_);
    SUNContext_Free(&c);
  }
}

void ImexIntegrator::reset(double t0, const double* y0) {
  double* y = N_VGetArrayPointer(asVector(y_));
  for (int i = 0; i < n_; ++i) y[i] = y0[i];
  t_ = t0;
  if (mem_) {
    ARKStepReset(mem_, t0, asVector(y_));
    return;
  }
  mem_ = ARKStepCreate(&ImexCallback::explicitRhs, &ImexCallback::implicitRhs, t0, asVector(y_),
                       asContext(context_));
  if (!mem_) throw std::runtime_error("ARKStepCreate failed");
  ARKStepSetUserData(mem_, this);
  ARKStepSVtolerances(mem_, opts_.rel_tol, asVector(atol_));
  ARKODE_DIRKTableID dirk = ARKODE_ARK437L2SA_DIRK_7_3_4;
  ARKODE_ERKTableID erk = ARKODE_ARK437L2SA_ERK_7_3_4;
  if (method_ == ImexMethod::kArk324) {
    dirk = ARKODE_ARK324L2SA_DIRK_4_2_3;
    erk = ARKODE_ARK324L2SA_ERK_4_2_3;
  } else if (method_ == ImexMethod::kArk436) {
    dirk = ARKODE_ARK436L2SA_DIRK_6_3_4;
    erk = ARKODE_ARK436L2SA_ERK_6_3_4;
  } else if (method_ == ImexMethod::kArk548) {
    dirk = ARKODE_ARK548L2SAb_DIRK_8_4_5;
    erk = ARKODE_ARK548L2SAb_ERK_8_4_5;
  }
  if (ARKStepSetTableNum(mem_, dirk, erk) != ARK_SUCCESS)
    throw std::runtime_error("ARKStepSetTableNum failed");
  if (ARKStepSetNonlinearSolver(mem_, asSolver(nls_)) != ARK_SUCCESS)
    throw std::runtime_error("ARKStepSetNonlinearSolver failed");
  // The stage solve is exact: the implicit RHS of a stage follows from its solution.
  ARKStepSetDeduceImplicitRhs(mem_, SUNTRUE);
  ARKStepSetMaxNumSteps(mem_, opts_.max_steps);
  if (opts_.max_step > 0.0) ARKStepSetMaxStep(mem_, opts_.max_step);
}

IntegratorStatus ImexIntegrator::advanceTo(double tout) {
  if (!mem_) throw std::logic_error("ImexIntegrator::advanceTo before reset");
  sunrealtype t_reached = t_;
  const int flag = ARKStepEvolve(mem_, tout, asVector(y_), &t_reached, ARK_NORMAL);
  detail::rethrowPending(&pending_);
  t_ = t_reached;
  if (flag < 0) {
    // The flag name is malloc'ed by SUNDIALS (6.x): the caller frees it.
    char* name = ARKStepGetReturnFlagName(flag);
    last_error_ = std::string("ARKODE ARKStep failed at t = ") + std::to_string(t_reached) +
                  " s: " + (name ? name : "unknown flag");
    std::free(name);
    return IntegratorStatus::kFailed;
  }
  return IntegratorStatus::kOk;
}

const double* ImexIntegrator::state() const { return N_VGetArrayPointer(asVector(y_)); }

long ImexIntegrator::steps() const {
  long n = 0;
  if (mem_) ARKStepGetNumSteps(mem_, &n);
  return n;
}

long ImexIntegrator::stepAttempts() const {
  long n = 0;
  if (mem_) ARKStepGetNumStepAttempts(mem_, &n);
  return n;
}

long ImexIntegrator::rhsEvaluations() const {
  long fe = 0, fi = 0;
  if (mem_) ARKStepGetNumRhsEvals(mem_, &fe, &fi);
  return fe;
}

}  // namespace orni
