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
#include "core/dynamics/free_flight_system.hpp"
#include "core/dynamics/simulation_options.hpp"
#include "core/dynamics/tethered_simulation.hpp"

namespace orni {

struct FreeFlightHistory {
  std::vector<double> t_s, delta_M_rad;
  std::vector<BodyState> body;
  std::vector<FreeFlightSample> samples;
};

struct FreeFlightSummary {
  SimulationStatus status = SimulationStatus::kFailed;  ///< ok, diverged, or failed (the
                                                        ///< periodic start failed: no result)
  std::string message;
  int cycles_run = 0;          ///< whole cycles completed
  double end_time_s = 0.0;
  BodyState initial;           ///< the trimmed (reference) state
  BoundedNormResult verdict;   ///< bounded-norm criterion over the window after the transient
  LimitCycleMetrics limit_cycle;
  int first_analysed_cycle = 0;  ///< 1-based
  CycleMeans mean;             ///< last cycle: aerodynamic FV, FH, M (wings + tail; with
                               ///< record_history) and aerodynamic power
  long steps = 0, rhs_evaluations = 0;
  std::string integrator_method;  ///< e.g. "ARKODE ARKStep ARK4(3)7L[2]SA IMEX, ..."
  bool analysed = false;       ///< verdict and limit_cycle are filled (status ok)
};

/// Initial state of a free flight at the operating point: level flight path at speed U with the
/// body pitched by theta (U_B = U cos theta, W_B = U sin theta), Q = 0, at the initial altitude.
BodyState trimmedBodyState(const OperatingPoint& point, double altitude_m);

/// Run `options.cycles` flapping cycles of free flight. `history` may be null. With
/// options.record_history false the loads are not sampled (history->samples stays empty and the
/// mean loads are zero): the body states, verdict and limit cycle are unaffected.
FreeFlightSummary simulateFree(const FlightCoreModel& model, const OperatingPoint& point,
                               const SimulationOptions& options, FreeFlightHistory* history);

}  // namespace orni
