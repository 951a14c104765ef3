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

/// The last cycles of a free flight's sampled histories (uniform, samples_per_cycle per cycle):
/// the last `keep_cycles` whole cycles and the samples after them (as TimeHistory,
/// tethered_simulation.hpp); `samples` stays empty without SimulationOptions::record_history.
/// Bounded whatever the cycle count: the whole run streams to a FreeFlightObserver.
struct FreeFlightHistory {
  int keep_cycles = 1;  ///< in: whole cycles to keep, >= 1
  std::vector<double> t_s, delta_M_rad;
  std::vector<BodyState> body;
  std::vector<FreeFlightSample> samples;
};

/// Receives every sample of a free flight as it is made (the runner's histories.csv), in time
/// order, from the simulating thread; an exception thrown here ends the run and propagates out of
/// simulateFree.
class FreeFlightObserver {
 public:
  virtual ~FreeFlightObserver() = default;
  /// `sample` (the loads) is null without SimulationOptions::record_history.
  virtual void onSample(double t_s, double delta_M_rad, const BodyState& body,
                        const FreeFlightSample* sample) = 0;
  /// Asked after each whole cycle `cycle` (1-based, its last sample already passed to onSample)
  /// but the last: true ends the run there (status ok, cycles_run = cycle, not analysed: the
  /// verdict's windows belong to the whole run). For a caller that flies until its own criterion
  /// holds (a settled free flight, trim/free_flight_trim.hpp). Default: never.
  virtual bool endRunAfterCycle(int cycle) {
    (void)cycle;
    return false;
  }
};

struct FreeFlightSummary {
  SimulationStatus status = SimulationStatus::kFailed;  ///< ok, diverged, or failed (the
                                                        ///< periodic start failed: no result)
  std::string message;
  int cycles_run = 0;          ///< whole cycles completed
  double end_time_s = 0.0;
  BodyState initial;           ///< the trimmed (reference) state
  BoundedNormResult verdict;   ///< bounded-norm criterion over the window after the transient
  LimitCycleMetrics limit_cycle;  ///< theta extremes over the window after the transient, the
                                  ///< rest over the limit-cycle window (limit_cycle.hpp)
  int first_analysed_cycle = 0;  ///< 1-based
  int limit_cycle_first_cycle = 0;  ///< 1-based first cycle of the limit-cycle window
                                    ///< (first_analysed_cycle unless the run is long)
  CycleMeans mean;             ///< last cycle: aerodynamic FV, FH, M (wings + tail; with
                               ///< record_history) and aerodynamic power
  long steps = 0, rhs_evaluations = 0;
  std::string integrator_method;  ///< e.g. "ARKODE ARKStep ARK4(3)7L[2]SA IMEX, ..."
  bool analysed = false;       ///< verdict and limit_cycle are filled (status ok, every cycle
                               ///< flown: not when the observer ended the run early)
};

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
