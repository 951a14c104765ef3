// The right-hand side of the equations of motion must not allocate after warm-up (style.md 8).
// This translation unit replaces the global operator new/delete of the test binary with counting
// versions; the counter is read only around the measured sections.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/integrate/erk_integrator.hpp"
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
  ErkIntegrator integrator(n, &rhs, &d, opts);
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

TEST(DynamicsNoAllocation, CounterSeesAllocations) {  // the test above can fail
  const long before = g_allocations.load();
  auto* p = new std::vector<double>(10);
  delete p;
  EXPECT_GE(g_allocations.load() - before, 2);
}

}  // namespace
}  // namespace orni
