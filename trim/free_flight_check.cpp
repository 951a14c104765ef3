#include "trim/free_flight_check.hpp"

#include "core/dynamics/flight_core.hpp"

namespace orni {

const char* toString(FreeFlightStatus s) {
  switch (s) {
    case FreeFlightStatus::kNotAvailable: return "not_available";
    case FreeFlightStatus::kSkipped: return "skipped";
    case FreeFlightStatus::kBounded: return "bounded";
    case FreeFlightStatus::kUnbounded: return "unbounded";
    case FreeFlightStatus::kFailed: return "failed";
  }
  return "failed";
}

FreeFlightVerification verifyFreeFlight(const FlightCoreModel& /*model*/,
                                        const OperatingPoint& /*trim*/,
                                        const FreeFlightCheckOptions& /*options*/) {
  // Issue 4 (free flight) replaces this body: fly Eq. (1)-(2) from the trim point for
  // options.cycles cycles and evaluate the bounded-norm criterion of Eq. (5).
  FreeFlightVerification v;
  v.status = FreeFlightStatus::kNotAvailable;
  v.message = "free-flight mode not yet implemented (issue 4); the trim is verified in tethered "
              "mode only";
  return v;
}

}  // namespace orni
