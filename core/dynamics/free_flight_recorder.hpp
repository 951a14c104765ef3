// What a free flight (free_flight.hpp) keeps of its samples while it runs: the caller's last cycles
// (history_window.hpp; at least the last one, for the mean loads), the limit-cycle window (the last
// cycles after the transient, limit_cycle.hpp), the bounded-norm monitor and the theta extremes
// over the cycles after the transient. The windows are known in advance from the options: the
// analysis runs only on a flight that completed every cycle. Every sample also goes to the
// run's observer. Memory does not depend on the cycle count.
#pragma once

#include <cstddef>
#include <vector>

#include "core/analysis/bounded_norm.hpp"
#include "core/analysis/limit_cycle.hpp"
#include "core/dynamics/free_flight_result.hpp"
#include "core/dynamics/free_flight_system.hpp"
#include "core/dynamics/simulation_options.hpp"

namespace orni {

/// Where a run of options.cycles cycles (samples_per_cycle each, sample 0 at t = 0) is judged.
struct FreeFlightWindows {
  int transient_cycles = 0;        ///< cycles skipped before the verdict (< options.cycles)
  int limit_cycle_cycles = 1;      ///< whole cycles of the limit-cycle window, >= 1
  std::size_t first = 0;           ///< first sample after the transient
  std::size_t limit_cycle_first = 0;  ///< first sample of the limit-cycle window
  std::size_t analysed_end = 0;    ///< one past the last sample of the last cycle
};

/// The windows of a run with these (valid) options: the transient is
/// floor(transient_fraction * cycles) cycles, at most cycles - 1.
FreeFlightWindows freeFlightWindows(const SimulationOptions& options);

/// Empties `history` but for its keep_cycles (the caller's request).
void clearFreeFlightHistory(FreeFlightHistory* history);

class FreeFlightRecorder {
 public:
  /// A recorder of the run of `sys` (which samples the loads with options.record_history) at
  /// flapping frequency `freq_hz` released in `initial` (the bounded-norm reference), with the
  /// pitch-rate bound `Q_bound_radps`. `history` (may be null: a window of the last cycle of its
  /// own) is cleared, keeping its keep_cycles (>= 1), and reserved for its bounded window.
  /// `observer` may be null. `sys` and `observer` must outlive the recorder.
  FreeFlightRecorder(FreeFlightSystem& sys, double freq_hz, const SimulationOptions& options,
                     const BodyState& initial, double Q_bound_radps, FreeFlightHistory* history,
                     FreeFlightObserver* observer);
  FreeFlightRecorder(const FreeFlightRecorder&) = delete;
  FreeFlightRecorder& operator=(const FreeFlightRecorder&) = delete;

  /// The next sample of the run: state y (FreeFlightSystem's layout) at t_s; `ydot` (may be null)
  /// its derivative from the integrator's dense output, used for the loads of a nonlinear wing
  /// when options.interpolate_sampled_loads (FreeFlightSystem::sample).
  void record(double t_s, const double* y, const double* ydot = nullptr);
  /// Drops the history's samples before its last keep_cycles whole cycles; `amortised`: only
  /// once it holds twice that (oldSamplesToDrop, history_window.hpp).
  void dropOld(bool amortised);

  const FreeFlightWindows& windows() const { return windows_; }
  /// The history window (the caller's or the recorder's own).
  const FreeFlightHistory& history() const { return h_; }
  /// Run index of the history's first sample.
  std::size_t historyFirst() const { return h_first_; }
  double lastTime_s() const { return last_t_s_; }
  /// The bounded-norm verdict over the samples after the transient (BoundedNormMonitor::result).
  BoundedNormResult verdict() const { return monitor_.result(); }
  /// The limit-cycle metrics over its window, theta extremes over the samples after the
  /// transient. Valid once every cycle is recorded.
  LimitCycleMetrics limitCycle() const;

 private:
  FreeFlightSystem& sys_;
  FreeFlightObserver* observer_;
  double flap_amplitude_rad_, freq_hz_;
  bool loads_;  // sample the loads (one more RHS evaluation per sample)
  bool interpolate_;  // u' of the nonlinear wing's samples from the dense output's derivative
  int spc_;
  FreeFlightWindows windows_;
  FreeFlightHistory local_;
  FreeFlightHistory& h_;
  std::size_t h_first_ = 0;  // index of h_'s first sample in the run
  std::vector<double> win_t_, win_delta_, win_theta_, win_h_;  // the limit-cycle window
  BoundedNormMonitor monitor_;
  double theta_min_ = 0.0, theta_max_ = 0.0;  // over [first, analysed_end)
  std::size_t index_ = 0;                     // of the next sample in the run
  double last_t_s_ = 0.0;
};

}  // namespace orni
