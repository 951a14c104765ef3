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
#include "trim/free_flight_trim.hpp"

namespace orni {

enum class CalibrationParameter {
  kMemberDiameterScale,  ///< wing.member_diameter_scale (spar details)
  kBodyDragArea,         ///< body.drag_area_m2 (parasite drag)
  kHingeX,               ///< kinematics.hinge_x_m (CG position relative to the hinge)
  kHingeZ,               ///< kinematics.hinge_z_m
  kTailArm,              ///< tail.arm_m
  kPitchInertia,         ///< body.pitch_inertia_kgm2
};
/// The vehicle-file key ("wing.member_diameter_scale", ...).
const char* keyOf(CalibrationParameter p);
/// The parameter of a key, or false.
bool parseCalibrationParameter(const std::string& key, CalibrationParameter* p);
/// Read / write the parameter's value on a vehicle (SI = file units for these keys).
double valueOf(const VehicleModel& v, CalibrationParameter p);
void setValue(VehicleModel* v, CalibrationParameter p, double value);

struct CalibrationVariable {
  CalibrationParameter parameter = CalibrationParameter::kBodyDragArea;
  double initial = 0.0, lower = 0.0, upper = 0.0;
};

struct CalibrationOptions {
  std::vector<CalibrationVariable> variables;  ///< 1-3, distinct, lower <= initial <= upper
  OperatingPoint target;                       ///< published trim point (theta, U, tail, f)
  SettledFlightOptions settled;                ///< free flights of each evaluation
  double tolerance = 0.01;  ///< converged when |theta err| <= tol deg, |U err| <= tol m/s, |climb
                            ///< angle| <= tol deg
  int max_iterations = 20;
  bool IsValid(std::string* why) const;
};

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
