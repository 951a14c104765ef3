// `ornithopter run STUDY... [-o DIR] [-j N]`: every study file, each by its kind.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/commands/run_study.hpp"
#include "studies/runner/distributed/point_farm.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/output/html_report.hpp"
#include "studies/runner/output/journal_file.hpp"

namespace orni::studies::cli {

namespace fs = std::filesystem;

namespace {

struct RunArgs {
  std::vector<std::string> files;
  std::optional<std::string> out;
  std::optional<std::string> jobs;
  bool fresh = false;
};

int runStudies(const RunArgs& a) {
  const int jobs = jobsOption(a.jobs);
  setFreshRun(a.fresh);
  // Load (and validate) every study first, so a typo in the last one fails before any work.
  std::vector<Study> studies;
  for (const std::string& f : a.files) studies.push_back(loadStudyFile(f));
  // One writer per folder: every output folder locked before any work, none shared.
  std::vector<fs::path> outs;
  for (const Study& s : studies) {
    outs.push_back(outputFolder(a.out, s, studies.size() > 1));
    for (std::size_t i = 0; i + 1 < outs.size(); ++i)
      if (outs[i].lexically_normal() == outs.back().lexically_normal())
        throw CliError("command line: studies " + inputFileOf(studies[i]) + " and " +
                       inputFileOf(s) + " both write into " + outs.back().string() +
                       " (give them different names, `name = ...`)");
  }
  std::vector<std::unique_ptr<OutputFolderLock>> locks;  // the writer's (rank 0's) only
  if (farmWriter())
    for (std::size_t i = 0; i < outs.size(); ++i)
      locks.push_back(std::make_unique<OutputFolderLock>(outs[i], FolderUse::kRun,
                                                         std::string(toString(studies[i].kind))));
  for (std::size_t i = 0; i < locks.size(); ++i) locks[i]->setRunning(false);
  int rc = kExitOk;
  for (std::size_t i = 0; i < studies.size(); ++i) {
    if (i < locks.size()) locks[i]->setRunning(true);
    const int r = runStudy(studies[i], outs[i], jobs);
    if (i < locks.size()) locks[i]->setRunning(false);
    if (r != kExitOk) rc = r;
  }
  // Several studies into DIR/<name>: DIR/index.html links their reports.
  if (farmWriter() && a.out && studies.size() > 1) writeSetReport(fs::path(*a.out), outs);
  return rc;
}

}  // namespace

Subcommand addRunSubcommand(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  auto* run = app.add_subcommand("run", "Run one or more study files (kind given inside)");
  run->add_option("STUDY", a->files, "Study files (TOML)")->required();
  run->add_option("-o,--output", a->out,
                  "Output folder (default results/<study name>); with several studies each goes "
                  "into DIR/<study name>")
      ->check(nonEmptyPath());
  addFieldOption(run, "-j,--jobs", "jobs", a->jobs, "Worker threads");
  run->add_flag("--fresh", a->fresh, kFreshHelp);
  return {run, [a] { return runStudies(*a); }, true};
}

}  // namespace orni::studies::cli
