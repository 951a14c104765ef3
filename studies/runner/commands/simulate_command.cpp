#include "studies/runner/commands/simulate_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "core/analysis/harmonics.hpp"
#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/frames.hpp"
#include "trim/trim_solver.hpp"
#include "studies/runner/commands/constrained_flight_output.hpp"
#include "studies/runner/commands/failed_run.hpp"
#include "studies/runner/commands/free_flight_command.hpp"
#include "studies/runner/commands/run_info.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/plotting/gnuplot.hpp"

namespace orni::studies {

namespace {

struct SimulationTrim {
  bool converged = false;
  OperatingPoint point;
  std::string message;
  JsonObject json;  ///< summary.json's "trim_point"
};

// The trim a simulation flies at ([simulate] at_trim): Eq. (4) refined in free flight at the
// study's frequency, from the study's point as the initial guess (trim/trim_solver.hpp).
SimulationTrim trimForSimulation(const Study& study) {
  TrimOptions options = defaultTrimOptions(study.vehicle);
  options.initial = study.point;
  options.verify_free_flight = false;  // the simulation is the check
  const TrimSummary t = solveTrim(FlightCoreModel(study.vehicle), options);
  SimulationTrim out;
  out.converged = t.converged;
  out.point = t.solution;
  out.message = t.message;
  out.json.set("converged", t.converged)
      .set("freq_hz", t.solution.freq_hz)
      .set("theta_mean_deg", t.solution.theta_rad * kRadToDeg)
      .set("speed_mps", t.solution.speed_mps)
      .set("tail_angle_deg", t.solution.tail_angle_rad * kRadToDeg)
      .set("message", t.message);
  return out;
}

template <typename Getter>
std::vector<double> column(const TimeHistory& h, Getter get) {
  std::vector<double> v;
  v.reserve(h.loads.size());
  for (const LoadSample& s : h.loads) v.push_back(get(s));
  return v;
}

CsvTable historyTable(const TimeHistory& h) {
  CsvTable t;
  t.addColumn("t", "s", h.t_s);
  std::vector<double> delta_deg;
  for (double d : h.delta_M_rad) delta_deg.push_back(d * kRadToDeg);
  t.addColumn("delta_M", "deg", delta_deg);
  t.addColumn("FV", "N", column(h, [](const LoadSample& s) { return s.FV_N; }));
  t.addColumn("FH", "N", column(h, [](const LoadSample& s) { return s.FH_N; }));
  t.addColumn("M", "N m", column(h, [](const LoadSample& s) { return s.M_Nm; }));
  t.addColumn("power_aero", "W", column(h, [](const LoadSample& s) { return s.power_aero_W; }));
  t.addColumn("power_hinge", "W", column(h, [](const LoadSample& s) { return s.power_hinge_W; }));
  t.addColumn("FV_wing_aero", "N", column(h, [](const LoadSample& s) { return s.FV_wing_aero_N; }));
  t.addColumn("FH_wing_aero", "N", column(h, [](const LoadSample& s) { return s.FH_wing_aero_N; }));
  t.addColumn("M_wing_aero", "N m", column(h, [](const LoadSample& s) { return s.M_wing_aero_Nm; }));
  t.addColumn("FV_wing_inertial", "N",
              column(h, [](const LoadSample& s) { return s.FV_wing_inertial_N; }));
  t.addColumn("FH_wing_inertial", "N",
              column(h, [](const LoadSample& s) { return s.FH_wing_inertial_N; }));
  t.addColumn("M_wing_inertial", "N m",
              column(h, [](const LoadSample& s) { return s.M_wing_inertial_Nm; }));
  t.addColumn("FV_tail", "N", column(h, [](const LoadSample& s) { return s.FV_tail_N; }));
  t.addColumn("FH_tail", "N", column(h, [](const LoadSample& s) { return s.FH_tail_N; }));
  t.addColumn("FH_body", "N", column(h, [](const LoadSample& s) { return s.FH_body_N; }));
  t.addColumn("M_tail", "N m", column(h, [](const LoadSample& s) { return s.M_tail_Nm; }));
  t.addColumn("separated_fraction", "-",
              column(h, [](const LoadSample& s) { return s.separated_fraction; }));
  t.addColumn("tip_deflection", "m",
              column(h, [](const LoadSample& s) { return s.tip_deflection_m; }));
  t.addColumn("tip_twist", "deg",
              column(h, [](const LoadSample& s) { return s.tip_twist_rad * kRadToDeg; }));
  return t;
}

CsvTable cycleTable(const SimulationSummary& s) {
  CsvTable t;
  std::vector<double> k, fv, fh, m, pa, ph;
  for (std::size_t i = 0; i < s.per_cycle.size(); ++i) {
    k.push_back(static_cast<double>(i + 1));
    fv.push_back(s.per_cycle[i].FV_N);
    fh.push_back(s.per_cycle[i].FH_N);
    m.push_back(s.per_cycle[i].M_Nm);
    pa.push_back(s.per_cycle[i].power_aero_W);
    ph.push_back(s.per_cycle[i].power_hinge_W);
  }
  t.addColumn("cycle", "-", k);
  t.addColumn("FV_mean", "N", fv);
  t.addColumn("FH_mean", "N", fh);
  t.addColumn("M_mean", "N m", m);
  t.addColumn("power_aero_mean", "W", pa);
  t.addColumn("power_hinge_mean", "W", ph);
  return t;
}

// Figure in the layout of paper Fig. 2: delta_M, FV, FH and M against time over the last (at most
// three) cycles, i.e. the periodic steady state, with the downstrokes shaded.
std::string loadsFigure(const Study& study, const SimulationSummary& s) {
  const double T = 1.0 / study.point.freq_hz;
  const int shown = std::min(3, s.cycles_run);
  const int first = s.cycles_run - shown;
  std::ostringstream g;
  g << "set multiplot layout 4,1 title \"" << study.name << " (tethered): U = "
    << study.point.speed_mps << " m/s, f = " << study.point.freq_hz
    << " Hz, theta = " << study.point.theta_rad * kRadToDeg << " deg, cycles " << first + 1
    << "-" << s.cycles_run << " of " << s.cycles_run
    << " (shaded: downstroke)\" noenhanced font ',13'\n";
  g << "set lmargin 12\nset rmargin 22\nset key outside right top vertical Left reverse\n";
  g << "set xrange [" << first * T << ":" << s.cycles_run * T << "]\n";
  for (int k = first; k < s.cycles_run; ++k)
    g << "set object " << k + 1 << " rect from " << (k + 0.25) * T << ", graph 0 to "
      << (k + 0.75) * T << ", graph 1 behind fc rgb '#e8e8f0' fs solid noborder\n";
  g << "set format x ''\n";
  g << "set ylabel '{/Symbol d}_M (deg)'\n"
       "plot 'histories.csv' skip 2 using 1:2 with lines lw 2 lc rgb '#333333' title 'flap angle'\n";
  g << "set ylabel 'F_V (N)'\n"
       "plot 'histories.csv' skip 2 using 1:3 with lines lw 2 lc rgb '#c0392b' title 'total', "
       "'' skip 2 using 1:8 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'wing aero', "
       "'' skip 2 using 1:11 with lines dt 3 lw 1.5 lc rgb '#27ae60' title 'wing inertia'\n";
  g << "set ylabel 'F_H (N)'\n"
       "plot 'histories.csv' skip 2 using 1:4 with lines lw 2 lc rgb '#c0392b' title 'total', "
       "'' skip 2 using 1:9 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'wing aero', "
       "'' skip 2 using 1:12 with lines dt 3 lw 1.5 lc rgb '#27ae60' title 'wing inertia'\n";
  g << "set format x '%g'\nset xlabel 'time (s)'\n";
  g << "set ylabel 'M_{CG} (N m)'\n"
       "plot 'histories.csv' skip 2 using 1:5 with lines lw 2 lc rgb '#c0392b' title 'total', "
       "'' skip 2 using 1:10 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'wing aero', "
       "'' skip 2 using 1:13 with lines dt 3 lw 1.5 lc rgb '#27ae60' title 'wing inertia'\n";
  g << "unset multiplot\n";
  return g.str();
}

double halfRange(const double* x, std::size_t n, std::size_t stride) {
  double lo = x[0], hi = x[0];
  for (std::size_t i = 1; i < n; ++i) {
    lo = std::min(lo, x[i * stride]);
    hi = std::max(hi, x[i * stride]);
  }
  return 0.5 * (hi - lo);
}

}  // namespace

int runSimulateStudy(const Study& given, const std::filesystem::path& out_dir) {
  const auto t0 = std::chrono::steady_clock::now();
  JsonObject summary;
  summary.set("kind", "simulate");

  // [simulate] at_trim: solve the trim first; a vehicle that does not trim is a reported outcome.
  Study study = given;
  JsonObject trim_point;
  if (study.at_trim) {
    const SimulationTrim t = trimForSimulation(study);
    trim_point = t.json;
    if (!t.converged) {
      summary.set("status", "not_converged")
          .set("message", "no trim at " + formatShortest(study.point.freq_hz) +
                              " Hz to fly at: " + t.message)
          .set("wall_time_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
                                  .count())
          .set("version", versionString())
          .set("mode", study.simulate.mode == FlightMode::kFree ? "free" : "tethered")
          .set("trim_point", trim_point);
      writeFileAtomic(out_dir / "study.resolved.toml", resolvedStudyToml(given));
      // Nothing was flown: the outputs of an earlier run must not pass for this one's.
      removeRunOutputs(out_dir, {"histories.csv", "cycles.csv", "zmp.csv", "spectra.csv"},
                       {"loads", "zmp", "flight", "cycle", "phase"});
      writeFileAtomic(out_dir / "summary.json", summary.toString() + "\n");
      std::cout << study.name << ": not_converged: no trim to fly at: " << t.message << "\n";
      return 0;
    }
    study.point = t.point;
  }

  if (study.simulate.mode == FlightMode::kFree)
    return runFreeFlightStudy(study, out_dir, study.at_trim ? &trim_point : nullptr, &given);

  const FlightCoreModel model(study.wing_only ? study.vehicle.mainWingAlone() : study.vehicle);
  TimeHistory history;
  SimulationOptions opts = study.simulate;
  opts.record_history = true;
  const SimulationSummary s = simulateTethered(model, study.point, opts, &history);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // A failed run (the integrator stopped) has no result: no CSV, no figure, no mean; only the
  // summary saying why. Outputs of an earlier run into the folder would pass for this run's.
  const bool failed = s.status == SimulationStatus::kFailed;
  // As given: with at_trim the resolved study keeps the initial guess and solves the same trim.
  writeFileAtomic(out_dir / "study.resolved.toml", resolvedStudyToml(given));
  std::optional<ConstrainedFlightTest> cft;
  if (failed) {
    removeRunOutputs(out_dir, {"histories.csv", "cycles.csv", "zmp.csv"}, {"loads", "zmp"});
  } else {
    writeFileAtomic(out_dir / "histories.csv",
                    historyTable(history).toString(static_cast<std::size_t>(study.history_every)));
    writeFileAtomic(out_dir / "cycles.csv", cycleTable(s).toString());
    // The constrained flight test (paper Fig. 9) of the last whole cycle.
    cft = lastCycleConstrainedFlightTest(study, model, history, opts.samples_per_cycle);
    if (cft) writeFileAtomic(out_dir / "zmp.csv", zmpTable(*cft).toString());
  }

  summary.set("status", toString(s.status))
      .set("message", s.message)
      .set("wall_time_s", wall_s)
      .set("version", versionString())
      .set("mode", "tethered")
      .set("cycles", s.cycles_run);
  if (failed) {
    summary.setNull("mean");
  } else {
    summary
        .set("mean", JsonObject()
                         .set("FV_N", s.mean.FV_N)
                         .set("FH_N", s.mean.FH_N)
                         .set("M_Nm", s.mean.M_Nm)
                         .set("power_W", s.mean.power_aero_W)
                         .set("hinge_power_W", s.mean.power_hinge_W))
        .set("steady_state_cycle", s.steady_state_cycle)
        .set("last_cycle_change", s.last_cycle_change);
  }
  summary.set("speed_mps", study.point.speed_mps)
      .set("freq_hz", study.point.freq_hz)
      .set("theta_deg", study.point.theta_rad * kRadToDeg)
      .set("tail_angle_deg", study.point.tail_angle_rad * kRadToDeg)
      .set("wing_only", study.wing_only);
  if (study.at_trim) summary.set("trim_point", trim_point);
  summary
      .set("aero_model", study.vehicle.aero.model == AeroModelKind::kMstTd ? "mst-td"
                                                                           : "delaurier1993")
      .set("structure", model.flexible ? "flexible" : "rigid")
      .set("strips", static_cast<int>(model.strips.size()))
      .set("wing_mass_kg", model.flexible ? model.flexible->modal->wing_mass_kg
                                          : model.wing_mass.total.mass_kg);
  // Harmonic content of the last cycle (samples_per_cycle points, endpoint excluded); only when
  // the history holds a whole cycle (a run that failed early may not).
  const std::size_t spc = static_cast<std::size_t>(opts.samples_per_cycle);
  if (!failed && history.loads.size() >= spc + 1) {
    const std::size_t start = history.loads.size() - 1 - spc;
    const std::size_t stride = sizeof(LoadSample) / sizeof(double);
    const double* fv = &history.loads[start].FV_N;
    const double* fh = &history.loads[start].FH_N;
    const double* mm = &history.loads[start].M_Nm;
    const Harmonic fv1 = periodHarmonic(fv, spc, 1, stride);
    const Harmonic fv2 = periodHarmonic(fv, spc, 2, stride);
    const Harmonic fh1 = periodHarmonic(fh, spc, 1, stride);
    const Harmonic fh2 = periodHarmonic(fh, spc, 2, stride);
    const Harmonic m1 = periodHarmonic(mm, spc, 1, stride);
    summary.set(
        "last_cycle",
        JsonObject()
            .set("FV_amplitude_1f_N", fv1.amplitude)
            .set("FV_amplitude_2f_N", fv2.amplitude)
            .set("FH_amplitude_1f_N", fh1.amplitude)
            .set("FH_amplitude_2f_N", fh2.amplitude)
            .set("M_amplitude_1f_Nm", m1.amplitude)
            .set("FV_peak_phase", peakPhase(fv, spc, stride))
            .set("FH_peak_phase", peakPhase(fh, spc, stride))
            .set("tip_deflection_amplitude_m",
                 halfRange(&history.loads[start].tip_deflection_m, spc, stride))
            .set("tip_twist_amplitude_deg",
                 kRadToDeg * halfRange(&history.loads[start].tip_twist_rad, spc, stride)));
  }
  if (cft) summary.set("constrained_flight_test", zmpSummary(*cft));
  summary.set("integrator", JsonObject()
                             .set("method", s.integrator_method)
                             .set("rel_tol", opts.rel_tol)
                             .set("steps", s.steps)
                             .set("rhs_evaluations", s.rhs_evaluations));
  writeFileAtomic(out_dir / "summary.json", summary.toString() + "\n");
  if (failed) return reportFailedRun(study, s.message, out_dir);
  drawFigure(out_dir, "loads", loadsFigure(study, s));
  if (cft) drawFigure(out_dir, "zmp", zmpFigureScript(study, *cft, s.cycles_run));
  std::cout << study.name << ": " << s.BriefReport() << "\n  -> " << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
