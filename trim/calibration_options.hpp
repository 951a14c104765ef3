// Calibration options (trim/calibration.hpp); light header for the study files.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/vehicle_fields.hpp"
#include "core/model/vehicle_model.hpp"
#include "trim/settled_flight_options.hpp"

namespace orni {

struct CalibrationEvaluation;  // trim/calibration.hpp

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
/// hinge), tail.arm_m, body.pitch_inertia_kgm2, wing.p3_aft_of_le_m (the universal joint on
/// the root chord), aero.suction_efficiency (the leading-edge suction a thin membrane section
/// realises) and wing.skin.pretension_N_per_m. SI = file units for each.
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
  /// Where the physical range [lower, upper] comes from (a reference, an estimate); shown with
  /// the fitted value wherever it is reported ("a fit is a fit").
  std::string source;
};

/// The band around the target within which the calibration's conditioning is judged: how far
/// each fitted value may move while the settled flight stays inside the band (the regression
/// tolerance of the published point, tests/regression/table3).
struct CalibrationBand {
  double theta_deg = 0.5, speed_mps = 0.3, climb_deg = 0.5;
};

struct CalibrationOptions {
  std::vector<CalibrationVariable> variables;  ///< 1-4, distinct, lower <= initial <= upper
  OperatingPoint target;                       ///< published trim point (theta, U, tail, f)
  SettledFlightOptions settled;                ///< free flights of each evaluation
  /// Converged when the residual vector (theta error in deg, U error in 0.1 m/s, climb angle in
  /// deg) has a norm <= tol: each |theta err| <= tol deg, |U err| <= 0.1 tol m/s, |climb| <= tol.
  double tolerance = 0.01;
  int max_iterations = 20;
  /// First solve the cheaper Eq. (4) version (tethered cycle means in equilibrium at the target)
  /// from the initial values, then the free-flight one from its result: the settled free flight
  /// needs a vehicle that roughly flies to settle at all.
  bool tethered_first = true;
  /// After the solve, central differences of the settled flight at the solution (2 per
  /// variable) give the Jacobian, its conditioning and how well the target determines each value.
  bool conditioning = true;
  CalibrationBand band;
  /// Called after every evaluation with the log so far (trim/calibration.hpp); the CLI writes
  /// calibration.csv from it, so a long calibration shows its progress and a kill keeps it.
  std::function<void(const std::vector<CalibrationEvaluation>&)> on_evaluation;
  bool IsValid(std::string* why) const;
};

}  // namespace orni
