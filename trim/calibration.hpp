// Calibration of vehicle values the paper leaves open against its published trim point (Table 3):
// find the values of up to four vehicle parameters for which the vehicle, flying freely at the
// published tail angle and frequency, settles into level flight at the published mean pitch and
// speed (free_flight_trim.hpp: settled means). Ceres Levenberg-Marquardt with bounds and central
// differences on the values scaled to their ranges; residuals (theta_mean - theta*) / 1 deg,
// (airspeed - U*) / (0.1 m/s) and the climb angle / 1 deg. Three residuals: a fourth value leaves
// a null direction, which the conditioning reports. No I/O.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/dynamics/simulation_options.hpp"
#include "core/model/vehicle_model.hpp"
#include "trim/calibration_options.hpp"
#include "trim/free_flight_trim.hpp"

namespace orni {

enum class CalibrationStage { kTethered = 0, kFreeFlight = 1, kConditioning = 2 };

struct CalibrationEvaluation {
  CalibrationStage stage = CalibrationStage::kFreeFlight;
  std::vector<double> values;
  SettledFlight settled;
  double residual[3] = {0, 0, 0};
};

/// How well the target determines the fitted values (linearised at the solution).
struct CalibrationConditioning {
  bool ok = false;      ///< the central differences all settled
  std::string message;  ///< why not
  /// d(theta deg, U m/s, climb deg)/d(value), 3 x n, by central differences of 1 % of each range.
  std::vector<std::array<double, 3>> jacobian;
  /// Singular values of the Jacobian with each value scaled by its range and each residual by
  /// the band (dimensionless: band widths per range), largest first; their ratio is the condition.
  std::vector<double> singular_values;
  double condition_number = 0.0;  ///< largest / smallest singular value; inf when rank-deficient
  /// Per value: the half-width it is determined to (file units) when the settled flight may lie
  /// anywhere inside the band, the others re-fitted (sum_j |J^+_ij| band_j); inf along a null
  /// direction (more values than the target determines).
  std::vector<double> determined_within;
  /// Per value: its largest component (range-scaled, of a unit vector) along a null direction of
  /// the scaled Jacobian; 0 when the fit is fully determined. With more values than residuals
  /// the null direction says which value the target leaves free: a component above 0.5 makes the
  /// value undetermined (determined_within inf), one below leaves it determined to within
  /// determined_within by the least-norm solution, plus that component times how far the free
  /// value may move.
  std::vector<double> null_component;
};

/// The conditioning of a fit from its Jacobian J (3 x n: theta error in deg, speed error in 0.1
/// m/s, climb angle in deg, per value scaled to its range, i.e. per unit of u in [1, 2]): the
/// per-unit Jacobian, the singular values of J with its rows divided by the band, the condition
/// number, each value's null_component and determined_within. Throws std::invalid_argument for a
/// J that is not 3 x variables.size().
CalibrationConditioning conditioningOfJacobian(const Eigen::MatrixXd& J,
                                               const std::vector<CalibrationVariable>& variables,
                                               const CalibrationBand& band);

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
  /// Per value: on (within 1e-6 of its range) its lower or upper bound, i.e. the range binds.
  std::vector<bool> at_lower, at_upper;
  CalibrationConditioning conditioning;  ///< when options.conditioning
};

/// Calibrate `base` (its other values unchanged). Throws std::invalid_argument for bad options.
CalibrationSummary calibrate(const VehicleModel& base, const CalibrationOptions& options);

}  // namespace orni
