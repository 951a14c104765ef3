#include "studies/runner/commands/run_info.hpp"

#include "core/version.hpp"

namespace orni::studies {

std::string versionString() {
  return std::string(orni::kVersion) + " (git " + orni::kGitRevision + ")";
}

}  // namespace orni::studies
