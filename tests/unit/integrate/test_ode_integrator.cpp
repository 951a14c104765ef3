// The ODE integrator (core/integrate/ode_integrator.*) against an analytic truth: a stiff, lightly
// damped oscillator (300 Hz, 1.5 % damping: the highest mode of the magpie wing) forced at 12 Hz
// (the flapping frequency). Implicit-explicit: its stiffness and damping in the implicit part, the
// forcing explicit; explicit: the whole right-hand side explicit. Started on its periodic
// (particular) solution it must stay there with either method. Also: exceptions and failures
// come back the same way from both methods, each naming its ARKODE stepper.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/integrate/ode_integrator.hpp"

namespace orni {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Oscillator {
  double omega = 2.0 * kPi * 300.0;  // rad/s
  double zeta = 0.015;
  double Omega = 2.0 * kPi * 12.0;   // forcing, rad/s
  double F0 = 1.0;                   // forcing amplitude (per unit mass)
  int explicit_calls = 0;
  bool throw_now = false;
  bool fail_now = false;
  double nan_once_after_s = -1.0;  // > 0: one non-finite explicit RHS at the first t past it

  // Particular solution x = X cos(Omega t - phase).
  double amplitude() const {
    const double a = omega * omega - Omega * Omega, b = 2.0 * zeta * omega * Omega;
    return F0 / std::sqrt(a * a + b * b);
  }
  double phase() const {
    return std::atan2(2.0 * zeta * omega * Omega, omega * omega - Omega * Omega);
  }
  double x(double t) const { return amplitude() * std::cos(Omega * t - phase()); }
  double v(double t) const { return -Omega * amplitude() * std::sin(Omega * t - phase()); }
};

int explicitRhs(double t, const double*, double* ydot, void* user) {
  auto* o = static_cast<Oscillator*>(user);
  ++o->explicit_calls;
  if (o->throw_now) throw std::runtime_error("thrown from the explicit part");
  if (o->fail_now) return -1;
  ydot[0] = 0.0;
  ydot[1] = o->F0 * std::cos(o->Omega * t);
  if (o->nan_once_after_s > 0.0 && t > o->nan_once_after_s) {
    o->nan_once_after_s = -1.0;
    ydot[1] = std::numeric_limits<double>::quiet_NaN();
  }
  return 0;
}
int implicitRhs(double, const double* y, double* ydot, void* user) {  // L y
  const auto* o = static_cast<Oscillator*>(user);
  ydot[0] = y[1];
  ydot[1] = -o->omega * o->omega * y[0] - 2.0 * o->zeta * o->omega * y[1];
  return 0;
}
int fullRhs(double t, const double* y, double* ydot, void* user) {  // forcing + L y, explicit
  double l[2] = {0.0, 0.0};
  const int rc = explicitRhs(t, y, ydot, user);
  if (rc != 0) return rc;
  implicitRhs(t, y, l, user);
  ydot[0] += l[0];
  ydot[1] += l[1];
  return 0;
}
int solve(double g, const double* b, double* x, void* user) {  // (I - g L) x = b, 2 x 2
  const auto* o = static_cast<Oscillator*>(user);
  const double k = o->omega * o->omega, c = 2.0 * o->zeta * o->omega;
  // [1, -g; g k, 1 + g c] x = b
  const double det = (1.0 + g * c) + g * g * k;
  x[0] = ((1.0 + g * c) * b[0] + g * b[1]) / det;
  x[1] = (b[1] - g * k * b[0]) / det;
  return 0;
}

IntegrationMethod imexMethod() {
  return IntegrationMethod::implicitExplicit(LinearImplicitPart{&implicitRhs, &solve},
                                             ImexMethod::kArk437);
}
IntegrationMethod erkMethod() {
  return IntegrationMethod::explicitRungeKutta(ErkMethod::kDormandPrince5);
}

IntegratorOptions options(double rel_tol, double amplitude) {
  IntegratorOptions o;
  o.rel_tol = rel_tol;
  o.abs_tol = {0.1 * rel_tol * amplitude, 0.1 * rel_tol * amplitude * 2.0 * kPi * 12.0};
  return o;
}

// Worst |x - x_exact| over 5 forcing periods sampled 12 times per period.
double worstDeviation(OdeIntegrator& integ, const Oscillator& osc) {
  const double y0[2] = {osc.x(0.0), osc.v(0.0)};
  integ.reset(0.0, y0);
  double worst = 0.0;
  for (int k = 1; k <= 60; ++k) {
    const double t = k / (12.0 * 12.0);
    EXPECT_EQ(integ.advanceTo(t), IntegratorStatus::kOk) << integ.lastError();
    worst = std::max(worst, std::abs(integ.state()[0] - osc.x(t)));
  }
  return worst;
}

TEST(OdeIntegrator, ImexForcedStiffOscillatorStaysOnItsAnalyticPeriodicSolution) {
  Oscillator osc;
  const double X = osc.amplitude();
  OdeIntegrator integ(2, &explicitRhs, &osc, imexMethod(), options(1e-6, X));
  const double worst = worstDeviation(integ, osc);
  // Tolerance: 1e-5 of the amplitude, ten times the relative tolerance asked for (global error
  // accumulates over the steps of five periods).
  EXPECT_LT(worst, 1e-5 * X) << "worst deviation " << worst << " of amplitude " << X;
  // The step count is not the point here: on this pure stiff oscillator the ESDIRK stage order
  // (2) limits the steps through the error estimate of the stiff component (order reduction;
  // ~2000 steps at rel_tol 1e-6). The gain on the wing, where the explicit run is limited by the
  // stability of its highest mode, is measured in tests/unit/dynamics/test_modal_imex.cpp.
  EXPECT_GT(integ.steps(), 5);
  EXPECT_EQ(integ.rhsEvaluations(), osc.explicit_calls);
  EXPECT_GT(integ.stageSolves(), 0);
  EXPECT_EQ(integ.methodName(),
            "ARKODE ARKStep ARK4(3)7L[2]SA IMEX, modal stiffness implicit");
}

// A non-finite explicit right-hand side after an accepted stage solve is unrecoverable in
// SUNDIALS 6.4 (ARK_UNREC_RHSFUNC_ERR). With a post-step update attached (the nonlinear wing) the
// integrator restarts from the last accepted step with a smaller step and stays on the solution;
// without one the failure is reported as before.
int noUpdate(double, const double*, void*) { return 0; }

TEST(OdeIntegrator, ImexRestartsFromTheLastAcceptedStepAfterANonFiniteStage) {
  for (const bool hooked : {false, true}) {
    Oscillator osc;
    const double X = osc.amplitude();
    osc.nan_once_after_s = 0.2;
    LinearImplicitPart part{&implicitRhs, &solve, hooked ? &noUpdate : nullptr};
    OdeIntegrator integ(2, &explicitRhs, &osc,
                        IntegrationMethod::implicitExplicit(part, ImexMethod::kArk437),
                        options(1e-6, X));
    const double y0[2] = {osc.x(0.0), osc.v(0.0)};
    integ.reset(0.0, y0);
    ::testing::internal::CaptureStderr();
    const IntegratorStatus status = integ.advanceTo(0.4);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");  // recovered or not: quiet
    EXPECT_LT(osc.nan_once_after_s, 0.0) << "the non-finite stage was not reached";
    if (!hooked) {
      EXPECT_EQ(status, IntegratorStatus::kFailed);
      EXPECT_NE(integ.lastError().find("ARK_UNREC_RHSFUNC_ERR"), std::string::npos)
          << integ.lastError();
      EXPECT_EQ(integ.restarts(), 0);
      continue;
    }
    ASSERT_EQ(status, IntegratorStatus::kOk) << integ.lastError();
    EXPECT_EQ(integ.restarts(), 1);
    EXPECT_DOUBLE_EQ(integ.time(), 0.4);
    // The same tolerance as the run without a failure (above).
    EXPECT_NEAR(integ.state()[0], osc.x(0.4), 1e-5 * X);
  }
}

TEST(OdeIntegrator, ExplicitForcedStiffOscillatorStaysOnItsAnalyticPeriodicSolution) {
  Oscillator osc;
  const double X = osc.amplitude();
  OdeIntegrator integ(2, &fullRhs, &osc, erkMethod(), options(1e-6, X));
  const double worst = worstDeviation(integ, osc);
  // The same tolerance as the implicit-explicit run's, for the same reason.
  EXPECT_LT(worst, 1e-5 * X) << "worst deviation " << worst << " of amplitude " << X;
  EXPECT_GT(integ.steps(), 5);
  EXPECT_GE(integ.stepAttempts(), integ.steps());
  EXPECT_EQ(integ.rhsEvaluations(), osc.explicit_calls);
  EXPECT_EQ(integ.stageSolves(), 0);
  EXPECT_EQ(integ.methodName(), "ARKODE ERKStep Dormand-Prince 5(4)");
}

// An integrator on the periodic solution, reset at t = 0.
struct StartedOscillator {
  Oscillator osc;
  OdeIntegrator integ;
  explicit StartedOscillator(bool imex)
      : integ(2, imex ? &explicitRhs : &fullRhs, &osc, imex ? imexMethod() : erkMethod(),
              options(1e-6, osc.amplitude())) {
    const double y0[2] = {osc.x(0.0), osc.v(0.0)};
    integ.reset(0.0, y0);
  }
};

TEST(OdeIntegrator, ExceptionFromTheRightHandSideIsRethrown) {
  for (const bool imex : {true, false}) {
    StartedOscillator s(imex);
    s.osc.throw_now = true;
    EXPECT_THROW(s.integ.advanceTo(0.01), std::runtime_error) << (imex ? "IMEX" : "explicit");
    // The stored exception was re-thrown once: the next failure is a plain failure.
    s.osc.throw_now = false;
    s.osc.fail_now = true;
    EXPECT_EQ(s.integ.advanceTo(0.02), IntegratorStatus::kFailed);
  }
}

TEST(OdeIntegrator, UnrecoverableFailureIsReportedNotThrownAndNamesTheStepper) {
  for (const bool imex : {true, false}) {
    StartedOscillator s(imex);
    s.osc.fail_now = true;
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(s.integ.advanceTo(0.01), IntegratorStatus::kFailed);
    // SUNDIALS's own message is in lastError(), and nothing reaches the console.
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    const std::string stepper = imex ? "ARKODE ARKStep failed" : "ARKODE ERKStep failed";
    EXPECT_NE(s.integ.lastError().find(stepper), std::string::npos) << s.integ.lastError();
    EXPECT_NE(s.integ.lastError().find("right-hand side"), std::string::npos)
        << s.integ.lastError();
  }
}

TEST(OdeIntegrator, RejectsMissingPartsAndAdvanceBeforeReset) {
  Oscillator osc;
  EXPECT_THROW(IntegrationMethod::implicitExplicit(LinearImplicitPart{&implicitRhs, nullptr},
                                                   ImexMethod::kArk437),
               std::invalid_argument);
  EXPECT_THROW(OdeIntegrator(2, nullptr, &osc, erkMethod(), options(1e-6, 1.0)),
               std::invalid_argument);
  OdeIntegrator integ(2, &fullRhs, &osc, erkMethod(), options(1e-6, 1.0));
  EXPECT_THROW(integ.advanceTo(0.01), std::logic_error);
}

}  // namespace
}  // namespace orni
