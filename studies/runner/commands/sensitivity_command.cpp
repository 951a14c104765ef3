#include "studies/runner/commands/sensitivity_command.hpp"
#include "studies/runner/output/console.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "studies/runner/config/sensitivity_study.hpp"
#include "studies/runner/distributed/point_farm.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/point_journal.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "studies/runner/plotting/sensitivity_figures.hpp"
#include "studies/runner/points/journaled_points.hpp"
#include "studies/runner/points/point_counts.hpp"
#include "studies/runner/points/sensitivity_point.hpp"
#include "studies/runner/points/sensitivity_ranking.hpp"

namespace orni::studies {

namespace {

namespace fs = std::filesystem;

/// NaN (written as null by JsonObject) for a value that does not exist.
double orNull(const std::optional<double>& v) {
  return v ? *v : std::numeric_limits<double>::quiet_NaN();
}

/// sensitivity.csv: point, parameter, side, value, value_unit, status, results, message; the base
/// point's parameter, value and unit are empty.
CsvTable sensitivityTable(const SensitivitySettings& s, const std::vector<SweepPointResult>& rows) {
  const std::vector<SensitivityColumn>& columns = sensitivityResultColumns();
  auto side = [](std::size_t i) { return sensitivityPointId(i).side; };
  auto param = [&](std::size_t i) -> const SensitivityParameter* {
    const SensitivityPointId id = sensitivityPointId(i);
    return id.side == SensitivitySide::kBase ? nullptr : &s.parameters[id.parameter];
  };
  RowTable<std::size_t> table("sensitivity.csv", rowIndices(rows.size()));
  table.text("point", [](std::size_t i) { return std::to_string(i); })
      .text("parameter", [&](std::size_t i) { return param(i) ? param(i)->key : std::string(); })
      .text("side", [&](std::size_t i) { return std::string(toString(side(i))); })
      .text("value",
            [&](std::size_t i) {
              const SensitivityParameter* p = param(i);
              if (!p) return std::string();
              return formatShortest(side(i) == SensitivitySide::kLow ? p->low : p->high);
            })
      .text("value_unit",
            [&](std::size_t i) { return param(i) ? keyUnit(param(i)->key) : std::string(); })
      .text("status", [&](std::size_t i) { return rows[i].status; });
  for (std::size_t c = 0; c < columns.size(); ++c)
    table.text(columns[c].name, columns[c].unit,
               [&rows, c](std::size_t i) { return rows[i].cells[c]; });
  return table.text("message", [&](std::size_t i) { return rows[i].message; }).table();
}

JsonObject parametersJson(const SensitivitySettings& s) {
  JsonObject o;
  for (const SensitivityParameter& p : s.parameters) {
    JsonObject q;
    q.set("unit", keyUnit(p.key)).set("low", p.low).set("high", p.high).set("base", p.base);
    if (std::isfinite(p.base))
      q.set("base_inside_range", p.base >= p.low && p.base <= p.high);
    else
      q.setNull("base_inside_range");
    o.set(p.key, q);
  }
  return o;
}

JsonObject predictionsJson(const SensitivitySettings& s,
                           const std::vector<PredictionRanking>& rankings) {
  const std::vector<SensitivityColumn>& columns = sensitivityResultColumns();
  JsonObject o;
  for (const PredictionRanking& p : rankings) {
    const SensitivityColumn& col = columns[p.column];
    std::vector<std::string> ranking;
    JsonObject effects;
    for (const SensitivityEffect& e : p.ranked) {
      const std::string& key = s.parameters[e.parameter].key;
      ranking.push_back(key);
      effects.set(key, JsonObject()
                           .set("low_value", orNull(e.low_value))
                           .set("high_value", orNull(e.high_value))
                           .set("delta_low", orNull(e.delta_low))
                           .set("delta_high", orNull(e.delta_high))
                           .set("swing", orNull(e.swing))
                           .set("swing_share", orNull(e.swing_share)));
    }
    o.set(col.name, JsonObject()
                        .set("unit", col.unit)
                        .set("label", col.label)
                        .set("base", orNull(p.base))
                        .setStrings("ranking", ranking)
                        .set("effects", effects));
  }
  return o;
}

/// The base point: status, message and every result column by name (null where no value).
JsonObject baseJson(const SweepPointResult& base) {
  const std::vector<SensitivityColumn>& columns = sensitivityResultColumns();
  JsonObject o;
  o.set("status", base.status).set("message", base.message);
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].name == "bounded") {
      if (base.cells[c].empty())
        o.setNull("bounded");
      else
        o.set("bounded", base.cells[c] == "1");
      continue;
    }
    o.set(columns[c].name, orNull(cellNumber(base.cells[c])));
  }
  return o;
}

}  // namespace

int runSensitivityStudy(const Study& study, const fs::path& out_dir,
                        const SensitivityRunOptions& run) {
  const auto t0 = std::chrono::steady_clock::now();
  const SensitivitySettings& s = study.sensitivity();
  const std::size_t n = sensitivityPointCount(s.parameters.size());
  if (s.parameters.empty() || s.points.size() != n)
    throw std::invalid_argument("sensitivity: one study per point expected");
  const std::size_t columns = sensitivityResultColumns().size();

  for (const SensitivityParameter& p : s.parameters)
    if (farmWriter() && std::isfinite(p.base) && (p.base < p.low || p.base > p.high))
      consoleErr() << "sensitivity: note: the base vehicle's " << p.key << " = "
                << formatShortest(p.base) << " lies outside its range [" << formatShortest(p.low)
                << ", " << formatShortest(p.high) << "]: both ends move it the same way\n";

  const std::string resolved = resolvedStudyToml(study);
  JournaledPointsJob job =
      journaledPointsJob("sensitivity", out_dir / kSensitivityJournalName, resolved, n, columns);
  job.threads = run.threads;
  job.progress = run.progress;
  ModalWingCache modal_wings;  // the points share the base's wing unless they change it
  job.compute = [&](std::size_t i) { return runSensitivityPoint(s.points[i], s, &modal_wings); };
  job.on_point = run.on_point;
  std::optional<JournaledPoints> done = runJournaledPoints(job);
  if (!done) return 0;  // a worker rank of a distributed run
  const std::vector<SweepPointResult>& rows = done->rows;

  const std::vector<PredictionRanking> rankings = rankSensitivity(s.parameters.size(), rows);
  writeFileAtomic(out_dir / "sensitivity.csv", sensitivityTable(s, rows).toString());
  writeFileAtomic(out_dir / "tornado.csv", tornadoTable(study, rankings).toString());
  writeFileAtomic(out_dir / "study.resolved.toml", resolved);
  const PointCounts count = countPoints(rows);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  JsonObject summary =
      summaryHeader("sensitivity", count.ok == n ? "ok" : "not_converged",
                    pointsMessage(count, n, "sensitivity.csv"), wall_s);
  setPointCounts(summary, count, n);
  summary.set("points_computed", static_cast<long>(done->computed))
      .set("points_resumed", static_cast<long>(done->resumed))
      .set("threads", run.threads)
      .set("free_flight_cycles", s.free_flight_cycles)
      .set("parameters", parametersJson(s))
      .set("base", baseJson(rows[0]))
      .set("predictions", predictionsJson(s, rankings));
  writeSummary(out_dir, summary);
  done->journal->remove();  // every result is in sensitivity.csv now

  int drawn = 0;
  if (run.figures) {
    for (std::size_t k = 0; k < rankings.size(); ++k) {
      const std::string figure = tornadoFigure(study, rankings, k);
      if (figure.empty()) continue;
      drawFigure(out_dir, tornadoStem(rankings[k]), figure);
      ++drawn;
    }
    const std::string overview = overviewFigure(study, rankings);
    if (!overview.empty()) {
      drawFigure(out_dir, "sensitivity_overview", overview);
      ++drawn;
    }
    if (drawn == 0) consoleErr() << "sensitivity: no prediction has a value to plot: no figure\n";
  }
  consoleOut() << study.name << ": sensitivity of " << rankings.size() << " predictions to "
            << s.parameters.size() << " parameters, " << n << " points (" << done->computed
            << " computed): " << pointCountsText(count) << "\n  -> " << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
