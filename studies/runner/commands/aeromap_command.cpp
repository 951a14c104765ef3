#include "studies/runner/commands/aeromap_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/commands/aeromap_figures.hpp"
#include "studies/runner/commands/run_info.hpp"
#include "studies/runner/output/aeromap_journal.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/progress_line.hpp"

namespace orni::studies {

namespace {

namespace fs = std::filesystem;

trim::AeroMapGrid gridOf(const AeromapSettings& a) {
  trim::AeroMapGrid g;
  g.speed_mps = a.speed_mps.values;
  g.freq_hz = a.freq_hz.values;
  for (const double d : a.theta_deg.values) g.theta_rad.push_back(d * kDegToRad);
  for (const double d : a.tail_angle_deg.values) g.tail_angle_rad.push_back(d * kDegToRad);
  return g;
}

/// aeromap.csv (layout in aeromap_command.hpp; column numbers in AeromapCsvColumns).
CsvTable mapTable(const AeromapSettings& a, const trim::AeroMapGrid& grid,
                  const trim::AeroMapSummary& map) {
  const std::size_t n = map.points.size();
  std::vector<double> speed, freq, theta, tail;
  std::vector<std::string> fv, fh, m, power, power_aero, status, steady, cycles, change, message;
  auto cell = [](bool ok, double v) { return ok ? formatShortest(v) : std::string(); };
  for (std::size_t i = 0; i < n; ++i) {
    const auto ax = grid.axisIndices(i);
    speed.push_back(a.speed_mps.values[ax[0]]);
    freq.push_back(a.freq_hz.values[ax[1]]);
    theta.push_back(a.theta_deg.values[ax[2]]);
    tail.push_back(a.tail_angle_deg.values[ax[3]]);
    const trim::AeroMapPoint& p = map.points[i];
    const bool ok = p.status == SimulationStatus::kOk;
    fv.push_back(cell(ok, p.mean.FV_N));
    fh.push_back(cell(ok, p.mean.FH_N));
    m.push_back(cell(ok, p.mean.M_Nm));
    power.push_back(cell(ok, p.mean.power_hinge_W));
    power_aero.push_back(cell(ok, p.mean.power_aero_W));
    status.push_back(toString(p.status));
    steady.push_back(p.steady_state_cycle > 0 ? std::to_string(p.steady_state_cycle) : "");
    cycles.push_back(std::to_string(p.cycles_run));
    change.push_back(cell(p.cycles_run > 1 && std::isfinite(p.last_cycle_change),
                          p.last_cycle_change));
    message.push_back(p.message);
  }
  CsvTable t;
  t.addColumn("speed_mps", "m/s", speed);
  t.addColumn("freq_hz", "Hz", freq);
  t.addColumn("theta_deg", "deg", theta);
  t.addColumn("tail_angle_deg", "deg", tail);
  t.addTextColumn("FV_mean_N", "N", fv);
  t.addTextColumn("FH_mean_N", "N", fh);
  t.addTextColumn("M_mean_Nm", "N m", m);
  t.addTextColumn("power_W", "W", power);
  t.addTextColumn("power_aero_W", "W", power_aero);
  t.addTextColumn("status", "-", status);
  t.addTextColumn("steady_cycle", "-", steady);
  t.addTextColumn("cycles_run", "-", cycles);
  t.addTextColumn("last_cycle_change", "-", change);
  t.addTextColumn("message", "-", message);
  return t;
}

std::string runStatus(const trim::AeroMapSummary& map) {
  return map.ok == map.points.size() ? "ok" : "not_converged";
}

std::string runMessage(const trim::AeroMapSummary& map) {
  char buf[240];
  if (map.ok == map.points.size()) {
    std::snprintf(buf, sizeof buf, "all %zu points reached their periodic steady state",
                  map.points.size());
  } else {
    std::snprintf(buf, sizeof buf,
                  "%zu of %zu points without a result (%zu not_converged, %zu diverged, %zu "
                  "failed): see the status and message columns of aeromap.csv",
                  map.points.size() - map.ok, map.points.size(), map.not_converged,
                  map.diverged, map.failed);
  }
  return buf;
}

}  // namespace

int runAeromapStudy(const Study& study, const fs::path& out_dir,
                    const AeromapRunOptions& run) {
  const auto t0 = std::chrono::steady_clock::now();
  const trim::AeroMapGrid grid = gridOf(study.aeromap);
  trim::AeroMapOptions options;
  options.simulation = study.aeromap.options;
  options.threads = run.threads;
  std::string why;
  if (!grid.IsValid(&why)) throw std::invalid_argument("aero map grid: " + why);
  if (!options.IsValid(&why)) throw std::invalid_argument("aero map options: " + why);

  // Built once, before the threads start (the flexible wing's modes come through the cache), and
  // shared read-only by every point.
  const FlightCoreModel model(study.aeromap.wing_only ? study.vehicle.mainWingAlone()
                                                      : study.vehicle);
  const std::string resolved = resolvedStudyToml(study);
  const std::uint64_t fingerprint = fnv1a64(versionString() + "\n" + resolved);

  fs::create_directories(out_dir);
  JournalResume resume;
  AeroMapJournal journal(out_dir / kAeromapJournalName, fingerprint, grid.size(), &resume);
  if (resume.existed && !resume.fingerprint_matched)
    std::cerr << "aeromap: " << journal.path().string()
              << " belongs to another study, grid or version: starting afresh\n";
  else if (resume.existed)
    std::cerr << "aeromap: resuming from " << journal.path().string() << ": " << resume.records
              << " of " << grid.size() << " points already done"
              << (resume.rejected_lines ? " (" + std::to_string(resume.rejected_lines) +
                                              " torn or corrupt line(s) dropped)"
                                        : std::string())
              << "\n";

  std::optional<ProgressLine> progress;
  if (run.progress) progress.emplace("aeromap", grid.size(), resume.records);
  const trim::AeroMapSummary map = trim::buildAeroMap(
      model, grid, options, resume.points,
      [&](std::size_t index, const trim::AeroMapPoint& point) {
        journal.append(index, point);
        if (progress) progress->pointDone();
        if (run.on_point) run.on_point(index, point);
      });
  if (progress) progress->finish();

  writeFileAtomic(out_dir / "aeromap.csv", mapTable(study.aeromap, grid, map).toString());
  writeFileAtomic(out_dir / "study.resolved.toml", resolved);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const AeromapSettings& a = study.aeromap;
  JsonObject summary;
  summary.set("kind", "aeromap")
      .set("status", runStatus(map))
      .set("message", runMessage(map))
      .set("wall_time_s", wall_s)
      .set("version", versionString())
      .set("points", static_cast<long>(map.points.size()))
      .set("points_ok", static_cast<long>(map.ok))
      .set("points_not_converged", static_cast<long>(map.not_converged))
      .set("points_diverged", static_cast<long>(map.diverged))
      .set("points_failed", static_cast<long>(map.failed))
      .set("points_computed", static_cast<long>(map.computed))
      .set("points_resumed", static_cast<long>(resume.records))
      .set("threads", run.threads)
      .set("speed_mps", a.speed_mps.values)
      .set("freq_hz", a.freq_hz.values)
      .set("theta_deg", a.theta_deg.values)
      .set("tail_angle_deg", a.tail_angle_deg.values)
      .set("cycles_max", a.options.cycles)
      .set("steady_tol", a.options.steady_tol)
      .set("aero_model",
           study.vehicle.aero.model == AeroModelKind::kMstTd ? "mst-td" : "delaurier1993")
      .set("structure", model.flexible ? "flexible" : "rigid");
  writeFileAtomic(out_dir / "summary.json", summary.toString() + "\n");

  if (run.figures && map.ok > 0) drawAeromapFigures(out_dir, study);
  if (run.figures && map.ok == 0)
    std::cerr << "aeromap: no point has a result: no figures drawn\n";
  // Every output is in place now: a run stopped before this line (in the figures too) resumes
  // from the journal and computes no point again.
  journal.remove();
  std::cout << study.name << ": aeromap " << map.BriefReport() << "\n  -> " << out_dir.string()
            << "\n";
  return 0;
}

}  // namespace orni::studies
