// `ornithopter plot RUN_DIR`: redraws the figures of a finished run.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <system_error>

#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/output/html_report.hpp"
#include "studies/runner/output/run_outputs.hpp"
#include "studies/runner/plotting/gnuplot.hpp"

namespace orni::studies::cli {

namespace fs = std::filesystem;

namespace {

int runPlot(const std::string& plot_dir) {
  const fs::path dir(plot_dir);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw CliError("command line: RUN_DIR " + plot_dir + ": " +
                   (fs::exists(dir, ec) ? "not a folder" : "no such folder"));
  if (!fs::is_regular_file(dir / "summary.json", ec))
    throw CliError("command line: RUN_DIR " + plot_dir +
                   ": not a run folder (no summary.json; expected the output folder of an "
                   "ornithopter run)");
  const OutputFolderLock lock(dir, FolderUse::kRedraw);
  // Only the figures of the run the summary describes (a folder written by an older version may
  // hold another run's scripts beside it).
  const std::string kind = summaryKind(dir);
  int skipped = 0;
  const int n = redrawFigures(dir, [&](const std::string& stem) {
    const bool ours = isFigureOfKind(kind, stem);
    skipped += ours ? 0 : 1;
    return ours;
  });
  if (n == 0)
    throw CliError("command line: RUN_DIR " + plot_dir +
                   ": no figure scripts (*.gp) of its " + (kind.empty() ? "" : kind + " ") +
                   "run to draw (this run drew no figures)");
  writeRunReport(dir);  // its figures are drawn now
  std::cout << "redrew " << n << " figure(s) in " << plot_dir << "\n";
  if (skipped > 0)
    std::cout << "left out " << skipped << " figure script(s) of another kind of run than the "
              << "summary's (" << kind << ")\n";
  return kExitOk;
}

}  // namespace

Subcommand addPlotSubcommand(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  auto* plot = app.add_subcommand("plot", "(Re)draw the figures of a finished run");
  plot->add_option("RUN_DIR", *dir, "Run output folder")->required()->check(nonEmptyPath());
  return {plot, [dir] { return runPlot(*dir); }, false};
}

}  // namespace orni::studies::cli
