// The flexible wing in the tethered mode (structure.md 3-4): it runs, reaches a periodic state,
// differs from the rigid wing, builds its modal model once per structure (cache), and reduces to
// the rigid wing when made very stiff.
#include <gtest/gtest.h>

#include <cmath>

#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni {
namespace {

VehicleModel efw(StructureLevel level) {
  VehicleModel v =
      studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) + "/studies/vehicles/efw_magpie.toml");
  v.wing.structure = level;
  v.wing.fe.element_size_m = 0.01;  // coarse mesh: fast test
  v.wing.fe.mode_count = 6;
  return v;
}

SimulationSummary run(const VehicleModel& v) {
  const FlightCoreModel model(v);
  SimulationOptions opts;
  opts.cycles = 6;
  return simulateTethered(model, v.operating_point, opts, nullptr);
}

TEST(DynamicsFlexibleTethered, RunsToAPeriodicStateAndDiffersFromTheRigidWing) {
  const SimulationSummary flex = run(efw(StructureLevel::kFlexible));
  const SimulationSummary rigid = run(efw(StructureLevel::kRigid));
  ASSERT_EQ(flex.status, SimulationStatus::kOk) << flex.message;
  ASSERT_EQ(rigid.status, SimulationStatus::kOk) << rigid.message;
  // Passive bending and twist change the loads (the paper's point): more than 10 % here.
  EXPECT_GT(std::abs(flex.mean.FV_N - rigid.mean.FV_N), 0.1 * std::abs(rigid.mean.FV_N));
  EXPECT_LT(flex.mean.power_aero_W, rigid.mean.power_aero_W);
  // Mean hinge power = aerodynamic power + structural damping dissipation >= aerodynamic power.
  EXPECT_GE(flex.mean.power_hinge_W, flex.mean.power_aero_W - 1e-9);
}

TEST(DynamicsFlexibleTethered, StiffWingApproachesTheRigidWing) {
  // Members and skin 1000 times stiffer: deflections shrink 1000-fold and the loads converge
  // to the rigid wing's (same mass, same aerodynamics).
  VehicleModel stiff = efw(StructureLevel::kFlexible);
  for (Material& m : stiff.materials) m.youngs_modulus_pa *= 1000.0;
  const SimulationSummary flex = run(stiff);
  const SimulationSummary rigid = run(efw(StructureLevel::kRigid));
  ASSERT_EQ(flex.status, SimulationStatus::kOk) << flex.message;
  EXPECT_NEAR(flex.mean.FV_N, rigid.mean.FV_N, 0.02 * std::abs(rigid.mean.FV_N));
  EXPECT_NEAR(flex.mean.FH_N, rigid.mean.FH_N, 0.02 * std::abs(rigid.mean.FH_N));
  EXPECT_NEAR(flex.mean.power_aero_W, rigid.mean.power_aero_W, 0.02 * rigid.mean.power_aero_W);
}

TEST(DynamicsFlexibleTethered, ModalWingIsBuiltOncePerStructure) {
  const VehicleModel v = efw(StructureLevel::kFlexible);
  const auto a = cachedModalWing(v);
  const long builds = modalWingBuildCount();
  const auto b = cachedModalWing(v);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_EQ(modalWingBuildCount(), builds);
  VehicleModel other = v;
  other.materials.front().youngs_modulus_pa *= 1.01;  // any structural change rebuilds
  EXPECT_NE(cachedModalWing(other).get(), a.get());
  EXPECT_EQ(modalWingBuildCount(), builds + 1);
}

}  // namespace
}  // namespace orni
