#include "studies/runner/output/summary_file.hpp"

#include <stdexcept>

#include "core/model/frames.hpp"
#include "core/version.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/output_schema.hpp"

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

void writeSummary(const std::filesystem::path& dir, const JsonObject& summary) {
  const std::string text = summary.toString() + "\n";
  const OutputCheck check = checkSummaryText(text);
  if (!check.findings.empty()) {
    std::string list;
    for (const std::string& f : check.findings) list += "\n  " + f;
    throw std::logic_error("summary.json of a " + check.kind +
                           " run: values the output table does not declare "
                           "(studies/runner/output/output_schema_table.cpp):" + list);
  }
  writeFileAtomic(dir / "summary.json", text);
}

}  // namespace orni::studies
