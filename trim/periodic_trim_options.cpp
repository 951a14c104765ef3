#include "trim/periodic_trim_options.hpp"

namespace orni {

const char* toString(TrimMethod m) { return m == TrimMethod::kPeriodic ? "periodic" : "two_stage"; }

std::optional<TrimMethod> parseTrimMethod(std::string_view text) {
  if (text == "two_stage") return TrimMethod::kTwoStage;
  if (text == "periodic") return TrimMethod::kPeriodic;
  return std::nullopt;
}

const char* toString(PeriodicControl c) {
  switch (c) {
    case PeriodicControl::kTailAngle: return "tail_angle_deg";
    case PeriodicControl::kFrequency: return "freq_hz";
    case PeriodicControl::kCgPosition: return "cg_shift_m";
  }
  return "tail_angle_deg";
}

std::optional<PeriodicControl> parsePeriodicControl(std::string_view text) {
  if (text == "tail_angle_deg" || text == "tail") return PeriodicControl::kTailAngle;
  if (text == "freq_hz" || text == "freq") return PeriodicControl::kFrequency;
  if (text == "cg_shift_m" || text == "cg") return PeriodicControl::kCgPosition;
  return std::nullopt;
}

}  // namespace orni
