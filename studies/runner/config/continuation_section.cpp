#include "studies/runner/config/continuation_section.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "core/model/field_table.hpp"
#include "core/model/frames.hpp"
#include "core/model/value_range.hpp"

namespace orni::studies {

namespace {

using orni::PeriodicControl;

std::vector<std::pair<std::string, PeriodicControl>> parameterChoices() {
  return {{"freq_hz", PeriodicControl::kFrequency},
          {"tail_angle_deg", PeriodicControl::kTailAngle},
          {"cg_shift_m", PeriodicControl::kCgPosition}};
}

// A forward CG shift beyond 0.1 m moves the CG of a vehicle of the magpie's size (tail arm 0.14 m,
// root chord 0.1 m) off the airframe: no branch worth following goes there.
constexpr Range kCgShiftRange = Range::closed(-0.1, 0.1);

/// SI per file unit of the parameter (deg -> rad for the tail angle).
double siPerFile(PeriodicControl p) {
  return p == PeriodicControl::kTailAngle ? orni::kDegToRad : 1.0;
}

/// The range of the branch's end in file units.

Range endRange(PeriodicControl p) {
  switch (p) {
    case PeriodicControl::kFrequency: return orni::field("trim.freq_hz").range;
    case PeriodicControl::kTailAngle: return orni::field("trim.initial.tail_angle_deg").range;
    case PeriodicControl::kCgPosition: return kCgShiftRange;
  }
  return kCgShiftRange;
}

/// The default first step in file units: 0.2 Hz, 0.5 deg, 2 mm (about 30 points over the ranges
/// a designer asks for: 10-16 Hz, a 15 deg tail range, a 6 cm CG range).
double defaultStep(PeriodicControl p) {
  switch (p) {
    case PeriodicControl::kFrequency: return 0.2;
    case PeriodicControl::kTailAngle: return 0.5;
    case PeriodicControl::kCgPosition: return 0.002;
  }
  return 0.2;
}

}  // namespace

std::vector<std::string> continuationSectionKeys() {
  return {"parameter", "to", "step", "max_points", "locate_events"};
}

const char* continuationParameterName(PeriodicControl p) {
  switch (p) {
    case PeriodicControl::kFrequency: return "freq_hz";
    case PeriodicControl::kTailAngle: return "tail_angle_deg";
    case PeriodicControl::kCgPosition: return "cg_shift_m";
  }
  return "freq_hz";
}

orni::TrimContinuationOptions readContinuationSection(TableReader& t) {
  orni::TrimContinuationOptions o;
  o.parameter = t.requiredEnum("parameter", parameterChoices());
  const double si = siPerFile(o.parameter);
  const std::string unit_note =
      std::string(" (the range of ") + continuationParameterName(o.parameter) + ")";
  o.to = t.requiredDouble("to", endRange(o.parameter), unit_note) * si;
  const Range width = Range::openClosed(0.0, endRange(o.parameter).hi - endRange(o.parameter).lo);
  o.step = t.optionalDouble("step", defaultStep(o.parameter), width) * si;
  o.max_points = t.optionalInt(orni::field("continuation.max_points"), o.max_points);
  o.locate_events = t.optionalBool("locate_events", o.locate_events);
  t.finish();
  return o;
}

void writeContinuationSection(const orni::TrimContinuationOptions& o, TomlWriter& out) {
  out.header({"continuation"});
  out.string("parameter", continuationParameterName(o.parameter));
  out.scaled("to", o.to, siPerFile(o.parameter));
  out.scaled("step", o.step, siPerFile(o.parameter));
  out.integer("max_points", o.max_points);
  out.boolean("locate_events", o.locate_events);
}

std::optional<double> continuationStart(const orni::TrimContinuationOptions& o,
                                        const orni::TrimOptions& trim) {
  auto solved = [&](orni::TrimUnknown u) {
    return std::find(trim.unknowns.begin(), trim.unknowns.end(), u) != trim.unknowns.end();
  };
  switch (o.parameter) {
    case PeriodicControl::kFrequency:
      if (solved(orni::TrimUnknown::kFreq)) return std::nullopt;
      return trim.initial.freq_hz;
    case PeriodicControl::kTailAngle:
      if (solved(orni::TrimUnknown::kTailAngle)) return std::nullopt;
      return trim.initial.tail_angle_rad;
    case PeriodicControl::kCgPosition: return 0.0;
  }
  return std::nullopt;
}

void checkContinuationEnd(const TableReader& section, const orni::TrimContinuationOptions& o,
                          const orni::TrimOptions& trim) {
  const std::optional<double> start = continuationStart(o, trim);
  if (!start || o.to != *start) return;
  const double per_file = siPerFile(o.parameter);
  const std::string where = o.parameter == PeriodicControl::kCgPosition
                                ? std::string("CG shift 0")
                                : std::string("the [trim] ") +
                                      continuationParameterName(o.parameter) + " " +
                                      displayNumber(*start / per_file);
  throw section.valueError("to", "a value other than the branch's start (" + where +
                                     "): a branch needs a range to follow",
                           displayNumber(o.to / per_file));
}

}  // namespace orni::studies
