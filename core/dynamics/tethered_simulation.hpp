// Tethered (wind-tunnel / constrained-flight) simulation: the body is held at (theta, U), the
// wings flap, and the constraint forces FV, FH and the moment about P1 are recorded, aerodynamic
// plus inertial, as the paper's load cells measure them (paper section 2, Fig. 2; Fig. 9).
//
// Integrates the aerodynamic states (MST-TD lag and separation states) and five quadrature states
// (the time integrals of FV, FH, M, aero power, hinge power) with ARKODE, cycle by cycle, and
// detects the periodic steady state from the cycle-to-cycle change of the cycle means: the first
// cycle from which on every channel's mean moves by less than steady_tol of its scale.
#pragma once

#include <string>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/simulation_options.hpp"
#include "core/dynamics/simulation_result.hpp"

namespace orni {

/// Run the tethered simulation at `point` (speed, frequency, theta, tail angle). `history` may be
/// null (aero maps, trim); when given (and options.record_history) it receives the sampled
/// histories of the last history->keep_cycles cycles. `observer` may be null; when given it
/// receives every sample (with options.record_history) and every cycle's means as they are made.
/// Memory does not depend on options.cycles. Throws std::invalid_argument for invalid options or
/// history->keep_cycles < 1.
SimulationSummary simulateTethered(const FlightCoreModel& model, const OperatingPoint& point,
                                   const SimulationOptions& options, TimeHistory* history,
                                   TetheredRunObserver* observer = nullptr);

}  // namespace orni
