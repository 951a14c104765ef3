// Version text shared by --version and summary.json, the summary's header (the five values every
// run kind's summary.json begins with, docs/outputs.md) and its operating points.
#pragma once

#include <string>
#include <string_view>

#include "core/model/vehicle_model.hpp"
#include "studies/runner/output/json_writer.hpp"

namespace orni::studies {

/// "0.1.0 (git abc1234)".
std::string versionString();

/// A summary.json object holding kind, status, message, wall_time_s and version, in that order;
/// the run kind's own values follow.
JsonObject summaryHeader(std::string_view kind, std::string_view status, const std::string& message,
                         double wall_time_s);

/// Sets freq_hz, theta_mean_deg, speed_mps and tail_angle_deg of `point` (file units, degrees), in
/// that order: an operating point as every summary writes it.
JsonObject& setOperatingPoint(JsonObject& o, const OperatingPoint& point);

}  // namespace orni::studies
