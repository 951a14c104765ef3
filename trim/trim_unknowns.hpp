// The quantities a trim solves for (paper Eq. 4 and Table 3: theta_MEAN, U, delta_T, f), their
// names, solver units and bounds. Light header (model types only) for the option structs and the
// study-file reader.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "core/model/vehicle_model.hpp"

namespace orni {

/// The quantities a trim can solve for (paper: theta_MEAN, U, delta_T, f).
enum class TrimUnknown { kThetaMean = 0, kSpeed = 1, kTailAngle = 2, kFreq = 3 };
constexpr int kTrimUnknownCount = 4;
constexpr int kTrimResidualCount = 3;

/// Every unknown, in enum order.
constexpr std::array<TrimUnknown, kTrimUnknownCount> kAllTrimUnknowns = {
    TrimUnknown::kThetaMean, TrimUnknown::kSpeed, TrimUnknown::kTailAngle, TrimUnknown::kFreq};

inline int trimIndex(TrimUnknown u) { return static_cast<int>(u); }

/// File and summary name: "theta_mean_deg", "speed_mps", "tail_angle_deg", "freq_hz".
const char* trimUnknownName(TrimUnknown u);
/// Short command-line name: "theta", "speed", "tail", "freq".
const char* trimUnknownShortName(TrimUnknown u);
/// Solver (and file) unit: "deg", "m/s", "deg", "Hz".
const char* trimUnknownUnit(TrimUnknown u);
/// SI value of one solver unit: kDegToRad for the angles, 1 for speed and frequency.
double trimUnknownScale(TrimUnknown u);
/// The unknown of that file name or short name, or nullopt.
std::optional<TrimUnknown> parseTrimUnknown(std::string_view name);

/// An unknown of an operating point, in SI (rad, m/s, Hz).
double unknownValue(const OperatingPoint& point, TrimUnknown u);
void setUnknownValue(OperatingPoint* point, TrimUnknown u, double value_si);

/// "THETA 9.2000 deg, SPEED 10.8000 m/s, tail 11.8500 deg, f 12.0000 Hz" with the names the report
/// gives theta and the speed ("theta" and "U" for Eq. 4's point, "theta_mean" and "airspeed" for
/// an orbit's): the operating point of the solvers' one-line reports.
std::string pointText(const OperatingPoint& p, const char* theta_name = "theta",
                      const char* speed_name = "U");

/// Closed interval of an unknown, SI.
struct TrimBounds {
  double lower = 0.0;
  double upper = 0.0;
};

}  // namespace orni
