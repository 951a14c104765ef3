#include "studies/runner/config/calibrate_section.hpp"

#include "core/model/frames.hpp"

namespace orni::studies {

using orni::field;

std::vector<std::string> calibrateSectionKeys() {
  return {"theta_mean_deg", "speed_mps", "tail_angle_deg", "freq_hz", "settled_cycles",
          "window_cycles",  "tolerance", "max_iterations", "tethered_first", "variables"};
}

orni::CalibrationOptions readCalibrateSection(TableReader& c, const orni::VehicleModel& vehicle,
                                              const orni::OperatingPoint& design_point) {
  orni::CalibrationOptions o;
  const orni::OperatingPoint& op = design_point;
  o.target.theta_rad =
      c.optionalDouble(field("calibrate.theta_mean_deg"), op.theta_rad * kRadToDeg) * kDegToRad;
  o.target.speed_mps = c.optionalDouble(field("calibrate.speed_mps"), op.speed_mps);
  o.target.tail_angle_rad =
      c.optionalDouble(field("calibrate.tail_angle_deg"), op.tail_angle_rad * kRadToDeg) *
      kDegToRad;
  o.target.freq_hz = c.optionalDouble(field("calibrate.freq_hz"), op.freq_hz);
  o.settled.cycles = c.optionalInt(field("calibrate.settled_cycles"), o.settled.cycles);
  o.settled.window_cycles =
      c.optionalInt(field("calibrate.window_cycles"), o.settled.cycles / 3);
  if (o.settled.window_cycles > o.settled.cycles - 1)
    throw c.valueError("window_cycles",
                       "an integer in [1, " + std::to_string(o.settled.cycles - 1) +
                           "] (below settled_cycles)",
                       sourceText(*c.table().get("window_cycles")));
  o.tolerance = c.optionalDouble(field("calibrate.tolerance"), o.tolerance);
  o.max_iterations = c.optionalInt(field("calibrate.max_iterations"), o.max_iterations);
  o.tethered_first = c.optionalBool("tethered_first", o.tethered_first);
  std::vector<TableReader> vars =
      c.optionalTableArray("variables", {"key", "initial", "lower", "upper", "source"});
  if (vars.empty() || vars.size() > 4)
    throw c.valueError("variables", "1 to 4 [[calibrate.variables]] tables",
                       std::to_string(vars.size()));
  for (TableReader& t : vars) {
    orni::CalibrationVariable v;
    const std::string key = t.requiredString("key");
    if (!orni::parseCalibrationParameter(key, &v.parameter))
      throw t.valueError("key", "one of " + orni::calibrationKeyList(), "\"" + key + "\"");
    for (const orni::CalibrationVariable& w : o.variables)
      if (w.parameter == v.parameter) throw t.valueError("key", "a key not listed before", key);
    // Bounds and initial value inside the range of the key (SI = file units for these keys).
    const orni::FieldSpec& spec = field(key);
    const std::string in_key = " (the range of " + key + ")";
    v.lower = t.requiredDouble("lower", spec.range, in_key);
    v.upper = t.requiredDouble("upper", spec.range, in_key);
    if (!(v.lower < v.upper))
      throw t.valueError("upper", "a number > lower = " + orni::displayNumber(v.lower),
                         sourceText(*t.table().get("upper")));
    v.initial = t.has("initial") ? t.requiredDouble("initial", spec.range, in_key)
                                 : (t.take("initial"), orni::valueOf(vehicle, v.parameter));
    if (!(v.initial >= v.lower && v.initial <= v.upper))
      throw t.valueError("initial",
                         "a number in [lower, upper] = [" + orni::displayNumber(v.lower) + ", " +
                             orni::displayNumber(v.upper) + "]",
                         t.has("initial") ? sourceText(*t.table().get("initial"))
                                          : orni::displayNumber(v.initial) + " (the vehicle's)");
    if (t.has("source")) v.source = t.requiredString("source");
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
  out.boolean("tethered_first", o.tethered_first);
  for (const orni::CalibrationVariable& v : o.variables) {
    out.arrayHeader({"calibrate", "variables"});
    out.string("key", orni::keyOf(v.parameter));
    out.number("initial", v.initial);
    out.number("lower", v.lower);
    out.number("upper", v.upper);
    if (!v.source.empty()) out.string("source", v.source);
  }
}

}  // namespace orni::studies
