#include "studies/runner/distributed/optimize_starts.hpp"

#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "studies/runner/distributed/point_farm.hpp"
#include "studies/runner/output/progress_line.hpp"

namespace orni::studies {

namespace {

using orni::opt::EvaluationRecord;

/// A journaled evaluation as the record optimizeJournalRecord() writes.
EvaluationRecord journaledRecord(int start, int index, const JournaledEvaluation& e) {
  EvaluationRecord r;
  r.start = start;
  r.index = index;
  r.x = e.x;
  r.result = e.result;
  return r;
}

}  // namespace

void serveOptimizeStarts(const orni::opt::DesignProblem& problem,
                         const orni::opt::OptimizerOptions& options,
                         const OptimizeJournalShape& shape, int threads) {
  FarmJob job;
  job.threads = threads;
  job.work = [&](std::size_t start, const std::string& journaled) {
    OptimizeJournalResume replayed;
    std::string_view rest(journaled);
    for (std::size_t eol; (eol = rest.find('\n')) != std::string_view::npos;
         rest.remove_prefix(eol + 1)) {
      int st = 0, index = 0;
      JournaledEvaluation e;
      if (parseOptimizeJournalRecord(rest.substr(0, eol), shape, &st, &index, &e))
        replayed.evaluations[{st, index}] = std::move(e);
    }
    orni::opt::OptimizerHooks hooks;
    hooks.replay = [&replayed](int st, int index, const std::vector<double>& x) {
      return replayed.replay(st, index, x);
    };
    std::string computed;
    hooks.on_evaluation = [&computed](const EvaluationRecord& r) {
      if (r.source == orni::opt::EvaluationSource::kComputed) computed += optimizeJournalRecord(r);
    };
    orni::opt::runStart(problem, problem.box(), options, hooks, static_cast<int>(start));
    return computed;
  };
  runFarm(job);
}

FarmedStarts farmOptimizeStarts(const orni::opt::OptimizerOptions& options,
                                const OptimizeJournalShape& shape, int threads, bool progress,
                                OptimizeJournal* journal, OptimizeJournalResume* resume) {
  const auto t0 = std::chrono::steady_clock::now();
  FarmedStarts farmed;
  std::optional<ProgressLine> starts_done;
  if (progress) starts_done.emplace("optimize starts", static_cast<std::size_t>(options.starts), 0);
  FarmJob job;
  for (int k = 0; k < options.starts; ++k) job.todo.push_back(static_cast<std::size_t>(k));
  job.threads = threads;
  job.task_input = [&](std::size_t start) {
    std::string lines;
    for (const auto& [key, e] : resume->evaluations)
      if (key.first == static_cast<int>(start))
        lines += optimizeJournalRecord(journaledRecord(key.first, key.second, e));
    return lines;
  };
  job.on_result = [&](std::size_t start, std::string records) {
    std::string_view rest(records);
    for (std::size_t eol; (eol = rest.find('\n')) != std::string_view::npos;
         rest.remove_prefix(eol + 1)) {
      int st = 0, index = 0;
      JournaledEvaluation e;
      if (!parseOptimizeJournalRecord(rest.substr(0, eol), shape, &st, &index, &e) ||
          st != static_cast<int>(start))
        throw std::runtime_error("optimize: start " + std::to_string(start) +
                                 ": a worker rank returned an invalid evaluation record");
      journal->append(journaledRecord(st, index, e));
      resume->evaluations[{st, index}] = std::move(e);
      ++farmed.computed;
    }
    if (!rest.empty())
      throw std::runtime_error("optimize: start " + std::to_string(start) +
                               ": a worker rank returned a torn evaluation record");
    if (starts_done) starts_done->pointDone();
  };
  runFarm(job);
  if (starts_done) starts_done->finish();
  farmed.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return farmed;
}

}  // namespace orni::studies
