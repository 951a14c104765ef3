#include "studies/runner/commands/calibrate_command.hpp"

#include <iostream>

#include "core/model/frames.hpp"
#include "trim/calibration.hpp"
#include "studies/runner/commands/run_info.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"

namespace orni::studies {

int runCalibrateStudy(const Study& study, const std::filesystem::path& out_dir) {
  const orni::CalibrationOptions& o = study.calibrate();
  const orni::CalibrationSummary s = orni::calibrate(study.vehicle, o);

  writeFileAtomic(out_dir / "study.resolved.toml", resolvedStudyToml(study));
  CsvTable t;
  std::vector<std::vector<double>> cols(o.variables.size());
  std::vector<double> ok, theta, speed, climb, drift;
  for (const orni::CalibrationEvaluation& e : s.log) {
    for (std::size_t i = 0; i < o.variables.size(); ++i) cols[i].push_back(e.values[i]);
    ok.push_back(e.settled.ok ? 1.0 : 0.0);
    theta.push_back(e.settled.theta_mean_rad * kRadToDeg);
    speed.push_back(e.settled.airspeed_mps);
    climb.push_back(e.settled.climb_angle_rad * kRadToDeg);
    drift.push_back(e.settled.theta_drift_rad * kRadToDeg);
  }
  for (std::size_t i = 0; i < o.variables.size(); ++i)
    t.addColumn(orni::keyOf(o.variables[i].parameter), "file units", cols[i]);
  t.addColumn("settled", "1=yes", ok);
  t.addColumn("theta_mean", "deg", theta);
  t.addColumn("airspeed", "m/s", speed);
  t.addColumn("climb_angle", "deg", climb);
  t.addColumn("theta_drift", "deg", drift);
  writeFileAtomic(out_dir / "calibration.csv", t.toString());

  orni::VehicleModel calibrated = study.vehicle;
  JsonObject values;
  for (std::size_t i = 0; i < o.variables.size(); ++i) {
    orni::setValue(&calibrated, o.variables[i].parameter, s.values[i]);
    values.set(orni::keyOf(o.variables[i].parameter), s.values[i]);
  }
  writeFileAtomic(out_dir / "calibrated_vehicle.toml",
                  vehicleToToml({calibrated, study.design_point}));

  JsonObject summary;
  summary.set("kind", "calibrate")
      .set("status", s.converged ? "ok" : "not_converged")
      .set("message", s.message)
      .set("wall_time_s", s.wall_time_s)
      .set("version", versionString())
      .set("converged", s.converged)
      .set("values", values)
      .set("target", JsonObject()
                         .set("theta_mean_deg", o.target.theta_rad * kRadToDeg)
                         .set("speed_mps", o.target.speed_mps)
                         .set("tail_angle_deg", o.target.tail_angle_rad * kRadToDeg)
                         .set("freq_hz", o.target.freq_hz))
      .set("settled", JsonObject()
                          .set("theta_mean_deg", s.settled.theta_mean_rad * kRadToDeg)
                          .set("airspeed_mps", s.settled.airspeed_mps)
                          .set("climb_angle_deg", s.settled.climb_angle_rad * kRadToDeg)
                          .set("theta_drift_deg", s.settled.theta_drift_rad * kRadToDeg))
      .set("theta_error_deg", s.theta_error_deg)
      .set("speed_error_mps", s.speed_error_mps)
      .set("climb_angle_deg", s.climb_angle_deg)
      .set("iterations", s.iterations)
      .set("evaluations", s.evaluations)
      .set("ceres_report", s.ceres_report);
  writeFileAtomic(out_dir / "summary.json", summary.toString() + "\n");
  std::cout << study.name << ": " << s.message << "\n  -> " << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
