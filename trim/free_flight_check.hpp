// Free-flight verification of a trim point: the hook for the bounded-norm check of paper Eq. (5)
// (architecture.md 2: deviations of [U W theta Q h] scaled by their bounds R_i stay <= 1 over the
// horizon, no secular drift).
//
// Free flight (paper Eq. 1-2) is not built yet (issue 4). Until it is, verifyFreeFlight() reports
// status kNotAvailable and leaves the measures unset (NaN); solveTrim() calls it on a converged
// trim, so the free-flight issue only has to fill in this function.
#pragma once

#include <limits>
#include <string>

#include "core/model/vehicle_model.hpp"

namespace orni {

struct FlightCoreModel;

enum class FreeFlightStatus {
  kNotAvailable,  ///< free-flight mode not implemented in this version
  kSkipped,       ///< not run (trim not converged, or not requested)
  kBounded,       ///< Eq. (5) holds: the scaled deviation norm stays <= 1
  kUnbounded,     ///< Eq. (5) violated or secular drift
  kFailed,        ///< the free-flight run failed
};
/// "not_available", "skipped", "bounded", "unbounded", "failed".
const char* toString(FreeFlightStatus s);

/// Options of the free-flight check (defaults per architecture.md 2).
struct FreeFlightCheckOptions {
  int cycles = 60;                    ///< flapping cycles to fly, [1, 100000]
  double bound_theta_rad = 0.6981317;  ///< R_theta = 40 deg (paper section 3.2), > 0
};

/// Result: the keys of a free-mode `simulate` summary (architecture.md 4).
struct FreeFlightVerification {
  FreeFlightStatus status = FreeFlightStatus::kNotAvailable;
  std::string message;
  bool bounded = false;
  double norm_ratio_max = std::numeric_limits<double>::quiet_NaN();
  double theta_min_rad = std::numeric_limits<double>::quiet_NaN();
  double theta_max_rad = std::numeric_limits<double>::quiet_NaN();
  double altitude_p2p_m = std::numeric_limits<double>::quiet_NaN();
  double dominant_freq_hz = std::numeric_limits<double>::quiet_NaN();
};

/// Fly the vehicle freely from the trim point `trim` and check paper Eq. (5). Not yet available:
/// returns kNotAvailable with a message.
FreeFlightVerification verifyFreeFlight(const FlightCoreModel& model, const OperatingPoint& trim,
                                        const FreeFlightCheckOptions& options);

}  // namespace orni
