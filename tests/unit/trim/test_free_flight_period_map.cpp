// The free-flight period map (trim/free_flight_period_map.hpp) builds one FreeFlightModel per
// underlying vehicle (the file's, the CG-shifted one) and a new system only when the parameters
// change: a flow does not depend on which parameters the map flew before, on whether the map is a
// clone, or on the map being new (same step grid), bit for bit.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/dynamics/free_flight_system.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "trim/free_flight_period_map.hpp"

namespace orni {
namespace {

struct Flown {
  std::vector<double> x_T;
  double altitude_gain_m = 0.0;
  double power_W = 0.0;
};

Flown fly(FreeFlightPeriodMap& map, const std::vector<double>& x, const std::vector<double>& p) {
  Flown f;
  f.x_T.assign(x.size(), 0.0);
  std::string why;
  EXPECT_TRUE(map.flow(x.data(), p.data(), f.x_T.data(), &f.altitude_gain_m, &why)) << why;
  f.power_W = map.lastMeanPower_W();
  return f;
}

void expectSameBits(const Flown& a, const Flown& b, const char* what) {
  EXPECT_EQ(a.x_T, b.x_T) << what;
  EXPECT_EQ(a.altitude_gain_m, b.altitude_gain_m) << what;
  EXPECT_EQ(a.power_W, b.power_W) << what;
}

TEST(TrimFreeFlightPeriodMap, FlowDoesNotDependOnTheParametersFlownBefore) {
  VehicleModel v =
      studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) + "/studies/vehicles/efw_magpie.toml")
          .model;
  v.wing.structure = StructureLevel::kRigid;
  const FlightCoreModel model(v);
  FreeFlightPeriodMapOptions mo;
  mo.rel_tol = 1e-5;
  mo.friction_speed_mps = 13.0;

  // A start near a level flight: the body at 16 deg and 13 m/s, quasi-steady aerodynamic states.
  FreeFlightSystem sys(model, nullptr, ControlInput{12.0, 0.3}, 13.0);
  BodyState body;
  body.theta_rad = 0.28;
  body.U_mps = 12.5;
  body.W_mps = 3.6;
  std::vector<double> y(static_cast<std::size_t>(sys.stateCount()), 0.0);
  sys.initialState(0.0, body, y.data());
  FreeFlightPeriodMap map(model, mo);
  ASSERT_EQ(sys.powerOffset() - 2, map.stateCount());
  const std::vector<double> x(y.begin() + 2, y.begin() + sys.powerOffset());

  const std::vector<double> p1{0.30, 12.0, 0.0}, p2{0.35, 12.5, 0.0};
  const std::vector<double> p3{0.30, 12.0, 0.005}, p4{0.30, 12.0, 0.01};
  const Flown a = fly(map, x, p1);  // also records the step grid (at p1)
  fly(map, x, p2);
  const Flown c = fly(map, x, p3);
  fly(map, x, p4);  // another shift: another vehicle
  expectSameBits(fly(map, x, p1), a, "back to p1");
  expectSameBits(fly(map, x, p3), c, "back to p3");

  const std::unique_ptr<PeriodMap> clone = map.clone();
  auto& cloned = dynamic_cast<FreeFlightPeriodMap&>(*clone);
  expectSameBits(fly(cloned, x, p3), c, "clone at p3");
  expectSameBits(fly(cloned, x, p1), a, "clone at p1");

  // A new map with the same grid builds its own models: the same bits.
  FreeFlightPeriodMap fresh(model, mo);
  std::string why;
  ASSERT_TRUE(fresh.refreshDiscretisation(x.data(), p1.data(), &why)) << why;
  expectSameBits(fly(fresh, x, p3), c, "new map at p3");
  expectSameBits(fly(fresh, x, p1), a, "new map at p1");
}

}  // namespace
}  // namespace orni
