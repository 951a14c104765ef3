#include "studies/runner/commands/run_info.hpp"

#include "core/model/frames.hpp"
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

JsonObject& setOperatingPoint(JsonObject& o, const OperatingPoint& point) {
  return o.set("freq_hz", point.freq_hz)
      .set("theta_mean_deg", point.theta_rad * kRadToDeg)
      .set("speed_mps", point.speed_mps)
      .set("tail_angle_deg", point.tail_angle_rad * kRadToDeg);
}

}  // namespace orni::studies
