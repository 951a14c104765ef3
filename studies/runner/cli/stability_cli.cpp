// `ornithopter stability VEHICLE [--freq F] [-o DIR]`: the periodic-orbit trim and all its Floquet
// multipliers.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "core/model/invalid_model_error.hpp"
#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/commands/periodic_trim_command.hpp"
#include "studies/runner/commands/run_study.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/output/heartbeat.hpp"
#include "trim/trim_options.hpp"

namespace orni::studies::cli {

namespace {

struct StabilityArgs {
  std::string vehicle;
  std::optional<std::string> out;
  std::optional<std::string> freq;
};

int runStability(const StabilityArgs& a) {
  Study study = studyFromVehicle(a.vehicle, StudyKind::kTrim);
  if (a.freq) study.trim.initial.freq_hz = optionValue("--freq", "trim.freq_hz", *a.freq);
  study = stabilityStudy(std::move(study));
  return runStabilityLocked(study, outputFolder(a.out, study, false));
}

}  // namespace

Subcommand addStabilitySubcommand(CLI::App& app) {
  auto a = std::make_shared<StabilityArgs>();
  auto* stab = app.add_subcommand(
      "stability",
      "Floquet stability of trimmed flight: the periodic-orbit trim, the monodromy "
      "matrix of the orbit and all its multipliers, sorted and labelled");
  stab->add_option("VEHICLE", a->vehicle, "Vehicle file (TOML) with a [body] section")->required();
  addFieldOption(stab, "--freq", "trim.freq_hz", a->freq,
                 "Flapping frequency f (Hz) (default: the vehicle's operating point)");
  stab->add_option("-o,--output", a->out,
                   "Output folder (default results/<vehicle name>_stability)")
      ->check(nonEmptyPath());
  return {stab, [a] { return runStability(*a); }, false};
}

}  // namespace orni::studies::cli
