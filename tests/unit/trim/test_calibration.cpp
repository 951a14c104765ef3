// The calibration machinery (trim/calibration.hpp) recovers a value it was not given: a vehicle's
// trim point is level settled flight by construction (Eq. 4 refined in free flight), so
// calibrating its CG position against that point from a perturbed start must return the CG it
// had. (The committed vehicle has no calibrated value: studies/vehicles/efw_magpie.toml.)
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/magpie_vehicle.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "trim/calibration.hpp"
#include "trim/trim_solver.hpp"

namespace orni {
namespace {

VehicleModel magpie() { return testing::magpieVehicle(); }

TEST(TrimCalibration, RecoversTheCgPositionFromAPerturbedStart) {
  const VehicleModel v = magpie();
  TrimOptions t;
  t.initial = testing::magpieDesignPoint();
  t.initial.freq_hz = 12.0;
  t.initial.theta_rad = 15.0 * kDegToRad;  // near its trim (13.56 deg, 18.02 m/s, 16.59 deg:
                                           // results/paper/trim_magpie)
  t.initial.speed_mps = 15.0;
  t.initial.tail_angle_rad = 18.0 * kDegToRad;
  t.verify_free_flight = false;
  const TrimSummary trim = solveTrim(FlightCoreModel(v), t);
  ASSERT_TRUE(trim.converged) << trim.message;

  CalibrationOptions o;
  o.target = trim.solution;  // level settled flight of v at its own tail angle
  const double truth = v.flapping.hinge_x_B_m;
  o.variables = {{calibrationParameter("kinematics.hinge_x_m"), truth - 0.004, truth - 0.01,
                  truth + 0.005, "test"}};
  o.tethered_first = false;
  o.tolerance = 0.05;  // one variable, three residuals: least squares, zero at the truth
  const CalibrationSummary s = calibrate(v, o);
  ASSERT_EQ(s.values.size(), 1u);
  // The trim is level to 0.01 deg climb and the settled means to its window: the CG comes back
  // within 0.3 mm (measured 0.0012 mm). (Started aft of the truth the first free flights do not
  // settle: the CG then nears this vehicle's stability limit, about 25 mm behind the hinge.)
  EXPECT_NEAR(s.values[0], truth, 3e-4) << s.message << "\n" << s.ceres_report;
  EXPECT_FALSE(s.at_lower[0] || s.at_upper[0]);
  // Converged means each residual within the tolerance in its unit: theta and climb in deg, the
  // speed in 0.1 m/s (calibrate.tolerance 0.01 holds U to 1 mm/s).
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_LE(std::abs(s.theta_error_deg), o.tolerance);
  EXPECT_LE(std::abs(s.speed_error_mps), 0.1 * o.tolerance);
  EXPECT_LE(std::abs(s.climb_angle_deg), o.tolerance);

  // Conditioning: one value, so one singular value and B = J diag(range) / band a column; the
  // half-width the band allows is then range sum_j |B_j| / |B|^2 (the pseudo-inverse of a column).
  const CalibrationConditioning& k = s.conditioning;
  ASSERT_TRUE(k.ok) << k.message;
  ASSERT_EQ(k.singular_values.size(), 1u);
  const double range = 0.015;
  const double band[3] = {o.band.theta_deg, o.band.speed_mps, o.band.climb_deg};
  double sum_abs = 0.0, sum_sq = 0.0;
  for (int j = 0; j < 3; ++j) {
    const double b = k.jacobian[0][static_cast<std::size_t>(j)] * range / band[j];
    sum_abs += std::abs(b);
    sum_sq += b * b;
  }
  EXPECT_NEAR(k.singular_values[0], std::sqrt(sum_sq), 1e-9 * std::sqrt(sum_sq));
  EXPECT_NEAR(k.determined_within[0], range * sum_abs / sum_sq, 1e-9 * range);
  // Moving the CG moves the settled pitch: well determined, to a fraction of the 15 mm range.
  EXPECT_LT(k.determined_within[0], 0.3 * range);
}

// Four values against three residuals: the Jacobian has a null direction, and which value it
// leaves free is what a user needs to know. Here the fourth value moves nothing (its column is
// zero, like P3 on one side of the nonlinear wing's fold): the null direction is that value alone,
// so it is undetermined and the three others are determined exactly as a three-value fit would
// determine them.
TEST(TrimCalibration, ConditioningNamesTheValueANullDirectionLeavesFree) {
  std::vector<CalibrationVariable> vars(4);
  for (int i = 0; i < 4; ++i) vars[static_cast<std::size_t>(i)] = {{}, 0.5, 0.0, 1.0 + i, "test"};
  Eigen::MatrixXd J(3, 4);  // deg, 0.1 m/s, deg per scaled value
  J << 0.40, -0.03, 0.34, 0.00,  //
       0.23, 0.06, -1.69, 0.00,  //
       0.46, -0.03, 0.07, 0.00;
  const CalibrationBand band;
  const CalibrationConditioning k4 = conditioningOfJacobian(J, vars, band);
  ASSERT_TRUE(k4.ok);
  ASSERT_EQ(k4.null_component.size(), 4u);
  EXPECT_NEAR(k4.null_component[3], 1.0, 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(k4.null_component[static_cast<std::size_t>(i)], 0.0, 1e-12);
  EXPECT_TRUE(std::isinf(k4.determined_within[3]));
  EXPECT_TRUE(std::isinf(k4.condition_number));
  const CalibrationConditioning k3 = conditioningOfJacobian(
      J.leftCols(3), std::vector<CalibrationVariable>(vars.begin(), vars.begin() + 3), band);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(k4.determined_within[static_cast<std::size_t>(i)],
                k3.determined_within[static_cast<std::size_t>(i)],
                1e-9 * k3.determined_within[static_cast<std::size_t>(i)]);
  EXPECT_TRUE(std::isfinite(k3.condition_number));

  // A null direction shared evenly by two values (two identical columns): neither is determined.
  J.col(3) = J.col(2);
  const CalibrationConditioning shared = conditioningOfJacobian(J, vars, band);
  EXPECT_NEAR(shared.null_component[2], std::sqrt(0.5), 1e-9);
  EXPECT_TRUE(std::isinf(shared.determined_within[2]) && std::isinf(shared.determined_within[3]));
  EXPECT_THROW(conditioningOfJacobian(J.leftCols(2), vars, band), std::invalid_argument);
}

}  // namespace
}  // namespace orni
