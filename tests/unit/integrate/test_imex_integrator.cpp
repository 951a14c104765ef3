// The IMEX wrapper (core/integrate/imex_integrator.*) against an analytic truth: a stiff, lightly
// damped oscillator (300 Hz, 1.5 % damping: the highest mode of the magpie wing) forced at 12 Hz
// (the flapping frequency), its stiffness and damping in the implicit part, the forcing explicit.
// Started on its periodic (particular) solution it must stay there. Also: exceptions and failures
// come back as with ErkIntegrator.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/integrate/imex_integrator.hpp"

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
  return 0;
}
int implicitRhs(double, const double* y, double* ydot, void* user) {  // L y
  const auto* o = static_cast<Oscillator*>(user);
  ydot[0] = y[1];
  ydot[1] = -o->omega * o->omega * y[0] - 2.0 * o->zeta * o->omega * y[1];
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

IntegratorOptions options(double rel_tol, double amplitude) {
  IntegratorOptions o;
  o.rel_tol = rel_tol;
  o.abs_tol = {0.1 * rel_tol * amplitude, 0.1 * rel_tol * amplitude * 2.0 * kPi * 12.0};
  return o;
}

TEST(ImexIntegrator, ForcedStiffOscillatorStaysOnItsAnalyticPeriodicSolution) {
  Oscillator osc;
  const double X = osc.amplitude();
  ImexIntegrator integ(2, &explicitRhs, LinearImplicitPart{&implicitRhs, &solve}, &osc,
                       options(1e-6, X));
  const double y0[2] = {osc.x(0.0), osc.v(0.0)};
  integ.reset(0.0, y0);
  double worst = 0.0;
  for (int k = 1; k <= 60; ++k) {  // 5 forcing periods, sampled 12 times per period
    const double t = k / (12.0 * 12.0);
    ASSERT_EQ(integ.advanceTo(t), IntegratorStatus::kOk) << integ.lastError();
    worst = std::max(worst, std::abs(integ.state()[0] - osc.x(t)));
  }
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
}

// An integrator on the periodic solution, reset at t = 0.
struct StartedOscillator {
  Oscillator osc;
  ImexIntegrator integ{2, &explicitRhs, LinearImplicitPart{&implicitRhs, &solve}, &osc,
                       options(1e-6, osc.amplitude())};
  StartedOscillator() {
    const double y0[2] = {osc.x(0.0), osc.v(0.0)};
    integ.reset(0.0, y0);
  }
};

TEST(ImexIntegrator, ExceptionFromTheRightHandSideIsRethrown) {
  StartedOscillator s;
  Oscillator& osc = s.osc;
  ImexIntegrator& integ = s.integ;
  osc.throw_now = true;
  EXPECT_THROW(integ.advanceTo(0.01), std::runtime_error);
}

TEST(ImexIntegrator, UnrecoverableFailureIsReportedNotThrown) {
  StartedOscillator s;
  Oscillator& osc = s.osc;
  ImexIntegrator& integ = s.integ;
  osc.fail_now = true;
  EXPECT_EQ(integ.advanceTo(0.01), IntegratorStatus::kFailed);
  EXPECT_NE(integ.lastError().find("ARKStep"), std::string::npos) << integ.lastError();
}

TEST(ImexIntegrator, RejectsMissingParts) {
  Oscillator osc;
  EXPECT_THROW(ImexIntegrator(2, &explicitRhs, LinearImplicitPart{&implicitRhs, nullptr}, &osc,
                              options(1e-6, 1.0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace orni
