#include "studies/runner/commands/calibrate_command.hpp"
#include "studies/runner/output/console.hpp"

#include <cmath>

#include "core/model/frames.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "trim/calibration.hpp"

namespace orni::studies {

namespace {
// calibration.csv: one row per settled flight (or tethered Eq. 4 run) of the calibration.
CsvTable calibrationTable(const orni::CalibrationOptions& o,
                          const std::vector<orni::CalibrationEvaluation>& log) {
  using E = orni::CalibrationEvaluation;
  RowTable<E> t("calibration.csv", log);
  for (std::size_t i = 0; i < o.variables.size(); ++i)
    t.number(orni::keyOf(o.variables[i].parameter), "file units",
             [i](const E& e) { return e.values[i]; });
  // The solver's residuals: stage 0 Eq. (4) in percent of the weight (FV - W, FH, M / c_mean);
  // otherwise theta error (deg), speed error (0.1 m/s), climb angle (deg).
  return t.number("stage", [](const E& e) { return e.stage; })
      .number("settled", [](const E& e) { return e.settled.ok ? 1.0 : 0.0; })
      .number("theta_mean", [](const E& e) { return e.settled.theta_mean_rad * kRadToDeg; })
      .number("airspeed", [](const E& e) { return e.settled.airspeed_mps; })
      .number("climb_angle", [](const E& e) { return e.settled.climb_angle_rad * kRadToDeg; })
      .number("theta_drift", [](const E& e) { return e.settled.theta_drift_rad * kRadToDeg; })
      .number("residual_1", [](const E& e) { return e.residual[0]; })
      .number("residual_2", [](const E& e) { return e.residual[1]; })
      .number("residual_3", [](const E& e) { return e.residual[2]; })
      .table();
}
}  // namespace

int runCalibrateStudy(const Study& study, const std::filesystem::path& out_dir) {
  orni::CalibrationOptions o = study.calibrate();
  writeFileAtomic(out_dir / "study.resolved.toml", resolvedStudyToml(study));
  // Progress of a long calibration: the evaluations so far, rewritten atomically after each.
  o.on_evaluation = [&](const std::vector<orni::CalibrationEvaluation>& log) {
    writeFileAtomic(out_dir / "calibration.csv", calibrationTable(o, log).toString());
  };
  const orni::CalibrationSummary s = orni::calibrate(study.vehicle, o);

  writeFileAtomic(out_dir / "calibration.csv", calibrationTable(o, s.log).toString());

  orni::VehicleModel calibrated = study.vehicle;
  JsonObject values;
  // Every value with its range, its source and how well the target fixes it.
  std::vector<JsonObject> fitted;
  const orni::CalibrationConditioning& k = s.conditioning;
  for (std::size_t i = 0; i < o.variables.size(); ++i) {
    const orni::CalibrationVariable& v = o.variables[i];
    orni::setValue(&calibrated, v.parameter, s.values[i]);
    values.set(orni::keyOf(v.parameter), s.values[i]);
    JsonObject f;
    f.set("key", orni::keyOf(v.parameter))
        .set("value", s.values[i])
        .set("lower", v.lower)
        .set("upper", v.upper)
        .set("source", v.source)
        .set("inside_range", !s.at_lower[i] && !s.at_upper[i])
        .set("binds", s.at_lower[i] ? "lower" : s.at_upper[i] ? "upper" : "none");
    if (k.ok) {
      f.set("d_theta_deg_per_unit", k.jacobian[i][0])
          .set("d_speed_mps_per_unit", k.jacobian[i][1])
          .set("d_climb_deg_per_unit", k.jacobian[i][2]);
      f.set("null_direction_component", k.null_component[i]);
      if (std::isfinite(k.determined_within[i]))
        f.set("determined_within", k.determined_within[i]);
      else
        f.set("determined_within", "undetermined (null direction)");
    }
    fitted.push_back(f);
  }
  JsonObject conditioning;
  conditioning.set("ok", k.ok).set("message", k.message);
  if (k.ok) {
    conditioning.set("singular_values", k.singular_values)
        .set("band", JsonObject()
                         .set("theta_deg", o.band.theta_deg)
                         .set("speed_mps", o.band.speed_mps)
                         .set("climb_deg", o.band.climb_deg));
    if (std::isfinite(k.condition_number))
      conditioning.set("condition_number", k.condition_number);
    else
      conditioning.set("condition_number", "inf (rank-deficient)");
  }
  writeFileAtomic(out_dir / "calibrated_vehicle.toml",
                  vehicleToToml({calibrated, study.design_point}));

  JsonObject summary =
      summaryHeader("calibrate", s.converged ? "ok" : "not_converged",
                    s.message, s.wall_time_s);
  summary.set("converged", s.converged)
      .set("values", values)
      .setObjects("fitted", fitted)
      .set("conditioning", conditioning)
      .set("target", JsonObject()
                         .set("theta_mean_deg", o.target.theta_rad * kRadToDeg)
                         .set("speed_mps", o.target.speed_mps)
                         .set("tail_angle_deg", o.target.tail_angle_rad * kRadToDeg)
                         .set("freq_hz", o.target.freq_hz))
      .set("settled", JsonObject()
                          .set("theta_mean_deg", s.settled.theta_mean_rad * kRadToDeg)
                          .set("airspeed_mps", s.settled.airspeed_mps)
                          .set("climb_angle_deg", s.settled.climb_angle_rad * kRadToDeg)
                          .set("theta_drift_deg", s.settled.theta_drift_rad * kRadToDeg)
                          .set("ok", s.settled.ok)
                          .set("message", s.settled.message))
      .set("theta_error_deg", s.theta_error_deg)
      .set("speed_error_mps", s.speed_error_mps)
      .set("climb_angle_deg", s.climb_angle_deg)
      .set("iterations", s.iterations)
      .set("evaluations", s.evaluations)
      .set("ceres_report", s.ceres_report);
  writeSummary(out_dir, summary);
  consoleOut() << study.name << ": " << s.message << "\n  -> " << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
