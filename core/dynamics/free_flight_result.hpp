// The results of a free flight: the body state, one sample of the right-hand side, the kept
// histories, the observer that streams every sample, and the summary with its bounded-norm
// verdict (paper Eq. 5). Result types only (no driver), so that the recorder and the code that
// writes or judges a flight need not include the driver (free_flight.hpp) that makes it.
#pragma once

#include <string>
#include <vector>

#include "core/analysis/bounded_norm.hpp"
#include "core/analysis/limit_cycle.hpp"
#include "core/dynamics/load_sample.hpp"
#include "core/dynamics/simulation_result.hpp"

namespace orni {

/// Longitudinal body state (B components; h altitude up).
struct BodyState {
  double x_I_m = 0, h_m = 0, theta_rad = 0, U_mps = 0, W_mps = 0, Q_radps = 0;
};

/// Everything the free-flight RHS computes at one instant (for histories and tests).
struct FreeFlightSample {
  double Udot_mps2 = 0, Wdot_mps2 = 0, Qdot_radps2 = 0;
  LoadSample loads;   ///< aerodynamic loads of wings (incl. apparent mass) and tail about P1 in
                      ///< the flight-path frame; the inertial fields hold the wings' inertial
                      ///< reaction on the fuselage
  double kinetic_energy_J = 0;    ///< fuselage + both wings (rigid part + modal)
  double potential_energy_J = 0;  ///< gravity (m g h of the whole vehicle, wing CG offsets
                                  ///< included) + strain energy of both wings
};

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

}  // namespace orni
