// Free longitudinal flight (paper Eq. 1-2, 5): the vehicle released at a given (theta, U, f, tail
// angle), integrated cycle by cycle with ARKODE, checked for divergence at every sample and judged
// by the bounded-norm criterion after the transient. Divergence (non-finite state, the scaled
// state norm above FreeFlightOptions::divergence_ratio, |theta| >= 85 deg, ground contact) ends
// the run early with status diverged and a reason; nothing is reported as NaN.
#pragma once

#include <string>
#include <vector>

#include "core/analysis/limit_cycle.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/free_flight_result.hpp"
#include "core/dynamics/free_flight_system.hpp"
#include "core/dynamics/simulation_options.hpp"
#include "core/dynamics/tethered_simulation.hpp"

namespace orni {

/// Initial state of a free flight at the operating point: level flight path at speed U with the
/// body pitched by theta (U_B = U cos theta, W_B = U sin theta), Q = 0, at the initial altitude.
BodyState trimmedBodyState(const OperatingPoint& point, double altitude_m);

/// Run `options.cycles` flapping cycles of free flight. `history` may be null; when given it
/// receives the last history->keep_cycles cycles. `observer` may be null; when given it receives
/// every sample. With options.record_history false the loads are not sampled (history->samples
/// stays empty and the mean loads are zero): the body states, verdict and limit cycle are
/// unaffected. The observer may end the run after any whole cycle
/// (FreeFlightObserver::endRunAfterCycle); history then holds the last cycles flown. Memory does
/// not depend on options.cycles. Throws std::invalid_argument for invalid options or
/// history->keep_cycles < 1.
FreeFlightSummary simulateFree(const FlightCoreModel& model, const OperatingPoint& point,
                               const SimulationOptions& options, FreeFlightHistory* history,
                               FreeFlightObserver* observer = nullptr);

}  // namespace orni
