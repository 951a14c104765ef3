// The [calibrate] section of a study of kind "calibrate" (trim/calibration.hpp):
//
//   [calibrate]
//   theta_mean_deg = 9.2     # target: the published trim point (default: the vehicle's
//   speed_mps = 10.8         #   operating point)
//   tail_angle_deg = 11.85
//   freq_hz = 12.0
//   settled_cycles = 120     # free flight of each evaluation, [6, 10000]
//   window_cycles = 40       # the last cycles averaged, [1, settled_cycles - 1]
//   tolerance = 0.01         # deg, m/s, deg
//   max_iterations = 20      # [1, 200]
//
//   [[calibrate.variables]]  # 1 to 4 of them (three residuals: a fourth leaves a null direction)
//   key = "body.drag_area_m2"   # wing.member_diameter_scale, body.drag_area_m2,
//                               # kinematics.hinge_x_m, kinematics.hinge_z_m, tail.arm_m,
//                               # body.pitch_inertia_kgm2, wing.p3_aft_of_le_m,
//                               # aero.suction_efficiency, wing.skin.pretension_N_per_m
//   initial = 0.007
//   lower = 0.0              # the physical range of the value ...
//   upper = 0.05
//   source = "C_D 0.1-1 on the frontal area"   # ... and where it comes from (optional)
#pragma once

#include <vector>

#include "core/model/vehicle_model.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "trim/calibration_options.hpp"

namespace orni::studies {

std::vector<std::string> calibrateSectionKeys();
/// Reads [calibrate]; the target defaults to `design_point` (the vehicle file's
/// [operating_point]), a variable's initial value to `vehicle`'s.
orni::CalibrationOptions readCalibrateSection(TableReader& section,
                                              const orni::VehicleModel& vehicle,
                                              const orni::OperatingPoint& design_point);
void writeCalibrateSection(const orni::CalibrationOptions& o, TomlWriter& out);

}  // namespace orni::studies
