// `ornithopter optimize STUDY [-o DIR] [-j N]`: a study of kind "optimize".
#include <memory>
#include <optional>
#include <string>

#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/commands/run_study.hpp"
#include "studies/runner/output/journal_file.hpp"

namespace orni::studies::cli {

namespace {

struct OptimizeArgs {
  std::string study;
  std::optional<std::string> out;
  std::optional<std::string> jobs;
  bool fresh = false;
};

int runOptimize(const OptimizeArgs& a) {
  const Study study = loadStudyFile(a.study);
  if (study.kind != StudyKind::kOptimize)
    throw CliError("command line: " + a.study +
                   ": expected a study of kind \"optimize\", got kind \"" +
                   std::string(toString(study.kind)) + "\" (run it with `ornithopter run`)");
  setFreshRun(a.fresh);
  return runStudyLocked(study, outputFolder(a.out, study, false), jobsOption(a.jobs));
}

}  // namespace

Subcommand addOptimizeSubcommand(CLI::App& app) {
  auto a = std::make_shared<OptimizeArgs>();
  auto* opt = app.add_subcommand(
      "optimize",
      "Design optimisation with NLopt (kind = \"optimize\" study): design variables "
      "(member sections and layout, tail area, aspect ratio and arm) sized so that "
      "the vehicle trims, flies bounded and needs the least flapping power; resumable");
  opt->add_option("STUDY", a->study, "Study file (TOML) of kind \"optimize\"")->required();
  opt->add_option("-o,--output", a->out,
                  "Output folder (default results/<study name>); an interrupted run resumes from "
                  "the journal there")
      ->check(nonEmptyPath());
  addFieldOption(opt, "-j,--jobs", "jobs", a->jobs,
                 "Worker threads (over the starts of a multi-start run)");
  opt->add_flag("--fresh", a->fresh, kFreshHelp);
  return {opt, [a] { return runOptimize(*a); }, true};
}

}  // namespace orni::studies::cli
