// The [continuation] section of a study of kind "continuation" (trim/trim_continuation.hpp):
//
//   kind = "continuation"
//   vehicle = "../vehicles/efw_magpie.toml"
//   [trim]                      # the periodic trim the branch starts from ([trim] keys; the
//   freq_hz = 12.0              #   method is "periodic" whatever is written; [trim.periodic]
//                               #   control is the unknown that keeps every orbit level)
//   [continuation]
//   parameter = "freq_hz"       # "freq_hz" | "tail_angle_deg" | "cg_shift_m" (not the control)
//   to = 16.0                   # the end of the branch, in the parameter's units
//   step = 0.2                  # first step in the parameter (default 0.2 Hz, 0.5 deg, 2 mm)
//   max_points = 30             # regular points after the start, [1, 10000]
//   locate_events = true        # folds and stability changes located by bisection
//
// The branch starts at the periodic trim's value of the parameter (its frequency, its tail angle,
// or CG shift 0) and runs towards `to`. Every error is an InputError naming file, line and key.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "studies/runner/config/toml_access.hpp"
#include "trim/trim_continuation.hpp"
#include "trim/trim_options.hpp"

namespace orni::studies {

/// The keys a [continuation] table may have.
std::vector<std::string> continuationSectionKeys();

/// "freq_hz", "tail_angle_deg", "cg_shift_m" (the file's names of the parameters).
const char* continuationParameterName(orni::PeriodicControl p);

/// Reads [continuation] into options in SI (the parameter's end and step converted from file
/// units). Throws InputError.
orni::TrimContinuationOptions readContinuationSection(TableReader& section);

void writeContinuationSection(const orni::TrimContinuationOptions& o, TomlWriter& out);

/// The branch's start value of the parameter (SI) when the study fixes it: the [trim] frequency
/// or tail angle when Eq. (4) does not solve for it, CG shift 0; none when the trim solves it.
std::optional<double> continuationStart(const orni::TrimContinuationOptions& o,
                                        const orni::TrimOptions& trim);

/// `to` equal to the known start: an InputError at [continuation] to (a branch of no length).
void checkContinuationEnd(const TableReader& section, const orni::TrimContinuationOptions& o,
                          const orni::TrimOptions& trim);

}  // namespace orni::studies
