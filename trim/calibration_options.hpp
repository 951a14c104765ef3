// Calibration options (trim/calibration.hpp); light header for the study files.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/model/vehicle_fields.hpp"
#include "core/model/vehicle_model.hpp"
#include "trim/settled_flight_options.hpp"

namespace orni {

/// A calibration parameter: one of the vehicle numbers of calibrationKeys(), read and written
/// through its accessor (core/model/vehicle_fields.hpp).
struct CalibrationParameter {
  const VehicleNumber* number = nullptr;
  friend bool operator==(CalibrationParameter a, CalibrationParameter b) {
    return a.number == b.number;
  }
};
/// The vehicle keys a calibration may vary: wing.member_diameter_scale (spar details),
/// body.drag_area_m2 (parasite drag), kinematics.hinge_x_m and hinge_z_m (the CG relative to the
/// hinge), tail.arm_m, body.pitch_inertia_kgm2 and wing.p3_aft_of_le_m (the universal joint on
/// the root chord). SI = file units for each.
const std::vector<std::string_view>& calibrationKeys();
/// "wing.member_diameter_scale, body.drag_area_m2, ..." (messages).
std::string calibrationKeyList();
/// The vehicle-file key ("wing.member_diameter_scale", ...); "?" for no parameter.
std::string keyOf(CalibrationParameter p);
/// The parameter of a key, or false.
bool parseCalibrationParameter(const std::string& key, CalibrationParameter* p);
/// The parameter of a key of calibrationKeys(); throws std::invalid_argument for another key.
CalibrationParameter calibrationParameter(const std::string& key);
/// Read / write the parameter's value on a vehicle (SI = file units for these keys).
double valueOf(const VehicleModel& v, CalibrationParameter p);
void setValue(VehicleModel* v, CalibrationParameter p, double value);

struct CalibrationVariable {
  CalibrationParameter parameter;
  double initial = 0.0, lower = 0.0, upper = 0.0;
};

struct CalibrationOptions {
  std::vector<CalibrationVariable> variables;  ///< 1-3, distinct, lower <= initial <= upper
  OperatingPoint target;                       ///< published trim point (theta, U, tail, f)
  SettledFlightOptions settled;                ///< free flights of each evaluation
  double tolerance = 0.01;  ///< converged when |theta err| <= tol deg, |U err| <= tol m/s, |climb
                            ///< angle| <= tol deg
  int max_iterations = 20;
  /// First solve the cheaper Eq. (4) version (tethered cycle means in equilibrium at the target)
  /// from the initial values, then the free-flight one from its result: the settled free flight
  /// needs a vehicle that roughly flies to settle at all.
  bool tethered_first = true;
  bool IsValid(std::string* why) const;
};

}  // namespace orni
