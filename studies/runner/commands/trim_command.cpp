#include "studies/runner/commands/trim_command.hpp"
#include "studies/runner/output/console.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/commands/cycle_means_json.hpp"
#include "studies/runner/commands/periodic_trim_command.hpp"
#include "studies/runner/commands/run_info.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
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

// Residual norm per iteration (log scale) with every residual run, and the unknowns per iteration.
std::string convergenceFigure(const Study& study, const TrimSummary& s, double tol) {
  int last = 0;
  for (const TrimEvaluationRecord& e : s.evaluation_log) last = std::max(last, e.iteration);
  // Stage 2 (free-flight refinement) moves the trim point after the last Eq. (4) iteration: shown
  // as open circles at x = last + 1 in the lower panel, so the figure ends at the reported point.
  const bool refined = s.refined_in_free_flight && s.converged;
  const double x2 = last + 1.0;
  std::ostringstream g;
  g << "set multiplot layout 2,1 title \"" << study.name << " trim (" << toString(s.status)
    << "), stage 1: paper Eq. (4) on tethered cycle means, max(|FV-W|, |FH|, |M|/c_mean) / W"
    << (refined ? "\\nstage 2: level settled free flight moves the trim point (open circles)"
                : "")
    << "\" noenhanced font ',13'\n";
  g << "set lmargin 12\nset rmargin 44\nset tmargin 4\n"
       "set key outside right top vertical Left reverse noenhanced\n";
  g << "set xrange [-0.2:" << last + 0.2 << "]\nset xlabel 'iteration'\nset xtics 1\n";
  g << "set logscale y\nset format y '10^{%L}'\nset ylabel 'scaled residual (-)'\n";
  double ymin = 0.1 * tol;
  for (const TrimIterationRecord& r : s.iteration_log)
    if (r.scaled_max > 0.0) ymin = std::min(ymin, 0.3 * r.scaled_max);
  g << "set yrange [" << ymin << ":*]\n";
  g << "plot 'trim_progress.csv' skip 2 using 1:8 with linespoints lw 2 pt 7 lc rgb '#c0392b' "
       "title 'accepted iterate', "
       "'trim_iterations.csv' skip 2 using ($3 == 0 && $4 == 1 ? $2 : 1/0):16 with points pt 6 "
       "ps 1.2 lc rgb '#2471a3' title 'residual runs (trial points)', "
    << tol << " with lines dt 2 lc rgb '#333333' title 'tolerance'\n";
  g << "unset logscale y\nset format y '%g'\nset yrange [*:*]\n";
  g << "set ylabel 'unknowns (deg, m/s, Hz)'\n";
  if (refined) {
    g << "set xrange [-0.2:" << x2 + 0.3 << "]\nset xtics add ('stage 2' " << x2 << ")\n";
    g << "set xlabel 'iteration (stage 1) / free-flight refinement (stage 2)'\n";
  }
  const char* kColours[3] = {"#9400d3", "#009e73", "#56b4e9"};  // gnuplot's first three
  g << "plot 'trim_progress.csv' skip 2 using 1:3 with linespoints lw 2 pt 7 lc rgb '"
    << kColours[0] << "' title 'theta mean (deg)', '' skip 2 using 1:4 with linespoints lw 2 pt 5 lc rgb '"
    << kColours[1] << "' title 'speed (m/s)', '' skip 2 using 1:5 with linespoints lw 2 pt 9 lc rgb '"
    << kColours[2] << "' title 'tail angle (deg)', '' skip 2 using 1:6 with linespoints lw 2 pt 11 "
       "lc rgb '#e69f00' title 'frequency (Hz)'";
  if (refined) {
    const double v[3] = {s.solution.theta_rad * kRadToDeg, s.solution.speed_mps,
                         s.solution.tail_angle_rad * kRadToDeg};
    const char* names[3] = {"theta", "U", "tail"};
    auto fixed2 = [](double x) {
      char b[32];
      std::snprintf(b, sizeof b, "%.2f", x);
      return std::string(b);
    };
    for (int k = 0; k < 3; ++k)
      g << ", '-' using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '" << kColours[k]
        << "' title 'stage 2: " << names[k] << " = " << fixed2(v[k]) << "'";
    g << "\n";
    for (int k = 0; k < 3; ++k) g << x2 << "," << formatShortest(v[k]) << "\ne\n";
  }
  g << "\n";
  g << "unset multiplot\n";
  return g.str();
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
  writeFileAtomic(out_dir / "summary.json", summary.toString() + "\n");
  drawFigure(out_dir, "trim_convergence", convergenceFigure(study, s, study.trim.residual_tol));
  consoleOut() << study.name << ": " << s.BriefReport() << "\n  " << s.message << "\n  -> "
            << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
