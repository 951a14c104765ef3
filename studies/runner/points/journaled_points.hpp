// The point loop of the studies whose points are rows of sweep results (sweep, sensitivity): the
// journal (resume, a note when it belongs to another run), the points still to compute on this
// process's threads or over the ranks of a distributed run (point_farm.hpp), each journaled as it
// finishes, the progress line and the caller's observer. The caller writes the outputs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "studies/runner/points/sweep_point.hpp"
#include "studies/runner/output/point_journal.hpp"

namespace orni::studies {

struct JournaledPointsJob {
  std::string kind;                   ///< "sweep", "sensitivity": the journal's and messages' name
  std::filesystem::path journal_path; ///< in the output folder (created when missing)
  std::uint64_t fingerprint = 0;      ///< of the run's inputs: a journal of others is not resumed
  std::size_t points = 0;
  std::size_t columns = 0;            ///< result cells per point
  int threads = 1;
  bool progress = true;
  /// Computes point i (concurrently for different i; a numerical failure is a status in the row).
  std::function<SweepPointResult(std::size_t index)> compute;
  /// Optional observer of every computed point, after its journal append, serialised.
  std::function<void(std::size_t index, const SweepPointResult& row)> on_point;
};

struct JournaledPoints {
  std::vector<SweepPointResult> rows;  ///< every point, resumed or computed
  std::size_t computed = 0, resumed = 0;
  /// The journal, open: the caller removes it once the outputs hold every result.
  std::unique_ptr<PointJournal> journal;
};

/// A job of `kind` ("sweep", "sensitivity") journaled at `journal_path`, its fingerprint that of
/// the program's version and the study's resolved text `resolved_toml`; the caller sets threads,
/// progress, compute and on_point.
JournaledPointsJob journaledPointsJob(const std::string& kind,
                                      const std::filesystem::path& journal_path,
                                      const std::string& resolved_toml, std::size_t points,
                                      std::size_t columns);

/// Runs the job. On a worker rank of a distributed run it computes the points the writer hands
/// out and returns nothing (the writer rank has the rows).
std::optional<JournaledPoints> runJournaledPoints(const JournaledPointsJob& job);

}  // namespace orni::studies
