// `ornithopter optimize STUDY.toml [-o DIR] [-j N]` and `kind = "optimize"` studies: the NLopt
// design optimisation of docs/theory.md 12.1 (optimize/design_problem.hpp) on `threads` threads
// (over the starts of a multi-start run). Writes into the output folder:
//   history.csv           every evaluation in start order: evaluation, start, start_evaluation,
//                         stage, the variables, objective, feasible, failed, violation, one g_<name>
//                         column per constraint, status (feasible | infeasible | failed),
//                         repeat_of (start_evaluation of the identical earlier point, else empty),
//                         the trim point and the physical results (empty where there is none,
//                         never NaN), best_objective (best feasible so far), message. Names row
//                         and units row. The objective of a failed evaluation is the finite
//                         penalty NLopt was given.
//   best_vehicle.toml     the best design as a complete vehicle file, its operating point = its
//                         trim point (`ornithopter trim best_vehicle.toml --freq F` re-runs it)
//   summary.json          the optimize keys of docs/design.md 4 and more (best and baseline
//                         results, per-start terminations, evaluation counts)
//   study.resolved.toml   the study with every default filled in
//   optimize_convergence.png/svg  objective per evaluation (feasible filled, infeasible open,
//                         best feasible so far) and the constraint violation
// Resumable: computed evaluations go to DIR/optimize.journal (output/optimize_journal.hpp) as they
// finish; a re-run of the same study into the same folder replays them and computes only the rest,
// then removes the journal. history.csv, best_vehicle.toml and study.resolved.toml depend only on
// the study (not on -j, nor on a resume).
#pragma once

#include <filesystem>
#include <functional>

#include "optimize/optimizer.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

struct OptimizeRunOptions {
  int threads = 1;       ///< worker threads over the starts, [1, 1024]
  bool progress = true;  ///< progress line on stderr
  bool figures = true;   ///< draw the convergence figure (gnuplot)
  /// Observer of every evaluation (after the journal append); tests use it to interrupt a run.
  std::function<void(const orni::opt::EvaluationRecord&)> on_evaluation;
};

/// Journal file name in the output folder.
inline constexpr const char* kOptimizeJournalName = "optimize.journal";

/// Run an optimize study into `out_dir`. Returns the process exit code: 0 when the optimisation
/// finished, whatever it found (the verdict is in summary.json); exceptions (a journal that cannot
/// be written) are failures (exit 1, mapped by main).
int runOptimizeStudy(const Study& study, const std::filesystem::path& out_dir,
                     const OptimizeRunOptions& options = {});

}  // namespace orni::studies
