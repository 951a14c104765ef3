#include "studies/runner/commands/run_study.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "core/model/invalid_model_error.hpp"
#include "studies/runner/commands/aeromap_command.hpp"
#include "studies/runner/commands/calibrate_command.hpp"
#include "studies/runner/commands/continuation_command.hpp"
#include "studies/runner/commands/modes_command.hpp"
#include "studies/runner/commands/optimize_command.hpp"
#include "studies/runner/commands/periodic_trim_command.hpp"
#include "studies/runner/commands/sensitivity_command.hpp"
#include "studies/runner/commands/simulate_command.hpp"
#include "studies/runner/commands/sweep_command.hpp"
#include "studies/runner/commands/trim_command.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "studies/runner/distributed/point_farm.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/output/heartbeat.hpp"
#include "studies/runner/output/html_report.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "trim/trim_options.hpp"

namespace fs = std::filesystem;

namespace orni::studies {

namespace {

/// The kinds whose points a distributed run spreads over the ranks (point_farm.hpp).
bool spreadsPoints(StudyKind kind) {
  return kind == StudyKind::kAeromap || kind == StudyKind::kSweep ||
         kind == StudyKind::kSensitivity || kind == StudyKind::kOptimize;
}

/// The kinds that have no points to count: a heartbeat line shows they are running
/// (docs/design.md 4.4); the others print their own progress (points, evaluations).
bool needsHeartbeat(StudyKind kind) {
  return kind == StudyKind::kSimulate || kind == StudyKind::kTrim ||
         kind == StudyKind::kCalibrate || kind == StudyKind::kContinuation;
}

int runStudyKind(const Study& study, const fs::path& out_dir, int jobs) {
  // A worker rank of a distributed run: the sequential kinds are rank 0's alone.
  if (!farmWriter() && !spreadsPoints(study.kind)) return 0;
  std::optional<Heartbeat> heartbeat;
  if (needsHeartbeat(study.kind)) heartbeat.emplace(std::string(toString(study.kind)));
  // The kinds that spread points over threads take `jobs` in their run options.
  auto withThreads = [jobs](auto opts) {
    opts.threads = jobs;
    return opts;
  };
  switch (study.kind) {
    case StudyKind::kSimulate: return runSimulateStudy(study, out_dir);
    case StudyKind::kAeromap:
      return runAeromapStudy(study, out_dir, withThreads(AeromapRunOptions{}));
    case StudyKind::kModes: return runModesStudy(study, out_dir);
    case StudyKind::kTrim: {  // the Jacobians' runs on the run's threads (same results)
      Study threaded = study;
      threaded.trim.jacobian_threads = std::min(jobs, 64);
      return runTrimStudy(threaded, out_dir);
    }
    case StudyKind::kCalibrate: return runCalibrateStudy(study, out_dir);
    case StudyKind::kSweep: return runSweepStudy(study, out_dir, withThreads(SweepRunOptions{}));
    case StudyKind::kContinuation: return runContinuationStudy(study, out_dir, jobs);
    case StudyKind::kSensitivity:
      return runSensitivityStudy(study, out_dir, withThreads(SensitivityRunOptions{}));
    case StudyKind::kOptimize:
      return runOptimizeStudy(study, out_dir, withThreads(OptimizeRunOptions{}));
  }
  throw std::logic_error("runStudyKind: a study kind without a runner");
}

}  // namespace

int runStudy(const Study& study, const fs::path& out_dir, int jobs) {
  try {
    const FiguresScope figures(study.figures);  // [output] figures = false: scripts only
    const int rc = runStudyKind(study, out_dir, jobs);
    // The HTML report of the finished run (a failed run has its summary.json too).
    std::error_code ec;
    if (farmWriter() && fs::is_regular_file(out_dir / "summary.json", ec))
      writeRunReport(out_dir);
    return rc;
  } catch (const InvalidModelError& e) {
    throw InputError(inputFileOf(study), 0, std::string(), std::string("invalid model: ") +
                                                               e.what());
  }
}

Study stabilityStudy(Study study) {
  study.name += "_stability";
  TrimOptions& o = study.trim;
  usePeriodicMethod(&o);
  o.periodic.multipliers = 0;    // all of them: the full monodromy matrix
  o.periodic.multiplier_check = true;  // and whether each is resolved (a finer grid's monodromy)
  o.verify_free_flight = false;  // the verdict is Floquet's; `trim` runs the Eq. (5) check
  std::string why;
  if (!o.IsValid(&why))
    throw InputError(inputFileOf(study), 0, "trim", "stability options: " + why);
  return study;
}

int runStabilityLocked(const Study& study, const fs::path& out_dir) {
  const OutputFolderLock lock(out_dir, FolderUse::kRun, "stability");
  const Heartbeat heartbeat("stability");  // a periodic trim has no points to count
  try {
    const FiguresScope figures(study.figures);
    const int rc = runPeriodicTrimStudy(study, out_dir, PeriodicRunKind::kStability);
    std::error_code ec;
    if (fs::is_regular_file(out_dir / "summary.json", ec)) writeRunReport(out_dir);
    return rc;
  } catch (const InvalidModelError& e) {
    throw InputError(inputFileOf(study), 0, std::string(),
                     std::string("invalid model: ") + e.what());
  }
}

int runStudyLocked(const Study& study, const fs::path& out_dir, int jobs) {
  std::optional<OutputFolderLock> lock;  // the writer's (rank 0's) only
  if (farmWriter()) lock.emplace(out_dir, FolderUse::kRun, std::string(toString(study.kind)));
  return runStudy(study, out_dir, jobs);
}

}  // namespace orni::studies
