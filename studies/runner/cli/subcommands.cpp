#include "studies/runner/cli/subcommands.hpp"

namespace orni::studies::cli {

std::vector<Subcommand> addSubcommands(CLI::App& app) {
  return {addSimulateSubcommand(app),  addRunSubcommand(app),      addPlotSubcommand(app),
          addModesSubcommand(app),     addAeromapSubcommand(app),  addTrimSubcommand(app),
          addStabilitySubcommand(app), addOptimizeSubcommand(app), addReportSubcommand(app),
          addKeysSubcommand(app)};
}

}  // namespace orni::studies::cli
