// The journal that makes an optimisation resumable (like the aero map's, aeromap_journal.hpp):
// DIR/optimize.journal holds one line per computed evaluation, appended as soon as it is done, so
// a killed run loses at most the evaluations in flight. A restarted run replays the journal: when
// NLopt asks start k for its i-th evaluation at exactly the journaled point, the journaled result
// is returned without computing (the driver's OptimizerHooks::replay), so the run retraces the
// interrupted one and continues from where it stopped; the outputs are the same bytes as an
// uninterrupted run's.
//
// Format (text, one record per line):
//   # ornithopter optimize journal v1 fingerprint=<16 hex> variables=<n> constraints=<m> values=<k>
//   <16 hex digits FNV-1a of the rest> <start>,<index>,<status>,<x_1..x_n>,<objective>,
//       <g_1..g_m>,<v_1..v_k>,<message>
// (one line; numbers in shortest round-trip form, "nan" for a missing value; the message last, may
// hold commas). A record is trusted only when it ends with a newline, its checksum matches and
// every field parses; for the same (start, index) the later record wins. The fingerprint is a hash
// of the version and the resolved study; a journal with another fingerprint or other sizes is
// discarded. Each record is one write(2); fdatasync at most once a second and on close.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "optimize/optimizer.hpp"
#include "studies/runner/output/journal_file.hpp"

namespace orni::studies {

/// Sizes of the records of one optimisation.
struct OptimizeJournalShape {
  int variables = 0, constraints = 0, values = 0;
};

/// One journaled evaluation.
struct JournaledEvaluation {
  std::vector<double> x;
  orni::opt::Evaluation result;
};

/// One journal line (with its newline) for a record.
std::string optimizeJournalRecord(const orni::opt::EvaluationRecord& record);
/// Parses one journal line (without its newline); false when it is not a valid record of `shape`.
bool parseOptimizeJournalRecord(std::string_view line, const OptimizeJournalShape& shape,
                                int* start, int* index, JournaledEvaluation* evaluation);

/// What reopening a journal found.
struct OptimizeJournalResume {
  bool existed = false;
  bool fingerprint_matched = false;
  std::size_t records = 0;         ///< valid records taken over
  std::size_t rejected_lines = 0;  ///< torn or corrupt lines dropped
  std::map<std::pair<int, int>, JournaledEvaluation> evaluations;  ///< by (start, index)

  /// The journaled result of (start, index) when it was made at exactly x.
  std::optional<orni::opt::Evaluation> replay(int start, int index,
                                              const std::vector<double>& x) const;
};

class OptimizeJournal {
 public:
  /// Opens `file`. A journal with the same fingerprint and shape is resumed (*resume); anything
  /// else there is discarded. The file is rewritten atomically with the header and the valid
  /// records only, then kept open for appending. Throws std::runtime_error when it cannot be
  /// written.
  OptimizeJournal(std::filesystem::path file, std::uint64_t fingerprint,
                  const OptimizeJournalShape& shape, OptimizeJournalResume* resume);
  OptimizeJournal(const OptimizeJournal&) = delete;
  OptimizeJournal& operator=(const OptimizeJournal&) = delete;

  /// Appends a record (one write; thread-safe). Throws std::runtime_error on failure.
  void append(const orni::opt::EvaluationRecord& record);
  /// Closes and deletes the journal (after the final outputs are written).
  void remove();

  const std::filesystem::path& path() const { return file_->path(); }

 private:
  std::optional<JournalFile> file_;  // set by the constructor
};

}  // namespace orni::studies
