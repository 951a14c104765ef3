#include "studies/runner/commands/run_info.hpp"

#ifndef ORNI_VERSION
#define ORNI_VERSION "0.0.0"
#endif
#ifndef ORNI_GIT_REVISION
#define ORNI_GIT_REVISION "unknown"
#endif

namespace orni::studies {

std::string versionString() { return std::string(ORNI_VERSION) + " (git " ORNI_GIT_REVISION ")"; }

}  // namespace orni::studies
