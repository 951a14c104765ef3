// Ceres logs through glog to stderr (a cost function that fails, a solve that stops on it). Our
// summaries already say why a solve ended, so library calls keep the console quiet:
// quietCeresLogging() raises glog's threshold to FATAL once per process. Internal: not installed.
#pragma once

namespace orni {

/// Drops Ceres's INFO, WARNING and ERROR log lines for the rest of the process (idempotent,
/// thread-safe). Called before every Ceres solve of this library.
void quietCeresLogging();

}  // namespace orni
