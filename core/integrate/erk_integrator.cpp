#include "core/integrate/erk_integrator.hpp"

#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "core/integrate/callback_guard.hpp"
#include "core/integrate/serial_vector_ops.hpp"

namespace orni {

namespace {
SUNContext asContext(void* p) { return static_cast<SUNContext>(p); }
N_Vector asVector(void* p) { return static_cast<N_Vector>(p); }
}  // namespace

// The C callback (ARKRhsFn). Catches everything: no exception crosses SUNDIALS.
struct ErkCallback {
  static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) {
    auto* self = static_cast<ErkIntegrator*>(user_data);
    return detail::guardedRhs(self->rhs_, t, y, ydot, self->n_, self->user_, &self->pending_);
  }
};

bool IntegratorOptions::IsValid(int state_size, std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (!(rel_tol > 0.0 && rel_tol < 1.0)) return fail("rel_tol must be in (0, 1)");
  if (static_cast<int>(abs_tol.size()) != state_size)
    return fail("abs_tol must have one entry per state");
  for (double a : abs_tol)
    if (!(a > 0.0)) return fail("abs_tol entries must be > 0");
  if (max_steps < 1) return fail("max_steps must be >= 1");
  if (max_step < 0.0) return fail("max_step must be >= 0");
  return true;
}

ErkIntegrator::ErkIntegrator(int state_size, RhsFunction rhs, void* user_data,
                             const IntegratorOptions& opts)
    : n_(state_size), rhs_(rhs), user_(user_data), opts_(opts) {
  std::string why;
  if (state_size < 1) throw std::invalid_argument("ErkIntegrator: state size must be >= 1");
  if (!opts.IsValid(state_size, &why)) throw std::invalid_argument("ErkIntegrator: " + why);
  SUNContext c = nullptr;
  if (SUNContext_Create(nullptr, &c) != 0) throw std::runtime_error("SUNContext_Create failed");
  context_ = c;
  y_ = N_VNew_Serial(n_, c);
  atol_ = N_VNew_Serial(n_, c);
  if (!y_ || !atol_) throw std::runtime_error("N_VNew_Serial failed");
  // Single-pass linear combinations (set before ERKStep clones the vector, so every work vector
  // inherits it): the integrator's own vector work is comparable to the RHS for ~60 states.
  detail::installSinglePassOps(asVector(y_));
  double* a = N_VGetArrayPointer(asVector(atol_));
  for (int i = 0; i < n_; ++i) a[i] = opts.abs_tol[static_cast<std::size_t>(i)];
  N_VConst(0.0, asVector(y_));
}

ErkIntegrator::~ErkIntegrator() {
  if (mem_) ERKStepFree(&mem_);
  if (atol_) N_VDestroy(asVector(atol_));
  if (y_) N_VDestroy(asVector(y_));
  if (context_) {
    SUNContext c = asContext(context_);
    SUNContext_Free(&c);
  }
}

void ErkIntegrator::reset(double t0, const double* y0) {
  double* y = N_VGetArrayPointer(asVector(y_));
  for (int i = 0; i < n_; ++i) y[i] = y0[i];
  t_ = t0;
  if (!mem_) {
    mem_ = ERKStepCreate(&ErkCallback::rhs, t0, asVector(y_), asContext(context_));
    if (!mem_) throw std::runtime_error("ERKStepCreate failed");
    ERKStepSetUserData(mem_, this);
    ERKStepSVtolerances(mem_, opts_.rel_tol, asVector(atol_));
    ARKODE_ERKTableID table = ARKODE_DORMAND_PRINCE_7_4_5;
    if (opts_.method == ErkMethod::kVerner6) table = ARKODE_VERNER_8_5_6;
    if (opts_.method == ErkMethod::kFehlberg8) table = ARKODE_FEHLBERG_13_7_8;
    if (opts_.method == ErkMethod::kBogackiShampine3) table = ARKODE_BOGACKI_SHAMPINE_4_2_3;
    if (opts_.method == ErkMethod::kArk436) table = ARKODE_ARK436L2SA_ERK_6_3_4;
    ERKStepSetTableNum(mem_, table);
    ERKStepSetMaxNumSteps(mem_, opts_.max_steps);
    if (opts_.max_step > 0.0) ERKStepSetMaxStep(mem_, opts_.max_step);
  } else {
    ERKStepReset(mem_, t0, asVector(y_));
  }
}

IntegratorStatus ErkIntegrator::advanceTo(double tout) {
  if (!mem_) throw std::logic_error("ErkIntegrator::advanceTo before reset");
  sunrealtype t_reached = t_;
  const int flag = ERKStepEvolve(mem_, tout, asVector(y_), &t_reached, ARK_NORMAL);
  detail::rethrowPending(&pending_);
  t_ = t_reached;
  if (flag < 0) {
    // The flag name is malloc'ed by SUNDIALS (6.x): the caller frees it.
    char* name = ERKStepGetReturnFlagName(flag);
    last_error_ = std::string("ARKODE ERKStep failed at t = ") + std::to_string(t_reached) +
                  " s: " + (name ? name : "unknown flag");
    std::free(name);
    return IntegratorStatus::kFailed;
  }
  return IntegratorStatus::kOk;
}

const double* ErkIntegrator::state() const { return N_VGetArrayPointer(asVector(y_)); }

long ErkIntegrator::steps() const {
  long n = 0;
  if (mem_) ERKStepGetNumSteps(mem_, &n);
  return n;
}

long ErkIntegrator::stepAttempts() const {
  long n = 0;
  if (mem_) ERKStepGetNumStepAttempts(mem_, &n);
  return n;
}

long ErkIntegrator::rhsEvaluations() const {
  long n = 0;
  if (mem_) ERKStepGetNumRhsEvals(mem_, &n);
  return n;
}

}  // namespace orni
