#include "studies/runner/commands/trim_command.hpp"
#include "studies/runner/output/console.hpp"

#include <limits>
#include <string>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/commands/cycle_means_json.hpp"
#include "studies/runner/commands/periodic_trim_command.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "studies/runner/plotting/trim_figures.hpp"
#include "trim/trim_solver.hpp"

namespace orni::studies {

namespace {

// Solver-unit value of an unknown (deg, m/s, deg, Hz).
double fileUnits(const OperatingPoint& p, TrimUnknown u) {
  return unknownValue(p, u) / trimUnknownScale(u);
}

JsonObject unknownsObject(const OperatingPoint& p) {
  JsonObject o;
  for (TrimUnknown u : kAllTrimUnknowns) o.set(trimUnknownName(u), fileUnits(p, u));
  return o;
}

// Every periodic run: which iteration, what for, where, and the Eq. (4) residual there (no value
// for a failed run).
CsvTable evaluationTable(const TrimSummary& s) {
  using E = TrimEvaluationRecord;
  auto ifOk = [](const E& e, double v) {
    return e.result.ok ? v : std::numeric_limits<double>::quiet_NaN();
  };
  return RowTable("trim_iterations.csv", s.evaluation_log)
      .number("evaluation", [](const E& e) { return e.index; })
      .number("iteration", [](const E& e) { return e.iteration; })
      .number("purpose", [](const E& e) { return static_cast<int>(e.purpose); })
      .number("ok", [](const E& e) { return e.result.ok ? 1.0 : 0.0; })
      .number("cycles", [](const E& e) { return e.result.cycles; })
      .number("theta_mean", [](const E& e) { return fileUnits(e.point, TrimUnknown::kThetaMean); })
      .number("speed", [](const E& e) { return fileUnits(e.point, TrimUnknown::kSpeed); })
      .number("tail_angle", [](const E& e) { return fileUnits(e.point, TrimUnknown::kTailAngle); })
      .number("freq", [](const E& e) { return fileUnits(e.point, TrimUnknown::kFreq); })
      .number("FV_mean", [&](const E& e) { return ifOk(e, e.result.mean.FV_N); })
      .number("FH_mean", [&](const E& e) { return ifOk(e, e.result.mean.FH_N); })
      .number("M_mean", [&](const E& e) { return ifOk(e, e.result.mean.M_Nm); })
      .number("residual_FV", [&](const E& e) { return ifOk(e, e.residual.FV_N); })
      .number("residual_FH", [&](const E& e) { return ifOk(e, e.residual.FH_N); })
      .number("residual_M", [&](const E& e) { return ifOk(e, e.residual.M_Nm); })
      .number("residual_scaled_max", [&](const E& e) { return ifOk(e, e.scaled_max); })
      .table();
}

// Every solver iteration: the accepted iterate and its residual.
CsvTable progressTable(const TrimSummary& s) {
  using R = TrimIterationRecord;
  return RowTable("trim_progress.csv", s.iteration_log)
      .number("iteration", [](const R& r) { return r.iteration; })
      .number("evaluations", [](const R& r) { return r.evaluations; })
      .number("theta_mean", [](const R& r) { return fileUnits(r.point, TrimUnknown::kThetaMean); })
      .number("speed", [](const R& r) { return fileUnits(r.point, TrimUnknown::kSpeed); })
      .number("tail_angle", [](const R& r) { return fileUnits(r.point, TrimUnknown::kTailAngle); })
      .number("freq", [](const R& r) { return fileUnits(r.point, TrimUnknown::kFreq); })
      .number("cost", [](const R& r) { return r.cost; })
      .number("residual_scaled_max", [](const R& r) { return r.scaled_max; })
      .number("step_norm", [](const R& r) { return r.step_norm; })
      .number("trust_region_radius", [](const R& r) { return r.trust_region_radius; })
      .number("step_successful", [](const R& r) { return r.step_successful ? 1.0 : 0.0; })
      .table();
}

// Stage 1 (paper Eq. 4, tethered means): its solution, residual and means, named as such.
JsonObject stage1Object(const TrimSummary& s) {
  const OperatingPoint& p = s.refined_in_free_flight ? s.tethered_solution : s.solution;
  const TrimResidual& r = s.refined_in_free_flight ? s.tethered_residual : s.residual;
  JsonObject o;
  return setOperatingPoint(o, p)
      .set("residual", JsonObject().set("FV_N", r.FV_N).set("FH_N", r.FH_N).set("M_Nm", r.M_Nm))
      .set("mean", cycleMeansJson(s.mean));
}

// Stage 2 (level settled free flight from stage 1): whether it ran, how it ended, how far it moved.
JsonObject stage2Object(const TrimSummary& s) {
  JsonObject o;
  o.set("applied", s.refined_in_free_flight);
  if (!s.refined_in_free_flight) return o;
  o.set("message", s.free_flight_trim_message)
      .set("settled_free_flights", s.free_flight_trim_evaluations)
      .set("settled_climb_angle_deg", s.free_flight_climb_angle_rad * kRadToDeg)
      .set("delta_theta_mean_deg",
           (s.solution.theta_rad - s.tethered_solution.theta_rad) * kRadToDeg)
      .set("delta_speed_mps", s.solution.speed_mps - s.tethered_solution.speed_mps)
      .set("delta_tail_angle_deg",
           (s.solution.tail_angle_rad - s.tethered_solution.tail_angle_rad) * kRadToDeg);
  return o;
}

}  // namespace

JsonObject freeFlightObject(const FreeFlightVerification& v) {
  JsonObject o;
  o.set("status", toString(v.status)).set("message", v.message);
  if (v.status == FreeFlightStatus::kBounded || v.status == FreeFlightStatus::kUnbounded)
    o.set("bounded", v.bounded);
  else
    o.setNull("bounded");
  o.set("norm_ratio_max", v.norm_ratio_max)
      .set("theta_min_deg", v.theta_min_rad * kRadToDeg)
      .set("theta_max_deg", v.theta_max_rad * kRadToDeg)
      .set("altitude_p2p_m", v.altitude_p2p_m)
      .set("dominant_freq_hz", v.dominant_freq_hz);
  return o;
}

int runTrimStudy(const Study& study, const std::filesystem::path& out_dir) {
  if (study.trim.method == TrimMethod::kPeriodic) return runPeriodicTrimStudy(study, out_dir);
  const FlightCoreModel model(study.vehicle);
  const TrimSummary s = solveTrim(model, study.trim);

  writeFileAtomic(out_dir / "study.resolved.toml", resolvedStudyToml(study));
  writeFileAtomic(out_dir / "trim_iterations.csv", evaluationTable(s).toString());
  writeFileAtomic(out_dir / "trim_progress.csv", progressTable(s).toString());

  std::vector<std::string> unknowns;
  for (TrimUnknown u : s.unknowns) unknowns.emplace_back(trimUnknownName(u));
  JsonObject summary = summaryHeader("trim", toString(s.status), s.message, s.wall_time_s);
  summary.set("converged", s.converged);
  setOperatingPoint(summary, s.solution)
      .set("residual", JsonObject()
                           .set("FV_N", s.residual.FV_N)
                           .set("FH_N", s.residual.FH_N)
                           .set("M_Nm", s.residual.M_Nm))
      .set("free_flight", freeFlightObject(s.free_flight))
      .set("termination", toString(s.termination))
      .set("solve", s.least_squares ? "least_squares" : "square")
      .setStrings("unknowns", unknowns)
      .setStrings("at_bound", s.at_bound)
      .set("residual_scaled", JsonObject()
                                  .set("FV", s.scaled_residual[0])
                                  .set("FH", s.scaled_residual[1])
                                  .set("M", s.scaled_residual[2])
                                  .set("max", s.scaled_residual_max)
                                  .set("tolerance", study.trim.residual_tol))
      .set("weight_N", s.reference.weight_N)
      .set("mean_chord_m", s.reference.length_m)
      .set("mean", cycleMeansJson(s.mean))
      .set("residual_source",
           s.refined_in_free_flight
               ? "residual, residual_scaled and mean are stage 1 (the Eq. (4) tethered means at "
                 "stage1_equation4), not at the free-flight-refined trim point above"
               : "residual, residual_scaled and mean are at the trim point above (no "
                 "free-flight refinement)")
      .set("stage1_equation4", stage1Object(s))
      .set("stage2_free_flight_refinement", stage2Object(s))
      .set("initial", unknownsObject(study.trim.initial))
      .set("iterations", s.iterations)
      .set("evaluations", s.evaluations)
      .set("residual_evaluations", s.residual_evaluations)
      .set("derivative_evaluations", s.derivative_evaluations)
      .set("failed_evaluations", s.failed_evaluations)
      .set("ceres", JsonObject()
                        .set("method", "Levenberg-Marquardt, dense QR, bounds; central differences")
                        .set("termination_message", s.ceres_message)
                        .set("report", s.ceres_report))
      .set("integrator", JsonObject()
                             .set("rel_tol", study.trim.simulation.rel_tol)
                             .set("steady_tol", study.trim.simulation.steady_tol)
                             .set("max_cycles", study.trim.simulation.cycles)
                             .set("derivative_cycles", study.trim.derivative_cycles));
  writeSummary(out_dir, summary);
  drawFigure(out_dir, "trim_convergence", trimConvergenceFigure(study, s, study.trim.residual_tol));
  consoleOut() << study.name << ": " << s.BriefReport() << "\n  " << s.message << "\n  -> "
            << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
