#include "core/integrate/ode_integrator.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <cstdlib>
#include <stdexcept>

#include "core/integrate/callback_guard.hpp"
#include "core/integrate/linear_stage_solver.hpp"
#include "core/integrate/serial_vector_ops.hpp"

namespace orni {

namespace {
SUNContext asContext(void* p) { return static_cast<SUNContext>(p); }
N_Vector asVector(void* p) { return static_cast<N_Vector>(p); }
}  // namespace

// The C callbacks (ARKRhsFn). Catch everything: no exception crosses SUNDIALS.
struct OdeCallback {
  static int call(OdeIntegrator* self, RhsFunction f, sunrealtype t, N_Vector y, N_Vector ydot) {
    return detail::guardedRhs(f, t, y, ydot, self->n_, self->user_, &self->pending_);
  }
  static int explicitRhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) {
    auto* self = static_cast<OdeIntegrator*>(user_data);
    return call(self, self->rhs_, t, y, ydot);
  }
  static int implicitRhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) {
    auto* self = static_cast<OdeIntegrator*>(user_data);
    return call(self, self->method_.linearPart().apply, t, y, ydot);
  }
  // ARKODE's error and warning messages (ARKErrHandlerFn): kept for lastError().
  static void storeError(int, const char* module, const char* function, char* msg,
                         void* user_data) {
    auto* self = static_cast<OdeIntegrator*>(user_data);
    self->arkode_message_ = std::string(module ? module : "") + "::" +
                            (function ? function : "") + ": " + (msg ? msg : "");
  }
  // ARKODE's post-processing of an accepted step: the linear part's update (the split changes
  // between steps only; SUNDIALS 6.4 evaluates every stage of a step, the first included, after
  // this call, so no stage value of the old split is reused).
  static int updateLinearPart(sunrealtype t, N_Vector y, void* user_data) {
    auto* self = static_cast<OdeIntegrator*>(user_data);
    self->last_accepted_t_ = t;
    try {
      return self->method_.linearPart().update(t, N_VGetArrayPointer(y), self->user_);
    } catch (...) {
      self->pending_ = std::current_exception();
      return -1;
    }
  }
};

namespace detail {

// The ARKODE calls of one stepper module. SUNDIALS 6 has the same calls under two prefixes
// (ERKStep, ARKStep); what differs is creation, the method's configuration and the counter of
// right-hand sides. Set-up order (both): create, user data, tolerances, configure, step limits.
struct ArkodeStepper {
  const char* module;  // "ERKStep" or "ARKStep", for the error messages
  void* (*create)(sunrealtype t0, N_Vector y, SUNContext context);
  // The method's own settings: the Butcher table(s); for ARKStep the stage solver.
  void (*configure)(void* mem, const IntegrationMethod& method, LinearStageSolver* stage_solver);
  int (*set_user_data)(void* mem, void* user_data);
  int (*set_err_handler)(void* mem, ARKErrHandlerFn handler, void* user_data);
  int (*sv_tolerances)(void* mem, sunrealtype rel_tol, N_Vector abs_tol);
  int (*set_max_num_steps)(void* mem, long max_steps);
  int (*set_max_step)(void* mem, sunrealtype max_step);
  int (*reset)(void* mem, sunrealtype t0, N_Vector y0);
  int (*evolve)(void* mem, sunrealtype tout, N_Vector yout, sunrealtype* tret, int itask);
  int (*num_steps)(void* mem, long* n);
  int (*num_step_attempts)(void* mem, long* n);
  int (*num_rhs_evals)(void* mem, long* n);  // of the explicit part
  char* (*flag_name)(long flag);             // malloc'ed by SUNDIALS (6.x): the caller frees it
  void (*free)(void** mem);
  int (*get_dky)(void* mem, sunrealtype t, int k, N_Vector dky);  // dense output's k-th derivative
};

namespace {

void configureErk(void* mem, const IntegrationMethod& method, LinearStageSolver*) {
  ARKODE_ERKTableID table = ARKODE_DORMAND_PRINCE_7_4_5;
  switch (method.explicitTable()) {
    case ErkMethod::kDormandPrince5: table = ARKODE_DORMAND_PRINCE_7_4_5; break;
    case ErkMethod::kVerner6: table = ARKODE_VERNER_8_5_6; break;
    case ErkMethod::kFehlberg8: table = ARKODE_FEHLBERG_13_7_8; break;
    case ErkMethod::kBogackiShampine3: table = ARKODE_BOGACKI_SHAMPINE_4_2_3; break;
    case ErkMethod::kArk436: table = ARKODE_ARK436L2SA_ERK_6_3_4; break;
  }
  if (ERKStepSetTableNum(mem, table) != ARK_SUCCESS)
    throw std::runtime_error("ERKStepSetTableNum failed");
}

void configureArk(void* mem, const IntegrationMethod& method, LinearStageSolver* stage_solver) {
  ARKODE_DIRKTableID dirk = ARKODE_ARK437L2SA_DIRK_7_3_4;
  ARKODE_ERKTableID erk = ARKODE_ARK437L2SA_ERK_7_3_4;
  switch (method.additivePair()) {
    case ImexMethod::kArk324:
      dirk = ARKODE_ARK324L2SA_DIRK_4_2_3;
      erk = ARKODE_ARK324L2SA_ERK_4_2_3;
      break;
    case ImexMethod::kArk436:
      dirk = ARKODE_ARK436L2SA_DIRK_6_3_4;
      erk = ARKODE_ARK436L2SA_ERK_6_3_4;
      break;
    case ImexMethod::kArk437: break;
    case ImexMethod::kArk548:
      dirk = ARKODE_ARK548L2SAb_DIRK_8_4_5;
      erk = ARKODE_ARK548L2SAb_ERK_8_4_5;
      break;
  }
  if (ARKStepSetTableNum(mem, dirk, erk) != ARK_SUCCESS)
    throw std::runtime_error("ARKStepSetTableNum failed");
  if (ARKStepSetNonlinearSolver(mem, stage_solver->attachTo(mem)) != ARK_SUCCESS)
    throw std::runtime_error("ARKStepSetNonlinearSolver failed");
  // The stage solve is exact: the implicit RHS of a stage follows from its solution.
  ARKStepSetDeduceImplicitRhs(mem, SUNTRUE);
}

const ArkodeStepper kErkStep{
    "ERKStep",
    [](sunrealtype t0, N_Vector y, SUNContext c) {
      return ERKStepCreate(&OdeCallback::explicitRhs, t0, y, c);
    },
    &configureErk,
    &ERKStepSetUserData,
    &ERKStepSetErrHandlerFn,
    &ERKStepSVtolerances,
    &ERKStepSetMaxNumSteps,
    &ERKStepSetMaxStep,
    &ERKStepReset,
    &ERKStepEvolve,
    &ERKStepGetNumSteps,
    &ERKStepGetNumStepAttempts,
    &ERKStepGetNumRhsEvals,
    &ERKStepGetReturnFlagName,
    &ERKStepFree,
    &ERKStepGetDky};

const ArkodeStepper kArkStep{
    "ARKStep",
    [](sunrealtype t0, N_Vector y, SUNContext c) {
      return ARKStepCreate(&OdeCallback::explicitRhs, &OdeCallback::implicitRhs, t0, y, c);
    },
    &configureArk,
    &ARKStepSetUserData,
    &ARKStepSetErrHandlerFn,
    &ARKStepSVtolerances,
    &ARKStepSetMaxNumSteps,
    &ARKStepSetMaxStep,
    &ARKStepReset,
    &ARKStepEvolve,
    &ARKStepGetNumSteps,
    &ARKStepGetNumStepAttempts,
    [](void* mem, long* n) {
      long fi = 0;
      return ARKStepGetNumRhsEvals(mem, n, &fi);
    },
    &ARKStepGetReturnFlagName,
    &ARKStepFree,
    &ARKStepGetDky};

}  // namespace
}  // namespace detail

OdeIntegrator::OdeIntegrator(int state_size, RhsFunction rhs, void* user_data,
                             const IntegrationMethod& method, const IntegratorOptions& opts)
    : n_(state_size), rhs_(rhs), user_(user_data), method_(method), opts_(opts),
      stepper_(method.isImplicitExplicit() ? &detail::kArkStep : &detail::kErkStep) {
  std::string why;
  if (state_size < 1) throw std::invalid_argument("OdeIntegrator: state size must be >= 1");
  if (!rhs) throw std::invalid_argument("OdeIntegrator: a right-hand side is needed");
  if (!opts.IsValid(state_size, &why)) throw std::invalid_argument("OdeIntegrator: " + why);
  SUNContext c = nullptr;
  if (SUNContext_Create(nullptr, &c) != 0) throw std::runtime_error("SUNContext_Create failed");
  context_ = c;
  y_ = N_VNew_Serial(n_, c);
  atol_ = N_VNew_Serial(n_, c);
  dky_ = N_VNew_Serial(n_, c);
  if (!y_ || !atol_ || !dky_) throw std::runtime_error("N_VNew_Serial failed");
  // Single-pass linear combinations (set before the stepper clones the vector, so every work
  // vector inherits them): the integrator's own vector work is comparable to the RHS for ~60
  // states. dky_ too: the interpolant's derivative is a linear combination written into it.
  detail::installSinglePassOps(asVector(y_));
  detail::installSinglePassOps(asVector(dky_));
  double* a = N_VGetArrayPointer(asVector(atol_));
  for (int i = 0; i < n_; ++i) a[i] = opts.abs_tol[static_cast<std::size_t>(i)];
  N_VConst(0.0, asVector(y_));
  if (method.isImplicitExplicit())
    stage_solver_ = std::make_unique<detail::LinearStageSolver>(
        c, asVector(y_), method.linearPart().solve, user_, &pending_);
}

OdeIntegrator::~OdeIntegrator() {
  if (mem_) stepper_->free(&mem_);
  stage_solver_.reset();
  if (dky_) N_VDestroy(asVector(dky_));
  if (atol_) N_VDestroy(asVector(atol_));
  if (y_) N_VDestroy(asVector(y_));
  if (context_) {
    SUNContext c = asContext(context_);
    SUNContext_Free(&c);
  }
}

void OdeIntegrator::reset(double t0, const double* y0) {
  double* y = N_VGetArrayPointer(asVector(y_));
  if (y0 != y)
    for (int i = 0; i < n_; ++i) y[i] = y0[i];
  t_ = t0;
  last_accepted_t_ = t0;
  const StepFunction update = method_.isImplicitExplicit() ? method_.linearPart().update : nullptr;
  if (update && update(t0, y, user_) != 0)
    throw std::runtime_error("OdeIntegrator: the implicit part could not be set up at t0");
  if (mem_) {
    stepper_->reset(mem_, t0, asVector(y_));
    return;
  }
  mem_ = stepper_->create(t0, asVector(y_), asContext(context_));
  if (!mem_) throw std::runtime_error(std::string(stepper_->module) + "Create failed");
  stepper_->set_user_data(mem_, this);
  // SUNDIALS's messages go into lastError(), not to stderr: a library call stays quiet, and a
  // failure the integrator recovers from (the restart in advanceTo) leaves no trace on the
  // console.
  stepper_->set_err_handler(mem_, &OdeCallback::storeError, this);
  stepper_->sv_tolerances(mem_, opts_.rel_tol, asVector(atol_));
  stepper_->configure(mem_, method_, stage_solver_.get());
  stepper_->set_max_num_steps(mem_, opts_.max_steps);
  if (opts_.max_step > 0.0) stepper_->set_max_step(mem_, opts_.max_step);
  if (update && ARKStepSetPostprocessStepFn(mem_, &OdeCallback::updateLinearPart) != ARK_SUCCESS)
    throw std::runtime_error("ARKStepSetPostprocessStepFn failed");
}

IntegratorStatus OdeIntegrator::advanceTo(double tout) {
  if (!mem_) throw std::logic_error("OdeIntegrator::advanceTo before reset");
  sunrealtype t_reached = t_;
  arkode_message_.clear();
  int flag = stepper_->evolve(mem_, tout, asVector(y_), &t_reached, ARK_NORMAL);
  detail::rethrowPending(&pending_);
  t_ = t_reached;
  // SUNDIALS 6.4 cannot recover when the right-hand side fails (non-finite) after an accepted
  // stage solve (ARK_UNREC_RHSFUNC_ERR): a step too long for the explicit part's coupling to a
  // stiff implicit part can produce such a stage before the error test rejects it (measured: the
  // nonlinear-wing magpie in free flight, a stage with a body speed of 9990 m/s after 383 cycles).
  // With the post-step update attached (the nonlinear wing), the last accepted step is known:
  // restart there with a tenth of the last step, at most kMaxRestarts times per call. yout holds
  // the last accepted state on failure (arkEvolve copies y_n).
  constexpr int kMaxRestarts = 5;
  const bool hooked = method_.isImplicitExplicit() && method_.linearPart().update != nullptr;
  for (int restart = 0; hooked && flag == ARK_UNREC_RHSFUNC_ERR && restart < kMaxRestarts;
       ++restart) {
    sunrealtype h_last = 0.0;
    ARKStepGetLastStep(mem_, &h_last);
    ++restarts_;
    arkode_message_.clear();
    reset(last_accepted_t_, N_VGetArrayPointer(asVector(y_)));
    ARKStepSetInitStep(mem_, 0.1 * std::abs(h_last));
    t_reached = t_;
    flag = stepper_->evolve(mem_, tout, asVector(y_), &t_reached, ARK_NORMAL);
    detail::rethrowPending(&pending_);
    t_ = t_reached;
  }
  if (flag < 0) {
    char* name = stepper_->flag_name(flag);
    last_error_ = std::string("ARKODE ") + stepper_->module + " failed at t = " +
                  std::to_string(t_reached) + " s: " + (name ? name : "unknown flag");
    if (!arkode_message_.empty()) last_error_ += " (" + arkode_message_ + ")";
    std::free(name);
    return IntegratorStatus::kFailed;
  }
  return IntegratorStatus::kOk;
}

const double* OdeIntegrator::state() const { return N_VGetArrayPointer(asVector(y_)); }

const double* OdeIntegrator::derivative() {
  if (!mem_) throw std::logic_error("OdeIntegrator::derivative before reset");
  // ARK_BAD_T before the first step after a reset: no interpolant yet.
  if (stepper_->get_dky(mem_, t_, 1, asVector(dky_)) != ARK_SUCCESS) return nullptr;
  return N_VGetArrayPointer(asVector(dky_));
}

long OdeIntegrator::steps() const {
  long n = 0;
  if (mem_) stepper_->num_steps(mem_, &n);
  return n;
}

long OdeIntegrator::stepAttempts() const {
  long n = 0;
  if (mem_) stepper_->num_step_attempts(mem_, &n);
  return n;
}

long OdeIntegrator::rhsEvaluations() const {
  long n = 0;
  if (mem_) stepper_->num_rhs_evals(mem_, &n);
  return n;
}

long OdeIntegrator::stageSolves() const { return stage_solver_ ? stage_solver_->solves() : 0; }

}  // namespace orni
