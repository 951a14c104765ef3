// The right-hand side of the equations of motion must not allocate after warm-up (docs/design.md
// 7.8). This translation unit replaces the global operator new/delete of the test binary with
// counting versions; the counter is read only around the measured sections.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

#include "core/dynamics/flexible_tethered.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/free_flight_system.hpp"
#include "core/integrate/ode_integrator.hpp"
#include "tests/support/magpie_vehicle.hpp"
#include "tests/support/test_vehicles.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// The replacements pair malloc with free; GCC cannot see that operator new below is ours and
// flags the pairing under some optimisation levels (-Wmismatched-new-delete false positive).
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
// The nothrow forms too (std::stable_sort's temporary buffer uses them): every form of new that
// can reach the replaced delete must be ours, or a sanitizer sees new/free pairs it did not make.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n ? n : 1);
}
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace orni {
namespace {

struct RhsData {
  const FlightCoreModel* model;
  FlightCoreData* data;
  BodyMotion body;
  ControlInput control;
  LoadSample loads;
};

int rhs(double t, const double* y, double* ydot, void* user) {
  auto* d = static_cast<RhsData*>(user);
  evaluateLoads(*d->model, *d->data, d->body, d->control, t, y, ydot, &d->loads);
  if (d->model->aeroStateCount() == 0) ydot[0] = d->loads.FV_N;  // a quadrature, as in the core
  return 0;
}

void expectNoAllocationInRhs(VehicleModel v) {
  const FlightCoreModel model(v);
  FlightCoreData data(model);
  RhsData d{&model, &data, tetheredBodyMotion(6.0, 20.0 * 3.14159265358979 / 180.0),
            ControlInput{4.0, 0.0}, LoadSample{}};
  const int n = std::max(1, model.aeroStateCount());
  std::vector<double> y(static_cast<std::size_t>(n), 0.0), ydot(y.size(), 0.0);
  initialAeroStates(model, d.body, d.control, 0.0, y.data());
  rhs(0.0, y.data(), ydot.data(), &d);  // warm-up (fills the friction cache)

  const long before = g_allocations.load();
  for (int i = 0; i < 1000; ++i) rhs(1e-3 * i, y.data(), ydot.data(), &d);
  EXPECT_EQ(g_allocations.load() - before, 0) << "evaluateLoads allocated";

  // The whole integration loop (ARKODE steps + RHS) after the integrator is set up.
  IntegratorOptions opts;
  opts.rel_tol = 1e-4;
  opts.abs_tol.assign(static_cast<std::size_t>(n), 1e-6);
  OdeIntegrator integrator(n, &rhs, &d,
                           IntegrationMethod::explicitRungeKutta(ErkMethod::kDormandPrince5), opts);
  integrator.reset(0.0, y.data());
  ASSERT_EQ(integrator.advanceTo(0.05), IntegratorStatus::kOk);  // warm-up
  const long before_steps = g_allocations.load();
  ASSERT_EQ(integrator.advanceTo(0.5), IntegratorStatus::kOk);
  EXPECT_EQ(g_allocations.load() - before_steps, 0) << "integration steps allocated";
  EXPECT_GT(integrator.steps(), 3);
}

TEST(DynamicsNoAllocation, MstTdRightHandSide) { expectNoAllocationInRhs(testing::rfwRig()); }

TEST(DynamicsNoAllocation, DeLaurierRightHandSide) {
  VehicleModel v = testing::rfwRig();
  v.aero.model = AeroModelKind::kDeLaurier1993;
  expectNoAllocationInRhs(v);
}

// The flexible wing's right-hand sides and their implicit-explicit steps (ARKStep with the modal
// split and the one-shot stage solver), tethered and in free flight.
template <class System>
void expectNoAllocationInImexSteps(System& sys, int n, const std::vector<double>& y0,
                                   double rel_tol) {
  using Imex = ModalImex<System>;
  std::vector<double> y(y0), ydot(static_cast<std::size_t>(n), 0.0);
  Imex::explicitRhs(0.0, y.data(), ydot.data(), &sys);  // warm-up
  const long before = g_allocations.load();
  for (int i = 0; i < 200; ++i) {
    if (sys.nonlinearWing()) Imex::update(1e-4 * i, y.data(), &sys);
    Imex::explicitRhs(1e-4 * i, y.data(), ydot.data(), &sys);
    Imex::implicitRhs(1e-4 * i, y.data(), ydot.data(), &sys);
    Imex::solve(1e-4 * (1 + i % 3), y.data(), ydot.data(), &sys);
  }
  EXPECT_EQ(g_allocations.load() - before, 0) << "the IMEX right-hand side allocated";

  IntegratorOptions opts;
  opts.rel_tol = rel_tol;
  sys.absoluteTolerances(rel_tol, 1e-5, 1e-5, &opts.abs_tol);
  OdeIntegrator integrator(
      n, &Imex::explicitRhs, &sys,
      IntegrationMethod::implicitExplicit(Imex::part(sys.nonlinearWing()), ImexMethod::kArk437),
      opts);
  integrator.reset(0.0, y0.data());
  ASSERT_EQ(integrator.advanceTo(0.02), IntegratorStatus::kOk) << integrator.lastError();
  const long before_steps = g_allocations.load();
  ASSERT_EQ(integrator.advanceTo(0.2), IntegratorStatus::kOk) << integrator.lastError();
  EXPECT_EQ(g_allocations.load() - before_steps, 0) << "IMEX integration steps allocated";
  EXPECT_GT(integrator.steps(), 10);
}

void expectNoAllocationInFlexibleTethered(const VehicleModel& v) {
  const FlightCoreModel model(v);
  const OperatingPoint p = testing::magpieDesignPoint();
  FlexibleTetheredSystem sys(model, *model.flexible, tetheredBodyMotion(p.speed_mps, p.theta_rad),
                             ControlInput{p.freq_hz, p.tail_angle_rad});
  const int n = sys.stateCount();
  std::vector<double> y0(static_cast<std::size_t>(n), 0.0);
  sys.initialState(0.0, y0.data());
  expectNoAllocationInImexSteps(sys, n, y0, 1e-4);
}

TEST(DynamicsNoAllocation, FlexibleTetheredImexSteps) {
  expectNoAllocationInFlexibleTethered(testing::magpieVehicle());
}

// The nonlinear wing: membrane force, Newton stages and the split's update after every step.
TEST(DynamicsNoAllocation, NonlinearWingTetheredImexSteps) {
  VehicleModel v = testing::magpieVehicle();
  v.wing.fe.nonlinear = true;
  v.wing.fe.max_modes = 12;
  expectNoAllocationInFlexibleTethered(v);
}

void expectNoAllocationInFlexibleFreeFlight(const VehicleModel& v) {
  const FlightCoreModel model(v);
  const OperatingPoint p = testing::magpieDesignPoint();
  FreeFlightSystem sys(model, model.flexible.get(), ControlInput{p.freq_hz, p.tail_angle_rad},
                       p.speed_mps);
  const int n = sys.stateCount();
  std::vector<double> y0(static_cast<std::size_t>(n), 0.0);
  BodyState b;
  b.h_m = 10.0;
  b.theta_rad = p.theta_rad;
  b.U_mps = p.speed_mps * std::cos(p.theta_rad);
  b.W_mps = p.speed_mps * std::sin(p.theta_rad);
  sys.initialState(0.0, b, y0.data());
  expectNoAllocationInImexSteps(sys, n, y0, 1e-4);
}

TEST(DynamicsNoAllocation, FlexibleFreeFlightImexSteps) {
  expectNoAllocationInFlexibleFreeFlight(testing::magpieVehicle());
}

TEST(DynamicsNoAllocation, NonlinearWingFreeFlightImexSteps) {
  VehicleModel v = testing::magpieVehicle();
  v.wing.fe.nonlinear = true;
  v.wing.fe.max_modes = 12;
  expectNoAllocationInFlexibleFreeFlight(v);
}

TEST(DynamicsNoAllocation, CounterSeesAllocations) {  // the test above can fail
  const long before = g_allocations.load();
  auto* p = new std::vector<double>(10);
  delete p;
  EXPECT_GE(g_allocations.load() - before, 2);
}

}  // namespace
}  // namespace orni
