#include "studies/runner/commands/run_info.hpp"

#include "core/version.hpp"

namespace orni::studies {

std::string versionString() {
  return std::string(orni::kVersion) + " (git " + orni::kGitRevision + ")";
}

JsonObject summaryHeader(std::string_view kind, std::string_view status, const std::string& message,
                         double wall_time_s) {
  JsonObject summary;
  summary.set("kind", std::string(kind))
      .set("status", std::string(status))
      .set("message", message)
      .set("wall_time_s", wall_time_s)
      .set("version", versionString());
  return summary;
}

}  // namespace orni::studies
