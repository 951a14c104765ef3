// Calibration of vehicle values the paper leaves open against its published trim point (Table 3):
// find the values of up to three vehicle parameters for which the vehicle, flying freely at the
// published tail angle and frequency, settles into level flight at the published mean pitch and
// speed (free_flight_trim.hpp: settled means). Ceres Levenberg-Marquardt with bounds and central
// differences; residuals (theta_mean - theta*) / 1 deg, (airspeed - U*) / (0.1 m/s) and the climb
// angle / 1 deg. No I/O.
#pragma once

#include <string>
#include <vector>

#include "core/dynamics/simulation_options.hpp"
#include "core/model/vehicle_model.hpp"
#include "trim/calibration_options.hpp"
#include "trim/free_flight_trim.hpp"

namespace orni {

struct CalibrationEvaluation {
  std::vector<double> values;
  SettledFlight settled;
  double residual[3] = {0, 0, 0};
};

struct CalibrationSummary {
  bool converged = false;
  std::string message;
  std::vector<double> values;      ///< calibrated values, in the order of the variables
  SettledFlight settled;           ///< at the calibrated values
  double theta_error_deg = 0, speed_error_mps = 0, climb_angle_deg = 0;
  int iterations = 0, evaluations = 0;
  double wall_time_s = 0;
  std::string ceres_report;
  std::vector<CalibrationEvaluation> log;
};

/// Calibrate `base` (its other values unchanged). Throws std::invalid_argument for bad options.
CalibrationSummary calibrate(const VehicleModel& base, const CalibrationOptions& options);

}  // namespace orni
