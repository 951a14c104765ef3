// summary.json, the one file every run writes (docs/outputs.md): its header (the five values every
// run kind's summary begins with), the operating point as every summary writes it, and the one
// writer, which refuses a value the output table (output_schema.hpp) does not declare for the run's
// kind. So no run, of any kind, in any test or user's folder, can write a summary value the
// listing of `ornithopter keys --outputs` and docs/outputs.md do not describe.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/model/vehicle_model.hpp"
#include "studies/runner/output/json_writer.hpp"

namespace orni::studies {

/// "0.1.0 (git abc1234)": --version and summary.json's version.
std::string versionString();

/// A summary.json object holding kind, status, message, wall_time_s and version, in that order;
/// the run kind's own values follow.
JsonObject summaryHeader(std::string_view kind, std::string_view status, const std::string& message,
                         double wall_time_s);

/// Sets freq_hz, theta_mean_deg, speed_mps and tail_angle_deg of `point` (file units, degrees), in
/// that order: an operating point as every summary writes it.
JsonObject& setOperatingPoint(JsonObject& o, const OperatingPoint& point);

/// Writes `summary` (begun by summaryHeader) as DIR/summary.json, atomically. Throws
/// std::logic_error, writing nothing, when a value's path is not in the output table for the
/// summary's kind (a programming error: the table gains the entry with the code that writes it).
void writeSummary(const std::filesystem::path& dir, const JsonObject& summary);

}  // namespace orni::studies
