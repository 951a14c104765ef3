#include "studies/runner/commands/optimize_command.hpp"
#include "studies/runner/output/console.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model/frames.hpp"
#include "optimize/design_problem.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "studies/runner/distributed/optimize_starts.hpp"
#include "studies/runner/distributed/point_farm.hpp"
#include "studies/runner/output/aeromap_journal.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/optimize_journal.hpp"
#include "studies/runner/output/progress_line.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/plotting/design_figures.hpp"
#include "studies/runner/plotting/gnuplot.hpp"

namespace orni::studies {

namespace {

namespace fs = std::filesystem;
using orni::opt::DesignProblem;
using orni::opt::DesignValueInfo;
using orni::opt::EvaluationRecord;
using orni::opt::EvaluationStatus;
using orni::opt::OptimizerSummary;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Unit of a design variable from its first field's key suffix.
std::string variableUnit(const orni::opt::DesignVariable& v) {
  const std::string& f = v.fields.front().name;
  auto ends = [&f](const std::string& s) {
    return f.size() >= s.size() && f.compare(f.size() - s.size(), s.size(), s) == 0;
  };
  if (ends("_m2")) return "m^2";
  if (ends("_m")) return "m";
  return "-";
}

std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

const char* statusText(const EvaluationRecord& r) {
  if (r.result.status == EvaluationStatus::kFailed) return "failed";
  return r.feasible ? "feasible" : "infeasible";
}

CsvTable historyTable(const DesignProblem& p, const OptimizerSummary& s) {
  const auto& vars = p.space().variables;
  const std::vector<DesignValueInfo>& info = p.valueInfo();
  const std::string objective_unit = orni::opt::objectiveUnit(p.options().objective);
  std::vector<std::string> best_so_far;  // the best feasible objective up to each evaluation
  double best = kNaN;
  for (const EvaluationRecord& r : s.history) {
    if (r.feasible && !(r.result.objective >= best)) best = r.result.objective;
    best_so_far.push_back(formatCell(best));
  }
  auto rec = [&s](std::size_t i) -> const EvaluationRecord& { return s.history[i]; };
  RowTable<std::size_t> t("history.csv", rowIndices(s.history.size()));
  t.number("evaluation", [](std::size_t i) { return i; })
      .number("start", [&](std::size_t i) { return rec(i).start; })
      .number("start_evaluation", [&](std::size_t i) { return rec(i).index; })
      .text("stage", [&](std::size_t i) { return std::string(orni::opt::toString(rec(i).stage)); });
  for (std::size_t j = 0; j < vars.size(); ++j)
    t.number(vars[j].name, variableUnit(vars[j]), [&, j](std::size_t i) { return rec(i).x[j]; });
  t.number("objective", objective_unit, [&](std::size_t i) { return rec(i).result.objective; })
      .number("feasible", [&](std::size_t i) { return rec(i).feasible ? 1.0 : 0.0; })
      .number("failed",
              [&](std::size_t i) {
                return rec(i).result.status == EvaluationStatus::kFailed ? 1.0 : 0.0;
              })
      .number("violation", [&](std::size_t i) { return rec(i).violation; });
  for (std::size_t j = 0; j < p.constraintNames().size(); ++j)
    t.number("g_" + p.constraintNames()[j], "-",
             [&, j](std::size_t i) { return rec(i).result.constraints[j]; });
  t.text("status", [&](std::size_t i) { return std::string(statusText(rec(i))); })
      .text("repeat_of", [&](std::size_t i) {
        return rec(i).repeat_of >= 0 ? std::to_string(rec(i).repeat_of) : std::string();
      });
  for (std::size_t j = 0; j < info.size(); ++j)
    t.text(info[j].name, info[j].unit, [&, j](std::size_t i) {
      return formatCell(rec(i).result.values[j] / info[j].si_per_unit);
    });
  return t.text("best_objective", objective_unit, [&](std::size_t i) { return best_so_far[i]; })
      .text("message", [&](std::size_t i) { return oneLine(rec(i).result.message); })
      .table();
}

JsonObject designObject(const DesignProblem& p, const std::vector<double>& x) {
  JsonObject o;
  for (std::size_t j = 0; j < x.size(); ++j) o.set(p.space().variables[j].name, x[j]);
  return o;
}

/// The physical results of one evaluation (file units; null where there is none).
JsonObject resultObject(const DesignProblem& p, const OptimizerSummary& s, int h) {
  const EvaluationRecord& r = s.history[static_cast<std::size_t>(h)];
  const std::vector<DesignValueInfo>& info = p.valueInfo();
  JsonObject o;
  o.set("evaluation", h).set("start", r.start).set("start_evaluation", r.index);
  o.set("design", designObject(p, r.x));
  o.set("status", statusText(r)).set("message", oneLine(r.result.message));
  o.set("objective", r.result.status == EvaluationStatus::kFailed ? kNaN : r.result.objective);
  JsonObject g;
  for (std::size_t j = 0; j < p.constraintNames().size(); ++j)
    g.set(p.constraintNames()[j], r.result.constraints[j]);
  o.set("constraints", g);
  for (std::size_t j = 0; j < info.size(); ++j) {
    const double v = r.result.values[j] / info[j].si_per_unit;
    const std::string name = info[j].name;
    if (name == "trim_converged" || name == "bounded" || name == "floquet_stable") {
      if (std::isfinite(v))
        o.set(name, v == 1.0);
      else
        o.setNull(name);
    } else {
      o.set(name, v);
    }
  }
  return o;
}

}  // namespace

int runOptimizeStudy(const Study& study, const fs::path& out_dir, const OptimizeRunOptions& run) {
  const auto t0 = std::chrono::steady_clock::now();
  const OptimizeSettings& settings = study.optimize();
  const DesignProblem problem(study.vehicle, settings.space, settings.problem);
  orni::opt::OptimizerOptions options = settings.optimizer;
  options.threads = run.threads;

  const OptimizeJournalShape shape{problem.variableCount(), problem.constraintCount(),
                                   problem.valueCount()};
  if (!farmWriter()) {  // a worker rank of a distributed run: runs the starts rank 0 hands out
    serveOptimizeStarts(problem, options, shape, run.threads);
    return 0;
  }
  const std::string resolved = resolvedStudyToml(study);
  const std::uint64_t fingerprint = fnv1a64(versionString() + "\n" + resolved);
  fs::create_directories(out_dir);
  OptimizeJournalResume resume;
  OptimizeJournal journal(out_dir / kOptimizeJournalName, fingerprint, shape, &resume);
  noteJournalResume("optimize", journal.path(), resume.existed, resume.fingerprint_matched,
                    std::to_string(resume.records) + " evaluation(s) journaled",
                    resume.rejected_lines);

  // Rank 0 of a distributed run: the starts run on the worker ranks (optimize_starts.hpp), then
  // minimize() below replays every evaluation: the bytes of a single-process run.
  FarmedStarts farmed;
  if (farmDistributed())
    farmed = farmOptimizeStarts(options, shape, run.threads, run.progress, &journal, &resume);

  std::mutex progress_mutex;
  std::optional<ProgressLine> progress;
  if (run.progress && !farmDistributed())
    progress.emplace("optimize",
                     static_cast<std::size_t>(options.starts) *
                         static_cast<std::size_t>(options.max_evaluations),
                     0);
  orni::opt::OptimizerHooks hooks;
  hooks.replay = [&resume](int start, int index, const std::vector<double>& x) {
    return resume.replay(start, index, x);
  };
  hooks.on_evaluation = [&](const EvaluationRecord& r) {
    if (r.source == orni::opt::EvaluationSource::kComputed) journal.append(r);
    if (progress) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      progress->pointDone();
    }
    if (run.on_evaluation) run.on_evaluation(r);
  };
  OptimizerSummary s = orni::opt::minimize(problem, problem.box(), options, hooks);
  if (progress) progress->finish();
  s.computed += farmed.computed;  // computed by the worker ranks of this run, replayed here
  s.replayed -= farmed.computed;
  s.wall_time_s += farmed.seconds;

  const EvaluationRecord* best = s.bestRecord();
  if (!best) throw std::runtime_error("optimize: no evaluation was made");
  const EvaluationRecord& base = s.history.front();  // start 0, evaluation 0: the initial design
  const bool base_ok = base.result.status != EvaluationStatus::kFailed;
  const double baseline_objective = base_ok ? base.result.objective : kNaN;
  const double improvement =
      base.feasible && s.feasible && baseline_objective != 0.0
          ? 100.0 * (baseline_objective - best->result.objective) / std::abs(baseline_objective)
          : kNaN;

  // The best design as a vehicle file (its trim point as the operating point).
  orni::VehicleDefinition best_vehicle = problem.designVehicle(best->x, best->result);
  best_vehicle.model.name = study.name + "_best";
  best_vehicle.model.description = "Best design of optimisation '" + study.name + "' (" +
                             (s.feasible ? "feasible" : "infeasible: no feasible design found") +
                             ") from vehicle '" + study.vehicle.name +
                             "'; operating point = its trim point";

  writeFileAtomic(out_dir / "history.csv", historyTable(problem, s).toString());
  writeFileAtomic(out_dir / "best_vehicle.toml", vehicleToToml(best_vehicle));
  writeFileAtomic(out_dir / "study.resolved.toml", resolved);

  std::vector<std::string> terminations;
  std::vector<double> start_best;
  for (const orni::opt::StartSummary& st : s.starts) {
    terminations.push_back(st.termination);
    const EvaluationRecord* b = nullptr;
    for (const EvaluationRecord& r : s.history)
      if (r.start == st.start && r.index == st.best) b = &r;
    start_best.push_back(b && b->feasible ? b->result.objective : kNaN);
  }
  int feasible_count = 0;
  for (const EvaluationRecord& r : s.history) feasible_count += r.feasible ? 1 : 0;
  const std::string status = s.converged ? "ok" : "not_converged";
  std::string message;
  if (s.converged)
    message = "optimum found: " + s.message;
  else if (s.feasible)
    message = "feasible design found but the optimiser did not converge: " + s.message;
  else
    message = "no design satisfied every constraint: " + s.message;
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const int best_index = s.best;
  JsonObject summary = summaryHeader("optimize", status, oneLine(message), wall_s);
  summary.set("converged", s.converged)
      .set("objective", best->result.status == EvaluationStatus::kFailed ? kNaN
                                                                         : best->result.objective)
      .set("baseline_objective", baseline_objective)
      .set("evaluations", static_cast<long>(s.history.size()))
      .set("design", designObject(problem, best->x))
      .set("constraints_satisfied", s.feasible)
      .set("objective_name", orni::opt::toString(problem.options().objective))
      .set("objective_unit", orni::opt::objectiveUnit(problem.options().objective))
      .set("baseline_feasible", base.feasible)
      .set("improvement_percent", improvement)
      .set("algorithm", orni::opt::toString(options.algorithm))
      .set("starts", options.starts)
      .set("threads", run.threads)
      .set("max_evaluations", options.max_evaluations)
      .setStrings("constraint_names", problem.constraintNames())
      .set("best", resultObject(problem, s, best_index))
      .set("baseline", resultObject(problem, s, 0))
      .set("best_vehicle", "best_vehicle.toml")
      .set("freq_hz", problem.options().trim.initial.freq_hz)
      .set("evaluations_feasible", feasible_count)
      .set("evaluations_computed", s.computed)
      .set("evaluations_repeated", s.cached)
      .set("evaluations_resumed", s.replayed)
      .set("evaluations_failed", s.failed)
      .setStrings("start_terminations", terminations)
      .set("start_best_objective", start_best)
      .set("structure", study.vehicle.wing.structure == StructureLevel::kFlexible ? "flexible"
                                                                                  : "rigid");
  writeSummary(out_dir, summary);

  bool any_result = false;
  for (const EvaluationRecord& r : s.history)
    any_result = any_result || r.result.status != EvaluationStatus::kFailed;
  bool figure_missing = false;
  if (run.figures && any_result) {
    try {
      drawFigure(out_dir, "optimize_convergence", optimizeConvergenceFigure(study, problem, s));
    } catch (const std::exception& e) {
      figure_missing = true;
      consoleErr() << "optimize: the convergence figure was not drawn (the journal is kept: the "
                   "same command redraws it without evaluating again): "
                << e.what() << "\n";
    }
  } else if (run.figures) {
    consoleErr() << "optimize: every evaluation failed: no figure drawn\n";
  }
  // Every output is in place now (a kill before this line resumes from the journal and
  // evaluates nothing again).
  if (!figure_missing) journal.remove();
  consoleOut() << study.name << ": optimize " << s.BriefReport() << "\n  " << message << "\n  -> "
            << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
