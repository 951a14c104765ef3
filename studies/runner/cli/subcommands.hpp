// The subcommands of `ornithopter` (docs/design.md 3), one file each in studies/runner/cli/:
// each adds its CLI11 subcommand with its options (names and help text as in docs/user-guide.md)
// and returns how to run it once parsed. main (studies/runner/main.cpp) adds them in the order of
// --help, parses, and runs the parsed one inside its one mapping of exceptions to exit codes.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

namespace orni::studies::cli {

struct Subcommand {
  CLI::App* app = nullptr;  ///< the CLI11 subcommand (parsed() after app.parse)
  /// Runs the parsed subcommand: its exit code; throws what main maps to exit codes.
  std::function<int()> run;
  /// True for the commands that spread points over the ranks of a distributed run (run, aeromap,
  /// optimize): a worker rank runs them too, and nothing else.
  bool runs_on_workers = false;
};

Subcommand addSimulateSubcommand(CLI::App& app);
Subcommand addRunSubcommand(CLI::App& app);
Subcommand addPlotSubcommand(CLI::App& app);
Subcommand addModesSubcommand(CLI::App& app);
Subcommand addAeromapSubcommand(CLI::App& app);
Subcommand addTrimSubcommand(CLI::App& app);
Subcommand addStabilitySubcommand(CLI::App& app);
Subcommand addOptimizeSubcommand(CLI::App& app);
Subcommand addReportSubcommand(CLI::App& app);
Subcommand addKeysSubcommand(CLI::App& app);

/// Every subcommand, in the order of `ornithopter --help`.
std::vector<Subcommand> addSubcommands(CLI::App& app);

}  // namespace orni::studies::cli
