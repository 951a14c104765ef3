#include "trim/trim_unknowns.hpp"

#include <cstdio>

#include "core/model/frames.hpp"

namespace orni {

namespace {

struct UnknownInfo {
  TrimUnknown id;
  const char* name;
  const char* short_name;
  const char* unit;
  double scale;
};

const std::array<UnknownInfo, kTrimUnknownCount> kInfo = {{
    {TrimUnknown::kThetaMean, "theta_mean_deg", "theta", "deg", kDegToRad},
    {TrimUnknown::kSpeed, "speed_mps", "speed", "m/s", 1.0},
    {TrimUnknown::kTailAngle, "tail_angle_deg", "tail", "deg", kDegToRad},
    {TrimUnknown::kFreq, "freq_hz", "freq", "Hz", 1.0},
}};

const UnknownInfo& info(TrimUnknown u) { return kInfo[static_cast<std::size_t>(trimIndex(u))]; }

}  // namespace

const char* trimUnknownName(TrimUnknown u) { return info(u).name; }
const char* trimUnknownShortName(TrimUnknown u) { return info(u).short_name; }
const char* trimUnknownUnit(TrimUnknown u) { return info(u).unit; }
double trimUnknownScale(TrimUnknown u) { return info(u).scale; }

std::optional<TrimUnknown> parseTrimUnknown(std::string_view name) {
  for (const UnknownInfo& i : kInfo)
    if (name == i.name || name == i.short_name) return i.id;
  return std::nullopt;
}

double unknownValue(const OperatingPoint& point, TrimUnknown u) {
  switch (u) {
    case TrimUnknown::kThetaMean: return point.theta_rad;
    case TrimUnknown::kSpeed: return point.speed_mps;
    case TrimUnknown::kTailAngle: return point.tail_angle_rad;
    case TrimUnknown::kFreq: return point.freq_hz;
  }
  return 0.0;
}

void setUnknownValue(OperatingPoint* point, TrimUnknown u, double value_si) {
  switch (u) {
    case TrimUnknown::kThetaMean: point->theta_rad = value_si; break;
    case TrimUnknown::kSpeed: point->speed_mps = value_si; break;
    case TrimUnknown::kTailAngle: point->tail_angle_rad = value_si; break;
    case TrimUnknown::kFreq: point->freq_hz = value_si; break;
  }
}

std::string pointText(const OperatingPoint& p, const char* theta_name, const char* speed_name) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "%s %.4f deg, %s %.4f m/s, tail %.4f deg, f %.4f Hz", theta_name,
                p.theta_rad * kRadToDeg, speed_name, p.speed_mps, p.tail_angle_rad * kRadToDeg,
                p.freq_hz);
  return buf;
}

}  // namespace orni
