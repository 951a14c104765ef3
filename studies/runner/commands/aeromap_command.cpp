#include "studies/runner/commands/aeromap_command.hpp"
#include "studies/runner/output/console.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <stdexcept>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/distributed/farm_schedule.hpp"
#include "studies/runner/distributed/point_farm.hpp"
#include "studies/runner/output/aeromap_journal.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_stream.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/progress_line.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/plotting/aeromap_figures.hpp"
#include "studies/runner/plotting/figure_rows.hpp"
#include "trim/aero_map_stream.hpp"

namespace orni::studies {

namespace {

namespace fs = std::filesystem;

/// Largest chunks a worker may be ahead of the first point not yet journaled (distributed runs).
constexpr std::size_t kAeromapFarmChunksAhead = 4;

AeroMapGrid gridOf(const AeromapSettings& a) {
  AeroMapGrid g;
  g.speed_mps = a.speed_mps.values;
  g.freq_hz = a.freq_hz.values;
  for (const double d : a.theta_deg.values) g.theta_rad.push_back(d * kDegToRad);
  for (const double d : a.tail_angle_deg.values) g.tail_angle_rad.push_back(d * kDegToRad);
  return g;
}

/// Points by status.
struct MapCounts {
  std::size_t points = 0, ok = 0, not_converged = 0, diverged = 0, failed = 0;
  void add(SimulationStatus s) {
    ++points;
    switch (s) {
      case SimulationStatus::kOk: ++ok; break;
      case SimulationStatus::kNotConverged: ++not_converged; break;
      case SimulationStatus::kDiverged: ++diverged; break;
      case SimulationStatus::kFailed: ++failed; break;
    }
  }
};

/// aeromap.csv (layout in aeromap_command.hpp; column numbers in AeromapCsvColumns), one row at a
/// time from the journal, which holds every point in order: a map of any size in bounded memory.
MapCounts writeMapTable(const fs::path& path, const AeromapSettings& a, const AeroMapGrid& grid,
                        const AeroMapJournal& journal) {
  CsvStreamWriter csv(path, declaredColumns("aeromap.csv",
                                            {"speed_mps", "freq_hz", "theta_deg", "tail_angle_deg",
                                             "FV_mean_N", "FH_mean_N", "M_mean_Nm", "power_W",
                                             "power_aero_W", "status", "steady_cycle", "cycles_run",
                                             "last_cycle_change", "message"}));
  auto cell = [](bool ok, double v) { return ok ? formatShortest(v) : std::string(); };
  MapCounts counts;
  std::vector<std::string> row(csv.columns());
  journal.replay([&](std::size_t i, const AeroMapPoint& p) {
    const auto ax = grid.axisIndices(i);
    const bool ok = p.status == SimulationStatus::kOk;
    row = {formatShortest(a.speed_mps.values[ax[0]]),
           formatShortest(a.freq_hz.values[ax[1]]),
           formatShortest(a.theta_deg.values[ax[2]]),
           formatShortest(a.tail_angle_deg.values[ax[3]]),
           cell(ok, p.mean.FV_N),
           cell(ok, p.mean.FH_N),
           cell(ok, p.mean.M_Nm),
           cell(ok, p.mean.power_hinge_W),
           cell(ok, p.mean.power_aero_W),
           toString(p.status),
           p.steady_state_cycle > 0 ? std::to_string(p.steady_state_cycle) : "",
           std::to_string(p.cycles_run),
           cell(p.cycles_run > 1 && std::isfinite(p.last_cycle_change), p.last_cycle_change),
           p.message};
    csv.textRow(row);
    counts.add(p.status);
  });
  if (counts.points != grid.size())
    throw std::runtime_error(journal.path().string() + ": " + std::to_string(counts.points) +
                             " of " + std::to_string(grid.size()) + " points recorded");
  csv.commit();
  return counts;
}

std::string runStatus(const MapCounts& map) {
  return map.ok == map.points ? "ok" : "not_converged";
}

std::string runMessage(const MapCounts& map) {
  char buf[240];
  if (map.ok == map.points) {
    std::snprintf(buf, sizeof buf, "all %zu points reached their periodic steady state",
                  map.points);
  } else {
    std::snprintf(buf, sizeof buf,
                  "%zu of %zu points without a result (%zu not_converged, %zu diverged, %zu "
                  "failed): see the status and message columns of aeromap.csv",
                  map.points - map.ok, map.points, map.not_converged, map.diverged, map.failed);
  }
  return buf;
}

/// "180 points (180 computed): 178 ok, 2 not_converged, 0 diverged, 0 failed, 1.23 s".
std::string briefReport(const MapCounts& map, std::size_t computed, double wall_s) {
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%zu points (%zu computed): %zu ok, %zu not_converged, %zu diverged, %zu failed, "
                "%.3g s",
                map.points, computed, map.ok, map.not_converged, map.diverged, map.failed, wall_s);
  return buf;
}

}  // namespace

int runAeromapStudy(const Study& study, const fs::path& out_dir,
                    const AeromapRunOptions& run) {
  const auto t0 = std::chrono::steady_clock::now();
  const AeroMapGrid grid = gridOf(study.aeromap());
  AeroMapOptions options;
  options.simulation = study.aeromap().options;
  options.threads = run.threads;
  std::string why;
  if (!grid.IsValid(&why)) throw std::invalid_argument("aero map grid: " + why);
  if (!options.IsValid(&why)) throw std::invalid_argument("aero map options: " + why);

  // Built once, before the threads start (one modal build for a flexible wing), and
  // shared read-only by every point.
  const FlightCoreModel model(study.aeromap().wing_only ? study.vehicle.mainWingAlone()
                                                      : study.vehicle);
  if (!farmWriter()) {  // a worker rank: compute the points rank 0 hands out, write nothing
    FarmJob job;
    job.threads = run.threads;
    job.work = [&](std::size_t index, const std::string&) {
      return journalRecord(index, computeAeroMapPoint(model, grid.point(index), options));
    };
    runFarm(job);
    return 0;
  }
  const std::string resolved = resolvedStudyToml(study);
  const std::uint64_t fingerprint = fnv1a64(versionString() + "\n" + resolved);

  fs::create_directories(out_dir);
  JournalResume resume;
  AeroMapJournal journal(out_dir / kAeromapJournalName, fingerprint, grid.size(), &resume);
  noteJournalResume("aeromap", journal.path(), resume.existed, resume.fingerprint_matched,
                    std::to_string(resume.records) + " of " + std::to_string(grid.size()) +
                        " points already done",
                    resume.rejected_lines);

  std::optional<ProgressLine> progress;
  if (run.progress) progress.emplace("aeromap", grid.size(), resume.records);
  const auto t_map = std::chrono::steady_clock::now();
  auto on_point = [&](std::size_t index, const AeroMapPoint& point) {
    journal.append(index, point);
    if (progress) progress->pointDone();
    if (run.on_point) run.on_point(index, point);
  };
  if (farmDistributed()) {
    // Rank 0 of a distributed run: the workers return each point as its journal record, which
    // is parsed and journaled in point order as a single process does.
    FarmJob job;
    for (std::size_t i = resume.records; i < grid.size(); ++i) job.todo.push_back(i);
    job.threads = run.threads;
    job.ordered = true;
    // The finished points waiting for an earlier one are bounded like the threads' lookahead,
    // but by whole chunks: a window of a few chunks per worker (a window smaller than a chunk
    // would let one worker at a time compute).
    job.ahead_limit = kAeromapFarmChunksAhead * kFarmMaxChunkPerThread *
                      static_cast<std::size_t>(run.threads) *
                      static_cast<std::size_t>(farmRanks() - 1);
    job.on_result = [&](std::size_t index, std::string record) {
      std::size_t parsed = 0;
      AeroMapPoint point;
      if (record.empty() || record.back() != '\n' ||
          !parseJournalRecord(std::string_view(record).substr(0, record.size() - 1),
                              grid.size(), &parsed, &point) ||
          parsed != index)
        throw std::runtime_error("aeromap: point " + std::to_string(index) +
                                 ": a worker rank returned an invalid record");
      on_point(index, point);
    };
    runFarm(job);
  } else {
    streamAeroMap(model, grid, options, resume.records, on_point);
  }
  if (progress) progress->finish();
  const std::size_t computed = grid.size() - resume.records;
  const double map_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_map).count();

  const MapCounts map = writeMapTable(out_dir / "aeromap.csv", study.aeromap(), grid, journal);
  writeFileAtomic(out_dir / "study.resolved.toml", resolved);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const AeromapSettings& a = study.aeromap();
  JsonObject summary = summaryHeader("aeromap", runStatus(map), runMessage(map), wall_s);
  summary.set("points", static_cast<long>(map.points))
      .set("points_ok", static_cast<long>(map.ok))
      .set("points_not_converged", static_cast<long>(map.not_converged))
      .set("points_diverged", static_cast<long>(map.diverged))
      .set("points_failed", static_cast<long>(map.failed))
      .set("points_computed", static_cast<long>(computed))
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
  writeSummary(out_dir, summary);

  // gnuplot reads aeromap.csv once per curve and keeps what it reads (its `stats` every value):
  // a map larger than kFigureRows points is left to the user's own plotting.
  const bool drawable = map.points <= kFigureRows;
  if (run.figures && map.ok > 0 && drawable) drawAeromapFigures(out_dir, study);
  if (run.figures && map.ok == 0)
    consoleErr() << "aeromap: no point has a result: no figures drawn\n";
  if (run.figures && map.ok > 0 && !drawable)
    consoleErr() << "aeromap: " << map.points << " points: no figures drawn (figures are drawn for "
              << "maps of at most " << kFigureRows << " points; aeromap.csv has every point)\n";
  // Every output is in place now: a run stopped before this line (in the figures too) resumes
  // from the journal and computes no point again.
  journal.remove();
  consoleOut() << study.name << ": aeromap " << briefReport(map, computed, map_s) << "\n  -> "
            << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
