#include "trim/ceres_logging.hpp"

#include <glog/logging.h>

#include <mutex>

namespace orni {

void quietCeresLogging() {
  static std::once_flag once;
  std::call_once(once, [] { FLAGS_minloglevel = google::GLOG_FATAL; });
}

}  // namespace orni
