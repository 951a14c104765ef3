// `ornithopter report DIR...`: writes the HTML report (index.html) of finished runs again, from
// their files: of a run folder (it has a summary.json), or of every run folder directly inside a
// folder of runs (`run A.toml B.toml -o DIR`, results/paper), with that folder's index page.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/output/html_report.hpp"

namespace orni::studies::cli {

namespace fs = std::filesystem;

namespace {

bool isRunFolder(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / "summary.json", ec);
}

int runReport(const std::vector<std::string>& dirs) {
  for (const std::string& d : dirs) {
    const fs::path dir(d);
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
      throw CliError("command line: DIR " + d + ": " +
                     (fs::exists(dir, ec) ? "not a folder" : "no such folder"));
    if (isRunFolder(dir)) {
      const OutputFolderLock lock(dir, FolderUse::kRedraw);
      writeRunReport(dir);
      std::cout << "wrote " << (dir / "index.html").string() << "\n";
      continue;
    }
    std::vector<fs::path> runs;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_directory(ec) && isRunFolder(e.path())) runs.push_back(e.path());
    if (runs.empty())
      throw CliError("command line: DIR " + d +
                     ": neither a run folder (no summary.json) nor a folder of runs");
    std::sort(runs.begin(), runs.end());
    for (const fs::path& run : runs) {
      const OutputFolderLock lock(run, FolderUse::kRedraw);
      writeRunReport(run);
    }
    writeSetReport(dir, runs);
    std::cout << "wrote " << (dir / "index.html").string() << " and the reports of " << runs.size()
              << " runs\n";
  }
  return kExitOk;
}

}  // namespace

Subcommand addReportSubcommand(CLI::App& app) {
  auto dirs = std::make_shared<std::vector<std::string>>();
  auto* report = app.add_subcommand(
      "report", "(Re)write the HTML report (index.html) of finished runs or a folder of runs");
  report->add_option("DIR", *dirs, "Run output folder, or a folder of run folders")
      ->required()
      ->check(nonEmptyPath());
  return {report, [dirs] { return runReport(*dirs); }, false};
}

}  // namespace orni::studies::cli
