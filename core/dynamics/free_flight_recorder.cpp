#include "core/dynamics/free_flight_recorder.hpp"

#include <algorithm>
#include <cmath>

#include "core/dynamics/flapping.hpp"
#include "core/dynamics/history_window.hpp"

namespace orni {

FreeFlightWindows freeFlightWindows(const SimulationOptions& options) {
  const FreeFlightOptions& fo = options.free;
  const int spc = options.samples_per_cycle;
  const std::size_t spc_n = static_cast<std::size_t>(spc);
  FreeFlightWindows w;
  w.transient_cycles = std::min(
      options.cycles - 1, static_cast<int>(std::floor(fo.transient_fraction * options.cycles)));
  w.first = static_cast<std::size_t>(w.transient_cycles) * spc_n;
  w.limit_cycle_cycles = limitCycleWindowCycles(options.cycles - w.transient_cycles, spc,
                                                fo.limit_cycle_window_samples);
  w.limit_cycle_first = static_cast<std::size_t>(options.cycles - w.limit_cycle_cycles) * spc_n;
  w.analysed_end = static_cast<std::size_t>(options.cycles) * spc_n;
  return w;
}

void clearFreeFlightHistory(FreeFlightHistory* history) {
  const int keep = history->keep_cycles;
  *history = FreeFlightHistory{};
  history->keep_cycles = keep;
}

namespace {

// The bounded-norm monitor of the body states [U W theta Q h] about the release state.
BoundedNormMonitor bodyMonitor(const BodyState& initial, const FreeFlightBounds& bounds,
                               double Q_bound_radps, std::size_t first, int samples_per_cycle) {
  return BoundedNormMonitor({{initial.U_mps, bounds.U_mps, "U"},
                             {initial.W_mps, bounds.W_mps, "W"},
                             {initial.theta_rad, bounds.theta_rad, "theta"},
                             {initial.Q_radps, Q_bound_radps, "Q"},
                             {initial.h_m, bounds.h_m, "h"}},
                            first, samples_per_cycle);
}

}  // namespace

FreeFlightRecorder::FreeFlightRecorder(FreeFlightSystem& sys, double freq_hz,
                                       const SimulationOptions& options, const BodyState& initial,
                                       double Q_bound_radps, FreeFlightHistory* history,
                                       FreeFlightObserver* observer)
    : sys_(sys),
      observer_(observer),
      flap_amplitude_rad_(sys.model().core.vehicle.flapping.amplitude_rad),
      freq_hz_(freq_hz),
      loads_(options.record_history),
      // The nonlinear wing only: there the evaluated accelerations are far off (its stiff
      // membrane force), on the linear wing the interpolant's are about 3x less accurate and no
      // cheaper (docs/theory.md 9.4).
      interpolate_(options.interpolate_sampled_loads && sys.model().flex != nullptr &&
                   sys.model().flex->nonlinear()),
      spc_(options.samples_per_cycle),
      windows_(freeFlightWindows(options)),
      h_(history ? *history : local_),
      monitor_(bodyMonitor(initial, options.free.bounds, Q_bound_radps, windows_.first, spc_)) {
  clearFreeFlightHistory(&h_);
  const std::size_t spc_n = static_cast<std::size_t>(spc_);
  const std::size_t most = 2 * static_cast<std::size_t>(h_.keep_cycles) * spc_n + 1;
  h_.t_s.reserve(most);
  h_.delta_M_rad.reserve(most);
  h_.body.reserve(most);
  if (loads_) h_.samples.reserve(most);
  for (std::vector<double>* v : {&win_t_, &win_delta_, &win_theta_, &win_h_})
    v->reserve(static_cast<std::size_t>(windows_.limit_cycle_cycles) * spc_n + 1);
}

void FreeFlightRecorder::record(double t_s, const double* y, const double* ydot) {
  const double delta = flapStateAt(flap_amplitude_rad_, freq_hz_, t_s).delta_rad;
  const BodyState b{y[0], y[1], y[2], y[3], y[4], y[5]};
  FreeFlightSample s;
  if (loads_) sys_.sample(t_s, y, &s, false, interpolate_ ? ydot : nullptr);
  if (observer_) observer_->onSample(t_s, delta, b, loads_ ? &s : nullptr);
  h_.t_s.push_back(t_s);
  h_.delta_M_rad.push_back(delta);
  h_.body.push_back(b);
  if (loads_) h_.samples.push_back(s);
  const double judged[5] = {b.U_mps, b.W_mps, b.theta_rad, b.Q_radps, b.h_m};
  monitor_.add(index_, t_s, judged);
  if (index_ >= windows_.first && index_ < windows_.analysed_end) {
    if (index_ == windows_.first || b.theta_rad < theta_min_) theta_min_ = b.theta_rad;
    if (index_ == windows_.first || b.theta_rad > theta_max_) theta_max_ = b.theta_rad;
  }
  if (index_ >= windows_.limit_cycle_first) {
    win_t_.push_back(t_s);
    win_delta_.push_back(delta);
    win_theta_.push_back(b.theta_rad);
    win_h_.push_back(b.h_m);
  }
  last_t_s_ = t_s;
  ++index_;
}

void FreeFlightRecorder::dropOld(bool amortised) {
  const std::size_t d =
      oldSamplesToDrop(h_.t_s.size(), static_cast<std::size_t>(spc_),
                       static_cast<std::size_t>(h_.keep_cycles), amortised);
  if (d == 0) return;
  dropFront(&h_.t_s, d);
  dropFront(&h_.delta_M_rad, d);
  dropFront(&h_.body, d);
  if (!h_.samples.empty()) dropFront(&h_.samples, d);
  h_first_ += d;
}

LimitCycleMetrics FreeFlightRecorder::limitCycle() const {
  LimitCycleMetrics m =
      analyseLimitCycle(win_t_, win_delta_, win_theta_, win_h_, 0, spc_, freq_hz_);
  m.theta_min_rad = theta_min_;
  m.theta_max_rad = theta_max_;
  return m;
}

}  // namespace orni
