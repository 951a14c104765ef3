#include "studies/runner/commands/simulate_command.hpp"
#include "studies/runner/output/console.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <optional>

#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/last_cycle_harmonics.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/commands/constrained_flight_output.hpp"
#include "studies/runner/commands/cycle_means_json.hpp"
#include "studies/runner/commands/failed_run.hpp"
#include "studies/runner/commands/free_flight_command.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_stream.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/plotting/figure_rows.hpp"
#include "studies/runner/plotting/flight_figures.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "trim/trim_solver.hpp"

namespace orni::studies {

const std::vector<CsvColumn>& historyColumns() {
  static const std::vector<CsvColumn> columns = declaredColumns(
      "histories.csv", {"t", "delta_M", "FV", "FH", "M", "power_aero", "power_hinge",
                        "FV_wing_aero", "FH_wing_aero", "M_wing_aero", "FV_wing_inertial",
                        "FH_wing_inertial", "M_wing_inertial", "FV_tail", "FH_tail", "FH_body",
                        "M_tail", "separated_fraction", "tip_deflection", "tip_twist"});
  return columns;
}

void historyRow(double t_s, double delta_M_rad, const LoadSample& l, double* row) {
  const double values[] = {t_s,
                           delta_M_rad * kRadToDeg,
                           l.FV_N,
                           l.FH_N,
                           l.M_Nm,
                           l.power_aero_W,
                           l.power_hinge_W,
                           l.FV_wing_aero_N,
                           l.FH_wing_aero_N,
                           l.M_wing_aero_Nm,
                           l.FV_wing_inertial_N,
                           l.FH_wing_inertial_N,
                           l.M_wing_inertial_Nm,
                           l.FV_tail_N,
                           l.FH_tail_N,
                           l.FH_body_N,
                           l.M_tail_Nm,
                           l.separated_fraction,
                           l.tip_deflection_m,
                           l.tip_twist_rad * kRadToDeg};
  static_assert(sizeof values / sizeof values[0] == kHistoryColumns,
                "one value per histories.csv column");
  std::copy(std::begin(values), std::end(values), row);
}

namespace {

struct SimulationTrim {
  bool converged = false;
  OperatingPoint point;
  std::string message;
  JsonObject json;  ///< summary.json's "trim_point"
};

// The trim a simulation flies at ([simulate] at_trim): Eq. (4) refined in free flight at the
// study's frequency, from the study's point as the initial guess (trim/trim_solver.hpp).
SimulationTrim trimForSimulation(const Study& study, ModalWingCache* modal_wings) {
  TrimOptions options = defaultTrimOptions(study.design_point);
  options.initial = study.point;
  options.verify_free_flight = false;  // the simulation is the check
  const TrimSummary t = solveTrim(
      FlightCoreModel(study.vehicle, FlightCoreModel::Checks::kRequired, modal_wings), options);
  SimulationTrim out;
  out.converged = t.converged;
  out.point = t.solution;
  out.message = t.message;
  out.json.set("converged", t.converged);
  setOperatingPoint(out.json, t.solution).set("message", t.message);
  return out;
}

// histories.csv (every sample, every history_every-th row) and cycles.csv (every cycle's means),
// written as the run makes them: memory does not grow with the cycle count. Nothing is in place
// until commit(); a run that fails leaves neither file.
class TetheredRunFiles : public TetheredRunObserver {
 public:
  TetheredRunFiles(const std::filesystem::path& out_dir, int history_every)
      : histories_(out_dir / "histories.csv", historyColumns(),
                   static_cast<std::size_t>(history_every)),
        cycles_(out_dir / "cycles.csv",
                declaredColumns("cycles.csv", {"cycle", "FV_mean", "FH_mean", "M_mean",
                                               "power_aero_mean", "power_hinge_mean"})) {}

  void onSample(double t_s, double delta_M_rad, const LoadSample& l) override {
    double row[kHistoryColumns];
    historyRow(t_s, delta_M_rad, l, row);
    histories_.row(row);
  }
  void onCycle(int cycle, const CycleMeans& m) override {
    const double row[] = {static_cast<double>(cycle), m.FV_N, m.FH_N, m.M_Nm, m.power_aero_W,
                          m.power_hinge_W};
    cycles_.row(row);
  }
  std::size_t historyRows() const { return histories_.rowsWritten(); }
  void commit() {
    histories_.commit();
    cycles_.commit();
  }

 private:
  CsvStreamWriter histories_, cycles_;
};

}  // namespace

JsonObject tetheredSummary(const Study& study, const FlightCoreModel& model,
                           const SimulationSummary& s, const SimulationOptions& opts,
                           const TimeHistory& history,
                           const std::optional<ConstrainedFlightTest>& cft, double wall_s,
                           const JsonObject* trim_point) {
  const bool failed = s.status == SimulationStatus::kFailed;
  JsonObject summary = summaryHeader("simulate", toString(s.status), s.message, wall_s);
  summary.set("mode", "tethered")
      .set("cycles", s.cycles_run);
  if (failed) {
    summary.setNull("mean");
  } else {
    summary.set("mean", cycleMeansJson(s.mean))
        .set("steady_state_cycle", s.steady_state_cycle)
        .set("last_cycle_change", s.last_cycle_change);
  }
  summary.set("speed_mps", study.point.speed_mps)
      .set("freq_hz", study.point.freq_hz)
      .set("theta_deg", study.point.theta_rad * kRadToDeg)
      .set("tail_angle_deg", study.point.tail_angle_rad * kRadToDeg)
      .set("wing_only", study.simulate().wing_only);
  if (trim_point) summary.set("trim_point", *trim_point);
  summary.set("aero_model", study.vehicle.aero.model == AeroModelKind::kMstTd ? "mst-td"
                                                                           : "delaurier1993")
      .set("structure", model.flexible ? "flexible" : "rigid")
      .set("strips", static_cast<int>(model.strips.size()))
      .set("wing_mass_kg", model.flexible ? model.flexible->modal->wing_mass_kg
                                          : model.wing_mass.total.mass_kg);
  // Harmonic content of the last cycle (samples_per_cycle points, endpoint excluded); only when
  // the history holds a whole cycle (a run that failed early may not).
  const std::optional<LastCycleHarmonics> last =
      failed ? std::nullopt
             : lastCycleHarmonics(history.loads, static_cast<std::size_t>(opts.samples_per_cycle));
  if (last)
    summary.set("last_cycle",
                JsonObject()
                    .set("FV_amplitude_1f_N", last->FV_1f.amplitude)
                    .set("FV_amplitude_2f_N", last->FV_2f.amplitude)
                    .set("FH_amplitude_1f_N", last->FH_1f.amplitude)
                    .set("FH_amplitude_2f_N", last->FH_2f.amplitude)
                    .set("M_amplitude_1f_Nm", last->M_1f.amplitude)
                    .set("FV_peak_phase", last->FV_peak_phase)
                    .set("FH_peak_phase", last->FH_peak_phase)
                    .set("tip_deflection_amplitude_m", last->tip_deflection_amplitude_m)
                    .set("tip_twist_amplitude_deg", kRadToDeg * last->tip_twist_amplitude_rad));
  if (cft) summary.set("constrained_flight_test", zmpSummary(*cft));
  summary.set("integrator", JsonObject()
                             .set("method", s.integrator_method)
                             .set("rel_tol", opts.rel_tol)
                             .set("steps", s.steps)
                             .set("rhs_evaluations", s.rhs_evaluations));
  return summary;
}

int runSimulateStudy(const Study& given, const std::filesystem::path& out_dir) {
  const auto t0 = std::chrono::steady_clock::now();

  // [simulate] at_trim: solve the trim first; a vehicle that does not trim is a reported outcome.
  Study study = given;
  JsonObject trim_point;
  ModalWingCache modal_wings;  // the trim's wing is the simulation's
  if (study.simulate().at_trim) {
    const SimulationTrim t = trimForSimulation(study, &modal_wings);
    trim_point = t.json;
    if (!t.converged) {
      const std::string message =
          "no trim at " + formatShortest(study.point.freq_hz) + " Hz to fly at: " + t.message;
      const double wall_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      JsonObject summary = summaryHeader("simulate", "not_converged", message, wall_s);
      summary.set("mode", study.simulate().options.mode == FlightMode::kFree ? "free" : "tethered")
          .set("trim_point", trim_point);
      writeFileAtomic(out_dir / "study.resolved.toml", resolvedStudyToml(given));
      // Nothing was flown: the outputs of an earlier run must not pass for this one's.
      removeRunOutputs(out_dir, {"histories.csv", "cycles.csv", "zmp.csv", "spectra.csv"},
                       {"loads", "zmp", "flight", "cycle", "phase"});
      writeSummary(out_dir, summary);
      consoleOut() << study.name << ": not_converged: no trim to fly at: " << t.message << "\n";
      return 0;
    }
    study.point = t.point;
  }

  if (study.simulate().options.mode == FlightMode::kFree)
    return runFreeFlightStudy(study, out_dir, study.simulate().at_trim ? &trim_point : nullptr,
                              &given, &modal_wings);

  const FlightCoreModel model(
      study.simulate().wing_only ? study.vehicle.mainWingAlone() : study.vehicle,
      FlightCoreModel::Checks::kRequired, &modal_wings);
  TimeHistory history;  // the last cycle (the analyses below); every cycle streams to `files`
  SimulationOptions opts = study.simulate().options;
  opts.record_history = true;
  std::optional<TetheredRunFiles> files(std::in_place, out_dir, study.simulate().history_every);
  const SimulationSummary s = simulateTethered(model, study.point, opts, &history, &*files);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // A failed run (the integrator stopped) has no result: no CSV, no figure, no mean; only the
  // summary saying why. Outputs of an earlier run into the folder would pass for this run's.
  const bool failed = s.status == SimulationStatus::kFailed;
  // As given: with at_trim the resolved study keeps the initial guess and solves the same trim.
  writeFileAtomic(out_dir / "study.resolved.toml", resolvedStudyToml(given));
  std::optional<ConstrainedFlightTest> cft;
  std::size_t history_rows = 0;
  if (failed) {
    files.reset();  // the streamed files are discarded
    removeRunOutputs(out_dir, {"histories.csv", "cycles.csv", "zmp.csv"}, {"loads", "zmp"});
  } else {
    history_rows = files->historyRows();
    files->commit();
    // The constrained flight test (paper Fig. 9) of the last whole cycle.
    cft = lastCycleConstrainedFlightTest(model, study.point, history, opts.samples_per_cycle);
    if (cft) writeFileAtomic(out_dir / "zmp.csv", zmpTable(*cft).toString());
  }

  const JsonObject summary = tetheredSummary(study, model, s, opts, history, cft, wall_s,
                                             study.simulate().at_trim ? &trim_point : nullptr);
  writeSummary(out_dir, summary);
  if (failed) return reportFailedRun(study, s.message, out_dir);
  drawFigure(out_dir, "loads", tetheredLoadsFigure(study, s, history_rows));
  if (cft) drawFigure(out_dir, "zmp", zmpFigureScript(study, *cft, s.cycles_run));
  consoleOut() << study.name << ": " << s.BriefReport() << "\n  -> " << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
