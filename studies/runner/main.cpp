// ornithopter: the command-line front end (docs/design.md 3). Only main catches everything and
// maps it to the exit code: 0 finished (whatever the physics verdict), 1 failed, 2 bad input.
// The subcommands' options and wiring: studies/runner/cli/ (one file each).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model/cancellation.hpp"
#include "core/model/invalid_model_error.hpp"
#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "studies/runner/distributed/point_farm.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/output/interrupted_run.hpp"
#include "studies/runner/output/journal_file.hpp"

#ifdef ORNI_HAVE_MPI
#include "studies/runner/mpi/mpi_farm.hpp"
#endif

using namespace orni;
using namespace orni::studies;
using namespace orni::studies::cli;

namespace {

/// Bad input (exit 2): the message on rank 0 only (every rank of a distributed run parses and
/// loads the same input and meets the same error, which one message reports).
int badInput(const std::string& message) {
  if (farmWriter()) std::cerr << "ornithopter: error: " << message << "\n";
  return kExitBadInput;
}

std::vector<std::string> subcommandNames(CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  return names;
}

}  // namespace

/// The command line of one process (every rank of a distributed run parses and loads the same).
int runCommandLine(int argc, char** argv) {
  CLI::App app{"ornithopter: flexible flapping-wing flight simulation, aero maps, trim and design"};
  app.require_subcommand(1);
  app.add_flag_callback(
      "--version",
      [] {
        std::cout << "ornithopter " << versionString() << "\n";
        throw CLI::Success();
      },
      "Print the version and git revision");
  const std::vector<Subcommand> commands = addSubcommands(app);
  // --no-figures on every command that runs a study: figure scripts only ([output] figures).
  bool no_figures = false;
  for (const Subcommand& c : commands)
    if (c.app->get_name() != "plot" && c.app->get_name() != "keys" &&
        c.app->get_name() != "report")
      c.app->add_flag("--no-figures", no_figures,
                      "Write the figures' scripts (*.gp) but draw no figure (as [output] figures "
                      "= false; `ornithopter plot DIR` draws them later)");

  // A mistyped subcommand: name the nearest one, as a mistyped key does.
  const std::vector<std::string> subcommands = subcommandNames(app);
  if (argc >= 2 && argv[1][0] != '-' &&
      std::find(subcommands.begin(), subcommands.end(), argv[1]) == subcommands.end()) {
    const std::string near = closestMatch(argv[1], subcommands);
    return badInput("unknown subcommand '" + std::string(argv[1]) + "'" +
                    (near.empty() ? std::string() : " (did you mean '" + near + "'?)") +
                    "; run with --help for the list");
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::ostringstream discard;  // a worker rank says nothing (rank 0 prints it)
    const int rc = farmWriter() ? app.exit(e) : app.exit(e, discard, discard);
    return rc == 0 ? kExitOk : kExitBadInput;
  }

  // A worker rank of a distributed run takes part in the commands that spread points (run,
  // aeromap, optimize) and does nothing else (rank 0 runs the rest alone).
  const auto parsed = std::find_if(commands.begin(), commands.end(),
                                   [](const Subcommand& c) { return c.app->parsed(); });
  if (!farmWriter() && (parsed == commands.end() || !parsed->runs_on_workers)) return kExitOk;

  try {
    // Every subcommand returns here; CLI11 rejects any other name before this point.
    if (parsed == commands.end())
      throw std::logic_error("unhandled subcommand " + app.get_subcommands().front()->get_name());
    setFiguresWanted(!no_figures);
    return parsed->run();
  } catch (const InputError& e) {
    return badInput(e.what());
  } catch (const CliError& e) {
    return badInput(e.what());
  } catch (const FolderBusyError& e) {
    return badInput(e.what());
  } catch (const OutputPathError& e) {
    return badInput(e.what());
  } catch (const ForeignJournalError& e) {
    return badInput(e.what());
  } catch (const Cancelled&) {
    // SIGINT/SIGTERM (interrupted_run.hpp): the run unwound; its folder says "interrupted".
    std::cerr << "ornithopter: interrupted by " << interruptSignalName() << "\n";
    return 128 + (interruptSignal() > 0 ? interruptSignal() : 2);
  } catch (const InvalidModelError& e) {
    return badInput(std::string("invalid model: ") + e.what());
  } catch (const std::exception& e) {
    std::cerr << "ornithopter: failed: " << e.what() << "\n";
    return kExitFailed;
  }
}

int main(int argc, char** argv) {
  installInterruptHandlers();
#ifdef ORNI_HAVE_MPI
  // Started by mpirun/srun: rank 0 is the master, the others compute (studies/runner/mpi/).
  // Otherwise no MPI function is called: the program runs as a build without MPI.
  if (launchedByMpi()) {
    MpiFarm mpi(&argc, &argv);
    setFarmBackend(&mpi);
    const int rc = runCommandLine(argc, argv);
    // A worker rank with bad input waits for rank 0, which meets the same error, prints it and
    // aborts the run with its status (a worker aborting first would kill rank 0 before it says).
    const bool quiet_worker = !farmWriter() && rc == kExitBadInput;
    setFarmBackend(nullptr);
    return mpi.finish(quiet_worker ? kExitOk : rc);
  }
#endif
  return runCommandLine(argc, argv);
}
