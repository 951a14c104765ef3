#include "studies/runner/commands/free_flight_command.hpp"
#include "studies/runner/output/console.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include "core/dynamics/free_flight.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/commands/failed_run.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_stream.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/plotting/figure_rows.hpp"
#include "studies/runner/plotting/flight_figures.hpp"
#include "studies/runner/plotting/gnuplot.hpp"

namespace orni::studies {

namespace {

// histories.csv, written as the run makes it (every history_every-th sample): memory does not grow
// with the cycle count. Nothing is in place until commit(); a failed run leaves no file.
class FreeFlightFiles : public FreeFlightObserver {
 public:
  FreeFlightFiles(const std::filesystem::path& out_dir, int history_every)
      : histories_(out_dir / "histories.csv",
                   declaredColumns("histories.csv",
                                   {"t", "delta_M", "x_I", "h", "theta", "U", "W", "Q", "airspeed",
                                    "alpha_body", "flight_path", "FV_aero", "FH_aero", "M_aero",
                                    "tip_deflection", "tip_twist", "separated_fraction"}),
                   static_cast<std::size_t>(history_every)) {}

  void onSample(double t_s, double delta_M_rad, const BodyState& b,
                const FreeFlightSample* sample) override {
    const LoadSample l = sample ? sample->loads : LoadSample{};
    const double a = std::atan2(b.W_mps, b.U_mps);
    const double row[] = {t_s,
                          delta_M_rad * kRadToDeg,
                          b.x_I_m,
                          b.h_m,
                          b.theta_rad * kRadToDeg,
                          b.U_mps,
                          b.W_mps,
                          b.Q_radps * kRadToDeg,
                          std::hypot(b.U_mps, b.W_mps),
                          a * kRadToDeg,
                          (b.theta_rad - a) * kRadToDeg,
                          l.FV_N,
                          l.FH_N,
                          l.M_Nm,
                          l.tip_deflection_m,
                          l.tip_twist_rad * kRadToDeg,
                          l.separated_fraction};
    static_assert(sizeof row / sizeof row[0] == 17, "one value per histories.csv column");
    histories_.row(row);
  }
  std::size_t rows() const { return histories_.rowsWritten(); }
  void commit() { histories_.commit(); }

 private:
  CsvStreamWriter histories_;
};

CsvTable spectrumTable(const LimitCycleMetrics& m) {
  return RowTable("spectra.csv", rowIndices(m.spectrum_delta.freq_hz.size()))
      .number("freq", [&](std::size_t k) { return m.spectrum_delta.freq_hz[k]; })
      .number("delta_M_amplitude",
              [&](std::size_t k) { return m.spectrum_delta.amplitude[k] * kRadToDeg; })
      .number("theta_amplitude",
              [&](std::size_t k) { return m.spectrum_theta.amplitude[k] * kRadToDeg; })
      .number("h_amplitude", [&](std::size_t k) { return m.spectrum_h.amplitude[k]; })
      .table();
}

// The limit-cycle metrics but the theta extremes; a long run's are over its last cycles only
// (FreeFlightOptions::limit_cycle_window_samples), and then say from which cycle on.
JsonObject limitCycleJson(const FreeFlightSummary& s) {
  const LimitCycleMetrics& m = s.limit_cycle;
  JsonObject j;
  j.set("altitude_p2p_slow_m", m.altitude_p2p_slow_m)
      .set("climb_rate_mps", m.climb_rate_mps)
      .set("dominant_freq_delta_hz", m.dominant_freq_delta_hz)
      .set("dominant_freq_theta_hz", m.dominant_freq_theta_hz)
      .set("dominant_freq_h_hz", m.dominant_freq_h_hz);
  if (s.limit_cycle_first_cycle != s.first_analysed_cycle)
    j.set("window_first_cycle", s.limit_cycle_first_cycle);
  return j;
}

}  // namespace

int runFreeFlightStudy(const Study& study, const std::filesystem::path& out_dir,
                       const JsonObject* trim_point, const Study* as_given,
                       ModalWingCache* modal_wings) {
  const auto t0 = std::chrono::steady_clock::now();
  const FlightCoreModel model(study.vehicle, FlightCoreModel::Checks::kRequired, modal_wings);
  std::optional<FreeFlightFiles> files(std::in_place, out_dir, study.simulate().history_every);
  const FreeFlightSummary s =
      simulateFree(model, study.point, study.simulate().options, nullptr, &*files);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // A failed run (the integrator stopped) has no result: no CSV, no figure, no mean, no verdict;
  // only the summary saying why (failed_run.hpp). A run that diverged is a verdict with its
  // history; its cycle means exist only when it completed a cycle.
  const bool failed = s.status == SimulationStatus::kFailed;
  writeFileAtomic(out_dir / "study.resolved.toml",
                  resolvedStudyToml(as_given != nullptr ? *as_given : study));
  std::size_t history_rows = 0;
  if (failed) {
    files.reset();  // the streamed file is discarded
    removeRunOutputs(out_dir, {"histories.csv", "spectra.csv"}, {"flight", "cycle", "phase"});
  } else {
    history_rows = files->rows();
    files->commit();
  }

  JsonObject summary = summaryHeader("simulate", toString(s.status), s.message, wall_s);
  summary.set("mode", "free")
      .set("cycles", s.cycles_run)
      .set("end_time_s", s.end_time_s);
  if (failed || s.cycles_run < 1)
    summary.setNull("mean");
  else
    summary.set("mean", JsonObject()
                            .set("FV_N", s.mean.FV_N)
                            .set("FH_N", s.mean.FH_N)
                            .set("M_Nm", s.mean.M_Nm)
                            .set("power_W", s.mean.power_aero_W));
  if (failed)
    summary.setNull("bounded");
  else
    summary.set("bounded", s.analysed && s.verdict.bounded);
  if (trim_point) summary.set("trim_point", *trim_point);
  if (s.analysed && !failed) {
    const LimitCycleMetrics& m = s.limit_cycle;
    summary.set("norm_ratio_max", s.verdict.norm_ratio_max)
        .set("theta_min_deg", m.theta_min_rad * kRadToDeg)
        .set("theta_max_deg", m.theta_max_rad * kRadToDeg)
        .set("altitude_p2p_m", m.altitude_p2p_fast_m)
        .set("dominant_freq_hz", m.dominant_freq_theta_hz)
        .set("verdict", JsonObject()
                            .set("reason", s.verdict.reason)
                            .set("worst_state", s.verdict.worst_state)
                            .set("time_of_max_s", s.verdict.time_of_max_s)
                            .set("drift", s.verdict.drift)
                            .set("drift_state", s.verdict.drift_state)
                            .set("drift_per_window", s.verdict.drift_per_window)
                            .set("first_analysed_cycle", s.first_analysed_cycle))
        .set("limit_cycle", limitCycleJson(s));
    writeFileAtomic(out_dir / "spectra.csv", spectrumTable(m).toString());
  }
  const FreeFlightBounds& b = study.simulate().options.free.bounds;
  summary.set("bounds", JsonObject()
                         .set("U_mps", b.U_mps)
                         .set("W_mps", b.W_mps)
                         .set("theta_deg", b.theta_rad * kRadToDeg)
                         .set("Q_degps", (b.Q_radps > 0 ? b.Q_radps
                                                        : 2 * kPi * study.point.freq_hz *
                                                              b.theta_rad) *
                                             kRadToDeg)
                         .set("h_m", b.h_m))
      .set("speed_mps", study.point.speed_mps)
      .set("freq_hz", study.point.freq_hz)
      .set("theta_deg", study.point.theta_rad * kRadToDeg)
      .set("tail_angle_deg", study.point.tail_angle_rad * kRadToDeg)
      .set("structure", model.flexible ? "flexible" : "rigid")
      .set("integrator", JsonObject()
                             .set("method", s.integrator_method)
                             .set("rel_tol", study.simulate().options.rel_tol)
                             .set("steps", s.steps)
                             .set("rhs_evaluations", s.rhs_evaluations));
  writeSummary(out_dir, summary);
  if (failed) return reportFailedRun(study, s.message, out_dir);
  // A long history is read in part (figure_rows.hpp): from the rows a figure shows on, every k-th.
  const std::size_t spc = static_cast<std::size_t>(study.simulate().options.samples_per_cycle);
  const std::size_t every = static_cast<std::size_t>(study.simulate().history_every);
  const std::size_t per_cycle = historyRowsPerCycle(spc, every);
  auto skipFrom = [&](int cycle) {  // the rows from the start of `cycle` (0-based) on
    return "skip 2" + figureEvery(history_rows,
                                  historyRowOf(static_cast<std::size_t>(cycle) * spc, every),
                                  per_cycle);
  };
  drawFigure(out_dir, "flight", freeFlightFigure(study, s.analysed, skipFrom(0)));
  if (s.cycles_run >= 1)
    drawFigure(out_dir, "cycle",
               freeFlightCycleFigure(study, s.cycles_run, skipFrom(s.cycles_run - 1)));
  const int first_analysed = s.first_analysed_cycle > 0 ? s.first_analysed_cycle - 1 : 0;
  const double t_from = first_analysed / study.point.freq_hz;
  drawFigure(out_dir, "phase", freeFlightPhaseFigure(study, t_from, skipFrom(first_analysed)));
  consoleOut() << study.name << ": " << toString(s.status) << ": " << s.message << "\n  -> "
            << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
