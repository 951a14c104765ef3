// [aeromap] of a study file (study_file.hpp documents the keys; ranges: the field table's
// aeromap.* entries).
#include <charconv>
#include <string>

#include "core/model/frames.hpp"
#include "studies/runner/config/study_reader.hpp"
#include "studies/runner/config/study_sections.hpp"

namespace orni::studies {

namespace {

using orni::field;

/// The value d in file units with d * si_per_file_unit == si exactly, when one exists.
double fileUnits(double si, double si_per_file_unit) {
  const std::string text = TomlWriter::scaledText(si, si_per_file_unit);
  double d = si / si_per_file_unit;
  std::from_chars(text.data(), text.data() + text.size(), d);
  return d;
}

/// An axis of the aero map at `key` ("speed_mps"), in the range of aeromap.<key>.
GridAxis readAeromapAxis(TableReader& am, const std::string& key) {
  return readGridAxis(am, key, field("aeromap." + key).range);
}

}  // namespace

GridAxis defaultTailAngleAxis(const OperatingPoint& point) {
  GridAxis axis;
  axis.values = {fileUnits(point.tail_angle_rad, orni::kDegToRad)};
  return axis;
}

void readAeromapSection(StudyDocument doc, Study& study) {
  TableReader am = doc.top.requiredTable(
      "aeromap", {"speed_mps", "freq_hz", "theta_deg", "tail_angle_deg", "wing_only", "cycles",
                  "rel_tol", "abs_tol", "separation_abs_tol", "steady_tol"});
  AeromapSettings& a = study.settings.emplace<AeromapSettings>();
  a.speed_mps = readAeromapAxis(am, "speed_mps");
  a.freq_hz = readAeromapAxis(am, "freq_hz");
  a.theta_deg = readAeromapAxis(am, "theta_deg");
  a.tail_angle_deg = am.has("tail_angle_deg") ? readAeromapAxis(am, "tail_angle_deg")
                                              : defaultTailAngleAxis(study.point);
  // A tail angle other than 0 (what a resolved study writes for a rig) on a vehicle without a
  // tail would be ignored: bad input (docs/design.md 3.2).
  if (am.has("tail_angle_deg") && !study.vehicle.tail.present)
    for (const double v : a.tail_angle_deg.values)
      if (v != 0.0)
        throw am.valueError("tail_angle_deg",
                            "0 or no tail angle: the vehicle has no [tail] (a tail angle would "
                            "be silently ignored)",
                            describeNode(*am.table().get("tail_angle_deg")));
  std::size_t points = 1;
  for (const GridAxis* axis : {&a.speed_mps, &a.freq_hz, &a.theta_deg, &a.tail_angle_deg}) {
    if (axis->values.size() > kMaxAeroMapPoints / points)
      throw am.valueError(
          "speed_mps", "a grid of at most " + std::to_string(kMaxAeroMapPoints) + " points",
          "a larger grid");
    points *= axis->values.size();
  }
  a.wing_only = am.optionalBool("wing_only", a.wing_only);
  SimulationOptions& o = a.options;
  o.cycles = am.optionalInt(field("aeromap.cycles"), o.cycles);
  readTolerances(am, o, "aeromap");
  std::string why;
  if (!o.IsValid(&why)) throwInvalidOptions(am, why);
  am.finish();
}

void writeAeromapSection(const AeromapSettings& a, TomlWriter& out) {
  out.header({"aeromap"});
  writeGridAxis(out, "speed_mps", a.speed_mps);
  writeGridAxis(out, "freq_hz", a.freq_hz);
  writeGridAxis(out, "theta_deg", a.theta_deg);
  writeGridAxis(out, "tail_angle_deg", a.tail_angle_deg);
  out.boolean("wing_only", a.wing_only, "true = the main wing alone (paper Fig. 5)");
  out.integer("cycles", a.options.cycles, "the maximum per point (each stops when steady)");
  writeTolerances(a.options, out);
}

}  // namespace orni::studies
