#include "studies/runner/config/calibrate_section.hpp"

#include "core/model/frames.hpp"

namespace orni::studies {

std::vector<std::string> calibrateSectionKeys() {
  return {"theta_mean_deg", "speed_mps", "tail_angle_deg", "freq_hz", "settled_cycles",
          "window_cycles",  "tolerance", "max_iterations", "variables"};
}

orni::CalibrationOptions readCalibrateSection(TableReader& c, const orni::VehicleModel& vehicle) {
  orni::CalibrationOptions o;
  const orni::OperatingPoint& op = vehicle.operating_point;
  o.target.theta_rad =
      c.optionalDouble("theta_mean_deg", op.theta_rad * kRadToDeg, Range::open(-90.0, 90.0)) *
      kDegToRad;
  o.target.speed_mps = c.optionalDouble("speed_mps", op.speed_mps, Range::positive());
  o.target.tail_angle_rad =
      c.optionalDouble("tail_angle_deg", op.tail_angle_rad * kRadToDeg, Range::open(-90.0, 90.0)) *
      kDegToRad;
  o.target.freq_hz = c.optionalDouble("freq_hz", op.freq_hz, Range::openClosed(0.0, 200.0));
  o.settled.cycles = c.optionalInt("settled_cycles", o.settled.cycles, 6, 10000);
  o.settled.window_cycles =
      c.optionalInt("window_cycles", o.settled.cycles / 3, 1, o.settled.cycles - 1);
  o.tolerance = c.optionalDouble("tolerance", o.tolerance, Range::positive());
  o.max_iterations = c.optionalInt("max_iterations", o.max_iterations, 1, 200);
  std::vector<TableReader> vars =
      c.optionalTableArray("variables", {"key", "initial", "lower", "upper"});
  if (vars.empty() || vars.size() > 3)
    throw c.valueError("variables", "1 to 3 [[calibrate.variables]] tables",
                       std::to_string(vars.size()));
  for (TableReader& t : vars) {
    orni::CalibrationVariable v;
    const std::string key = t.requiredString("key");
    if (!orni::parseCalibrationParameter(key, &v.parameter))
      throw t.valueError("key",
                         "one of wing.member_diameter_scale, body.drag_area_m2, "
                         "kinematics.hinge_x_m, kinematics.hinge_z_m, tail.arm_m, "
                         "body.pitch_inertia_kgm2, wing.p3_aft_of_le_m",
                         "\"" + key + "\"");
    for (const orni::CalibrationVariable& w : o.variables)
      if (w.parameter == v.parameter) throw t.valueError("key", "a key not listed before", key);
    v.lower = t.requiredDouble("lower", Range::any());
    v.upper = t.requiredDouble("upper", Range::any());
    if (!(v.lower < v.upper))
      throw t.valueError("upper", "a number > lower = " + std::to_string(v.lower),
                         std::to_string(v.upper));
    v.initial = t.optionalDouble("initial", orni::valueOf(vehicle, v.parameter), Range::any());
    if (!(v.initial >= v.lower && v.initial <= v.upper))
      throw t.valueError("initial", "a number in [lower, upper]", std::to_string(v.initial));
    t.finish();
    o.variables.push_back(v);
  }
  c.finish();
  return o;
}

void writeCalibrateSection(const orni::CalibrationOptions& o, TomlWriter& out) {
  out.header({"calibrate"});
  out.scaled("theta_mean_deg", o.target.theta_rad, kDegToRad);
  out.number("speed_mps", o.target.speed_mps);
  out.scaled("tail_angle_deg", o.target.tail_angle_rad, kDegToRad);
  out.number("freq_hz", o.target.freq_hz);
  out.integer("settled_cycles", o.settled.cycles);
  out.integer("window_cycles", o.settled.window_cycles);
  out.number("tolerance", o.tolerance);
  out.integer("max_iterations", o.max_iterations);
  for (const orni::CalibrationVariable& v : o.variables) {
    out.arrayHeader({"calibrate", "variables"});
    out.string("key", orni::keyOf(v.parameter));
    out.number("initial", v.initial);
    out.number("lower", v.lower);
    out.number("upper", v.upper);
  }
}

}  // namespace orni::studies
