#include "studies/runner/commands/sweep_command.hpp"
#include "studies/runner/output/console.hpp"

#include <chrono>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/grid/sweep_grid.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/point_journal.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/plotting/design_figures.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "studies/runner/points/journaled_points.hpp"
#include "studies/runner/points/point_counts.hpp"

namespace orni::studies {

namespace {

namespace fs = std::filesystem;

SweepGrid gridOf(const SweepSettings& s) {
  SweepGrid g;
  for (const SweepAxis& a : s.axes) g.sizes.push_back(a.values.values.size());
  return g;
}

/// sweep.csv: axes, status, the result columns, message.
CsvTable sweepTable(const SweepSettings& s, const SweepGrid& grid,
                    const std::vector<SweepColumn>& columns,
                    const std::vector<SweepPointResult>& rows) {
  RowTable<std::size_t> t("sweep.csv", rowIndices(rows.size()));
  for (std::size_t k = 0; k < s.axes.size(); ++k)
    t.number(s.axes[k].key, keyUnit(s.axes[k].key),
             [&, k](std::size_t i) { return s.axes[k].values.values[grid.axisIndices(i)[k]]; });
  t.text("status", [&](std::size_t i) { return rows[i].status; });
  for (std::size_t c = 0; c < columns.size(); ++c)
    t.text(columns[c].name, columns[c].unit, [&, c](std::size_t i) { return rows[i].cells[c]; });
  return t.text("message", [&](std::size_t i) { return rows[i].message; }).table();
}

}  // namespace

int runSweepStudy(const Study& study, const fs::path& out_dir, const SweepRunOptions& run) {
  const auto t0 = std::chrono::steady_clock::now();
  const SweepSettings& s = study.sweep();
  const SweepGrid grid = gridOf(s);
  std::string why;
  if (!grid.IsValid(&why)) throw std::invalid_argument("sweep grid: " + why);
  if (s.points.size() != grid.size())
    throw std::invalid_argument("sweep: one study per point expected");
  const std::vector<SweepColumn> columns = sweepResultColumns(study);
  const std::size_t n = grid.size();

  const std::string resolved = resolvedStudyToml(study);
  JournaledPointsJob job =
      journaledPointsJob("sweep", out_dir / kSweepJournalName, resolved, n, columns.size());
  job.threads = run.threads;
  job.progress = run.progress;
  ModalWingCache modal_wings;  // the points share one wing unless the axes change it
  job.compute = [&](std::size_t i) { return runSweepPoint(s.points[i], s.run, &modal_wings); };
  job.on_point = run.on_point;
  std::optional<JournaledPoints> done = runJournaledPoints(job);
  if (!done) return 0;  // a worker rank of a distributed run
  const std::vector<SweepPointResult>& rows = done->rows;

  writeFileAtomic(out_dir / "sweep.csv", sweepTable(s, grid, columns, rows).toString());
  writeFileAtomic(out_dir / "study.resolved.toml", resolved);
  std::size_t bounded_column = std::numeric_limits<std::size_t>::max();
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c].name == "bounded") bounded_column = c;
  const PointCounts count = countPoints(rows, bounded_column);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  JsonObject axes;
  for (const SweepAxis& a : s.axes) axes.set(a.key, a.values.values);
  JsonObject summary =
      summaryHeader("sweep", count.ok == n ? "ok" : "not_converged",
                    pointsMessage(count, n, "sweep.csv"), wall_s);
  summary.set("run", std::string(toString(s.run)));
  if (s.run == StudyKind::kSimulate)
    summary.set("mode", s.base_simulate.options.mode == FlightMode::kFree ? "free" : "tethered");
  setPointCounts(summary, count, n);
  if (s.run == StudyKind::kTrim || s.base_simulate.options.mode == FlightMode::kFree)
    summary.set("points_bounded", static_cast<long>(count.bounded));
  summary.set("points_computed", static_cast<long>(done->computed))
      .set("points_resumed", static_cast<long>(done->resumed))
      .set("threads", run.threads)
      .set("axes", axes);
  writeSummary(out_dir, summary);

  if (run.figures) {
    const std::string figure = sweepFigure(study, grid, columns, rows);
    if (figure.empty())
      consoleErr() << "sweep: no point has a value to plot: no figure drawn\n";
    else
      drawFigure(out_dir, "sweep", figure);
  }
  // Every output is in place now: a run stopped before this line (in the figure too) resumes
  // from the journal and computes no point again.
  done->journal->remove();
  consoleOut() << study.name << ": sweep of " << toString(s.run) << ", " << n << " points ("
            << done->computed << " computed): " << pointCountsText(count) << "\n  -> "
            << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
