// `ornithopter aeromap VEHICLE --speed A:B:N --freq .. --theta .. [--tail ..] [--cycles] [-j]
// [-o]`.
// [-o]`.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/commands/aeromap_command.hpp"
#include "studies/runner/distributed/point_farm.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/output/journal_file.hpp"
#include "trim/aero_map_options.hpp"

namespace orni::studies::cli {

namespace fs = std::filesystem;

namespace {

struct AeromapArgs {
  std::string vehicle, speed, freq, theta, tail;
  std::optional<std::string> out;
  std::optional<std::string> cycles, jobs;
  bool fresh = false;
};

int runAeromap(const AeromapArgs& a) {
  GridAxis speed = axisOption("--speed", "aeromap.speed_mps", a.speed);
  GridAxis freq = axisOption("--freq", "aeromap.freq_hz", a.freq);
  GridAxis theta = axisOption("--theta", "aeromap.theta_deg", a.theta);
  std::optional<GridAxis> tail;
  if (!a.tail.empty()) tail = axisOption("--tail", "aeromap.tail_angle_deg", a.tail);
  std::size_t points = speed.values.size() * freq.values.size() * theta.values.size();
  if (tail) points *= tail->values.size();
  if (points > kMaxAeroMapPoints)
    throw CliError(
        "command line: options --speed, --freq, --theta, --tail: expected a grid of "
        "at most " +
        std::to_string(kMaxAeroMapPoints) + " points, got " + std::to_string(points));
  const bool nonzero_tail =
      tail && std::any_of(tail->values.begin(), tail->values.end(),
                          [](double v) { return v != 0.0; });
  Study study = aeromapStudyFromVehicle(a.vehicle, std::move(speed), std::move(freq),
                                        std::move(theta), std::move(tail));
  if (nonzero_tail && !study.vehicle.tail.present)
    throw CliError("command line: option --tail: expected 0 or no tail angle (key "
                   "aeromap.tail_angle_deg): the vehicle has no [tail], got '" + a.tail + "'");
  if (a.cycles)
    study.aeromap().options.cycles =
        static_cast<int>(optionValue("--cycles", "aeromap.cycles", *a.cycles));
  AeromapRunOptions opts;
  opts.threads = jobsOption(a.jobs);
  setFreshRun(a.fresh);
  const fs::path out = outputFolder(a.out, study, false);
  std::optional<OutputFolderLock> lock;  // the writer's (rank 0's) only
  if (farmWriter()) lock.emplace(out, FolderUse::kRun, "aeromap");
  return runAeromapStudy(study, out, opts);
}

}  // namespace

Subcommand addAeromapSubcommand(CLI::App& app) {
  auto a = std::make_shared<AeromapArgs>();
  auto* am = app.add_subcommand(
      "aeromap",
      "Aero map: cycle-mean tethered loads over a grid of speed, frequency, pitch and "
      "tail angle (paper Fig. 5); resumable");
  am->add_option("VEHICLE", a->vehicle, "Vehicle file (TOML)")->required();
  addFieldOption(am, "--speed", "aeromap.speed_mps", a->speed,
                 "Speeds U (m/s) A:B:N: N values from A to B inclusive")
      ->required();
  addFieldOption(am, "--freq", "aeromap.freq_hz", a->freq, "Flapping frequencies f (Hz) A:B:N")
      ->required();
  addFieldOption(am, "--theta", "aeromap.theta_deg", a->theta, "Mean pitch attitudes (deg) A:B:N")
      ->required();
  addFieldOption(am, "--tail", "aeromap.tail_angle_deg", a->tail,
                 "Tail elevation angles delta_T (deg) A:B:N (default: the vehicle's "
                 "operating-point tail angle)");
  addFieldOption(am, "--cycles", "aeromap.cycles", a->cycles,
                 "Maximum flapping cycles per point (default 40)");
  addFieldOption(am, "-j,--jobs", "jobs", a->jobs, "Worker threads");
  am->add_option("-o,--output", a->out,
                 "Output folder (default results/<vehicle name>_aeromap); an interrupted run "
                 "resumes from the journal there")
      ->check(nonEmptyPath());
  am->add_flag("--fresh", a->fresh, kFreshHelp);
  return {am, [a] { return runAeromap(*a); }, true};
}

}  // namespace orni::studies::cli
