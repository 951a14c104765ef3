#include "studies/runner/commands/failed_run.hpp"
#include "studies/runner/output/console.hpp"

#include <system_error>

namespace orni::studies {

void removeRunOutputs(const std::filesystem::path& dir, const std::vector<std::string>& files,
                      const std::vector<std::string>& figure_stems) {
  std::error_code ec;
  for (const std::string& f : files) std::filesystem::remove(dir / f, ec);
  for (const std::string& stem : figure_stems)
    for (const char* ext : {".gp", ".png", ".svg"}) std::filesystem::remove(dir / (stem + ext), ec);
}

int reportFailedRun(const Study& study, const std::string& cause,
                    const std::filesystem::path& out_dir) {
  consoleErr() << "ornithopter: " << study.name << ": the simulation failed: " << cause
            << "\n  no results and no figures; status in " << (out_dir / "summary.json").string()
            << "\n";
  return 1;
}

}  // namespace orni::studies
