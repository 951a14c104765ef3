#include "studies/runner/commands/sweep_command.hpp"
#include "studies/runner/output/console.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/grid/sweep_grid.hpp"
#include "studies/runner/commands/journaled_points.hpp"
#include "studies/runner/commands/point_counts.hpp"
#include "studies/runner/commands/run_info.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/point_journal.hpp"
#include "studies/runner/plotting/gnuplot.hpp"

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

/// Gnuplot script: one panel per plotted column with a value somewhere, the column against the
/// first axis, one line per combination of the other axes' values. Empty when nothing to plot.
std::string sweepFigure(const Study& study, const SweepGrid& grid,
                        const std::vector<SweepColumn>& columns,
                        const std::vector<SweepPointResult>& rows) {
  const SweepSettings& s = study.sweep();
  const std::size_t n_axes = s.axes.size();
  const std::size_t n_first = grid.sizes[0];
  const std::size_t n_series = rows.size() / n_first;  // combinations of the other axes
  auto rowOf = [&](std::size_t series, std::size_t i0) { return i0 * n_series + series; };

  struct Panel {
    std::size_t column;               // index into columns
    std::vector<std::size_t> series;  // series with a value
  };
  std::vector<Panel> panels;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (!columns[c].plotted) continue;
    Panel p{c, {}};
    for (std::size_t se = 0; se < n_series; ++se)
      for (std::size_t i0 = 0; i0 < n_first; ++i0)
        if (!rows[rowOf(se, i0)].cells[c].empty()) {
          p.series.push_back(se);
          break;
        }
    if (!p.series.empty()) panels.push_back(std::move(p));
  }
  if (panels.empty()) return {};

  // Rows of one series are every n_series-th row of sweep.csv (the first axis is outermost), so
  // `every n_series::series` picks them in order; an empty cell is skipped by the line.
  const std::size_t cols = panels.size() <= 3 ? 1 : 2;
  const std::size_t rows_layout = (panels.size() + cols - 1) / cols;
  const bool legend = n_series > 1;
  const std::string& x_key = s.axes[0].key;
  std::ostringstream g;
  g << "set multiplot layout " << rows_layout << "," << cols << " margins 0.08,"
    << (legend ? "0.74" : "0.97") << ",0.07,0.92 spacing 0.09,0.1 title \"" << study.name << ": "
    << toString(s.run) << " sweep, " << rows.size() << " points\" noenhanced font ',13'\n";
  if (legend) {  // entries are the other axes' values; the legend's title names those axes
    std::string keys;
    for (std::size_t a = 1; a < n_axes; ++a)
      keys += (a > 1 ? ", " : "") + s.axes[a].key + " (" + keyUnit(s.axes[a].key) + ")";
    g << "set key at screen 0.76,0.92 left top Left reverse noenhanced box title '" << keys
      << "' noenhanced font ',10'\n";
  } else
    g << "unset key\n";
  g << "set xlabel '" << x_key << " (" << keyUnit(x_key) << ")' noenhanced\n";
  {  // tics at the swept values (few) or a handful (many), and a margin around them
    const std::vector<double>& xv = s.axes[0].values.values;
    const double lo = *std::min_element(xv.begin(), xv.end());
    const double hi = *std::max_element(xv.begin(), xv.end());
    const double pad = hi > lo ? 0.06 * (hi - lo) : std::max(0.05 * std::fabs(lo), 1e-9);
    g << "set xrange [" << formatShortest(lo - pad) << ":" << formatShortest(hi + pad) << "]\n";
    if (xv.size() <= 8) {
      g << "set xtics (";
      for (std::size_t i = 0; i < xv.size(); ++i)
        g << (i ? ", " : "") << formatShortest(xv[i]);
      g << ")\n";
    } else {
      g << "set xtics autofreq\n";
    }
  }
  for (std::size_t pi = 0; pi < panels.size(); ++pi) {
    const Panel& p = panels[pi];
    const SweepColumn& col = columns[p.column];
    const std::size_t csv_col = n_axes + 2 + p.column;  // 1-based: axes, status, results
    if (pi == 1) g << "unset key\n";                    // the legend once, beside the panels
    g << "set ylabel '" << col.name << " (" << col.unit << ")' noenhanced\n";
    g << "plot ";
    for (std::size_t k = 0; k < p.series.size(); ++k) {
      const std::size_t se = p.series[k];
      const std::vector<std::size_t> at = grid.axisIndices(rowOf(se, 0));
      std::string title;
      for (std::size_t a = 1; a < n_axes; ++a)
        title += (title.empty() ? "" : ", ") + formatShortest(s.axes[a].values.values[at[a]]);
      if (title.empty()) title = col.name;
      g << (k ? ", " : "") << "'sweep.csv' skip 2 every " << n_series << "::" << se
        << " using 1:" << csv_col << " with linespoints lw 2 pt 7 title '" << title << "'";
    }
    if (col.name == "norm_ratio_max")
      g << ", 1 with lines dt 2 lc rgb '#333333' title 'bound (bounded below 1)'";
    g << "\n";
  }
  g << "unset multiplot\n";
  return g.str();
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
  writeFileAtomic(out_dir / "summary.json", summary.toString() + "\n");

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
