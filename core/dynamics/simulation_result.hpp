// The results of a run of the flapping vehicle: cycle means, sampled histories, the observer that
// streams them, the status and the tethered run's summary. Result types only (no driver), so that
// the code that records, writes or judges a run need not include the drivers that make it.
#pragma once

#include <string>
#include <vector>

#include "core/dynamics/load_sample.hpp"
#include "core/dynamics/simulation_options.hpp"

namespace orni {

struct CycleMeans {
  double FV_N = 0, FH_N = 0, M_Nm = 0, power_aero_W = 0, power_hinge_W = 0;
};

/// The last cycles of the sampled time histories (uniform, SimulationOptions::samples_per_cycle
/// per cycle, sample i at t = i T / samples_per_cycle): the last `keep_cycles` whole cycles and
/// the sample that ends them (the run's last sample; fewer cycles when the run is shorter, and the
/// samples of an unfinished cycle after them when the run stopped inside one). Bounded whatever
/// the cycle count: the whole run streams to a TetheredRunObserver (history_window.hpp).
struct TimeHistory {
  int keep_cycles = 1;  ///< in: whole cycles to keep, >= 1
  std::vector<double> t_s;
  std::vector<double> delta_M_rad;
  std::vector<LoadSample> loads;
};

/// Receives a tethered run's outputs as they are made, so that a caller can write them out
/// without keeping the run in memory (the runner's histories.csv and cycles.csv). Called from the
/// simulating thread, outside the right-hand side; an exception thrown here ends the run and
/// propagates out of simulateTethered.
class TetheredRunObserver {
 public:
  virtual ~TetheredRunObserver() = default;
  /// Every sample, in time order: with SimulationOptions::record_history only.
  virtual void onSample(double t_s, double delta_M_rad, const LoadSample& loads) = 0;
  /// The means of every completed cycle (`cycle` 1-based, in order).
  virtual void onCycle(int cycle, const CycleMeans& means) = 0;
};

enum class SimulationStatus { kOk, kNotConverged, kDiverged, kFailed };
const char* toString(SimulationStatus s);

struct SimulationSummary {
  SimulationStatus status = SimulationStatus::kFailed;
  std::string message;
  int cycles_run = 0;
  int steady_state_cycle = -1;   ///< first cycle whose means match the previous one (1-based)
  double last_cycle_change = 0;  ///< scaled change of the last cycle means vs the one before
  double last_state_change = 0;  ///< max change of the aero states over the last cycle
  CycleMeans mean;               ///< means over the last simulated cycle (the means of every
                                 ///< cycle go to TetheredRunObserver::onCycle)
  /// State at the end of the last cycle (flap phase 0): flexible wing [q, q', aero states],
  /// rigid wing [aero states] (quadratures dropped). Free flight starts from it.
  std::vector<double> final_wing_state;
  int final_mode_count = 0;      ///< modes in final_wing_state
  long steps = 0;
  long rhs_evaluations = 0;
  long step_attempts = 0;
  std::string integrator_method;  ///< e.g. "ARKODE ERKStep Dormand-Prince 5(4)"

  std::string BriefReport() const;
};

}  // namespace orni
