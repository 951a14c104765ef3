// The starts of an optimisation spread over the ranks of a distributed run (point_farm.hpp;
// docs/design.md 6). A start is the farm's unit of work: it runs NLopt from one initial design
// and is sequential inside, so the ranks take whole starts.
//
// Rank 0 hands out the starts, each with the evaluations its journal already holds for it; a
// worker rank runs the start, replaying those evaluations, and returns the ones it computed as
// journal records (optimize_journal.hpp). Rank 0 journals them and adds them to its replay set,
// so that the optimisation it then runs itself replays every evaluation, as a resumed run does
// from a complete journal: the outputs are the bytes of a single-process run.
#pragma once

#include "optimize/design_problem.hpp"
#include "optimize/optimizer.hpp"
#include "studies/runner/output/optimize_journal.hpp"

namespace orni::studies {

/// A worker rank: serves the starts rank 0 hands out until released; writes nothing.
void serveOptimizeStarts(const orni::opt::DesignProblem& problem,
                         const orni::opt::OptimizerOptions& options,
                         const OptimizeJournalShape& shape, int threads);

/// What the worker ranks computed for rank 0.
struct FarmedStarts {
  int computed = 0;       ///< evaluations computed by the workers (journaled here)
  double seconds = 0.0;   ///< wall time of the farm
};

/// Rank 0: runs every start of `options` on the worker ranks, appending each computed evaluation
/// to `journal` and to `resume`'s replay set; `progress`: a progress line of finished starts.
/// Throws std::runtime_error when a worker returns an invalid or torn record.
FarmedStarts farmOptimizeStarts(const orni::opt::OptimizerOptions& options,
                                const OptimizeJournalShape& shape, int threads, bool progress,
                                OptimizeJournal* journal, OptimizeJournalResume* resume);

}  // namespace orni::studies
