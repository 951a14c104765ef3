#include "core/integrate/ode_integrator.hpp"

namespace orni {

namespace {
const char* erkName(ErkMethod m) {
  switch (m) {
    case ErkMethod::kDormandPrince5: return "ARKODE ERKStep Dormand-Prince 5(4)";
    case ErkMethod::kVerner6: return "ARKODE ERKStep Verner 6(5)";
    case ErkMethod::kFehlberg8: return "ARKODE ERKStep Fehlberg 8(7)";
    case ErkMethod::kBogackiShampine3: return "ARKODE ERKStep Bogacki-Shampine 3(2)";
    case ErkMethod::kArk436: return "ARKODE ERKStep ARK4(3)6L[2]SA explicit table";
  }
  return "ARKODE ERKStep";
}
const char* imexName(ImexMethod m) {
  switch (m) {
    case ImexMethod::kArk324: return "ARKODE ARKStep ARK3(2)4L[2]SA IMEX, modal stiffness implicit";
    case ImexMethod::kArk436: return "ARKODE ARKStep ARK4(3)6L[2]SA IMEX, modal stiffness implicit";
    case ImexMethod::kArk437: return "ARKODE ARKStep ARK4(3)7L[2]SA IMEX, modal stiffness implicit";
    case ImexMethod::kArk548: return "ARKODE ARKStep ARK5(4)8L[2]SAb IMEX, modal stiffness implicit";
  }
  return "ARKODE ARKStep IMEX";
}
}  // namespace

OdeIntegrator::OdeIntegrator(int state_size, RhsFunction rhs, void* user_data,
                             const IntegratorOptions& opts)
    : erk_(std::make_unique<ErkIntegrator>(state_size, rhs, user_data, opts)),
      name_(erkName(opts.method)) {}

OdeIntegrator::OdeIntegrator(int state_size, RhsFunction explicit_rhs,
                             LinearImplicitPart implicit, void* user_data,
                             const IntegratorOptions& opts, ImexMethod method)
    : imex_(std::make_unique<ImexIntegrator>(state_size, explicit_rhs, implicit, user_data, opts,
                                             method)),
      name_(imexName(method)) {}

void OdeIntegrator::reset(double t0, const double* y0) {
  if (erk_) erk_->reset(t0, y0); else imex_->reset(t0, y0);
}
IntegratorStatus OdeIntegrator::advanceTo(double tout) {
  return erk_ ? erk_->advanceTo(tout) : imex_->advanceTo(tout);
}
const double* OdeIntegrator::state() const { return erk_ ? erk_->state() : imex_->state(); }
double OdeIntegrator::time() const { return erk_ ? erk_->time() : imex_->time(); }
long OdeIntegrator::steps() const { return erk_ ? erk_->steps() : imex_->steps(); }
long OdeIntegrator::rhsEvaluations() const {
  return erk_ ? erk_->rhsEvaluations() : imex_->rhsEvaluations();
}
long OdeIntegrator::stepAttempts() const {
  return erk_ ? erk_->stepAttempts() : imex_->stepAttempts();
}
const std::string& OdeIntegrator::lastError() const {
  return erk_ ? erk_->lastError() : imex_->lastError();
}

}  // namespace orni
