// `ornithopter modes VEHICLE [-o DIR] [--export-ccx FILE]`.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/commands/modes_command.hpp"
#include "studies/runner/output/folder_lock.hpp"

namespace orni::studies::cli {

namespace fs = std::filesystem;

namespace {

struct ModesArgs {
  std::string vehicle, ccx;
  std::optional<std::string> out;
};

int runModes(const ModesArgs& a) {
  const fs::path out = a.out ? fs::path(*a.out) : fs::path("results") / fs::path(a.vehicle).stem();
  const OutputFolderLock lock(out, FolderUse::kRun, "modes");
  return runModesCommand(a.vehicle, out, a.ccx);
}

}  // namespace

Subcommand addModesSubcommand(CLI::App& app) {
  auto a = std::make_shared<ModesArgs>();
  auto* modes = app.add_subcommand("modes",
                                   "Wing FE model: natural frequencies, effective masses, "
                                   "mode shapes; optional CalculiX deck");
  modes->add_option("VEHICLE", a->vehicle, "Vehicle file (TOML)")->required();
  modes->add_option("-o,--output", a->out, "Output folder (default results/<vehicle name>)")
      ->check(nonEmptyPath());
  modes->add_option("--export-ccx", a->ccx, "Also write the FE model as a CalculiX deck (.inp)")
      ->check(nonEmptyPath());
  return {modes, [a] { return runModes(*a); }, false};
}

}  // namespace orni::studies::cli
