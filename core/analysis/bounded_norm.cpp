#include "core/analysis/bounded_norm.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace orni {

BoundedNormMonitor::BoundedNormMonitor(std::vector<StateBound> states, std::size_t first,
                                       int samples_per_cycle, double drift_limit)
    : states_(std::move(states)),
      first_(first),
      spc_(static_cast<std::size_t>(samples_per_cycle)),
      drift_limit_(drift_limit),
      worst_values_(states_.size(), 0.0),
      cycle_sums_(states_.size(), 0.0),
      cycle_means_(states_.size()) {
  if (samples_per_cycle < 1)
    throw std::invalid_argument("bounded-norm check: samples_per_cycle < 1");
}

void BoundedNormMonitor::add(std::size_t index, double t_s, const double* values) {
  if (index < first_) return;
  const std::size_t m = states_.size();
  // A sample at a cycle boundary ends the cycle before it: its mean joins the trend.
  if (index > first_ && (index - first_) % spc_ == 0) {
    for (std::size_t j = 0; j < m; ++j) {
      cycle_means_[j].add(cycle_sums_[j] / static_cast<double>(spc_));
      cycle_sums_[j] = 0.0;
    }
  }
  double sq = 0.0;
  for (std::size_t j = 0; j < m; ++j) {
    const double d = (values[j] - states_[j].reference) / states_[j].bound;
    sq += d * d;
    cycle_sums_[j] += d;
  }
  const double norm = std::sqrt(sq);
  if (!any_ || norm > norm_max_) {
    if (norm > norm_max_) norm_max_ = norm;
    time_of_max_s_ = t_s;
    for (std::size_t j = 0; j < m; ++j) worst_values_[j] = values[j];
  }
  any_ = true;
}

BoundedNormResult BoundedNormMonitor::result() const {
  if (!any_) throw std::invalid_argument("bounded-norm check: empty window");
  BoundedNormResult r;
  r.norm_ratio_max = norm_max_;
  r.time_of_max_s = time_of_max_s_;
  double worst = -1.0;
  for (std::size_t j = 0; j < states_.size(); ++j) {
    const double d = std::abs((worst_values_[j] - states_[j].reference) / states_[j].bound);
    if (d > worst) {
      worst = d;
      r.worst_state = states_[j].name;
    }
  }
  // Secular drift: trend of the per-cycle means of each scaled deviation.
  const std::size_t cycles = cycle_means_.empty() ? 0 : cycle_means_.front().count();
  if (cycles >= 3) {
    for (std::size_t j = 0; j < states_.size(); ++j) {
      const double change =
          std::abs(cycle_means_[j].slope()) * static_cast<double>(cycles);
      if (change > r.drift_per_window) {
        r.drift_per_window = change;
        r.drift_state = states_[j].name;
      }
    }
    r.drift = r.drift_per_window > drift_limit_;
  }
  r.bounded = r.norm_ratio_max <= 1.0 && !r.drift;
  char buf[256];
  if (r.norm_ratio_max > 1.0)
    std::snprintf(buf, sizeof buf,
                  "not bounded: scaled state norm %.3g > 1 at t = %.3f s (largest: %s)",
                  r.norm_ratio_max, r.time_of_max_s, r.worst_state.c_str());
  else if (r.drift)
    std::snprintf(buf, sizeof buf,
                  "not bounded: secular drift of %s (%.3g of its bound over the window > %.3g)",
                  r.drift_state.c_str(), r.drift_per_window, drift_limit_);
  else
    std::snprintf(buf, sizeof buf,
                  "bounded: scaled state norm <= %.3g (largest %s at t = %.3f s), drift %.3g of "
                  "a bound (%s)",
                  r.norm_ratio_max, r.worst_state.c_str(), r.time_of_max_s, r.drift_per_window,
                  r.drift_state.c_str());
  r.reason = buf;
  return r;
}

BoundedNormResult boundedNorm(const std::vector<double>& t_s,
                              const std::vector<StateSeries>& states, std::size_t first,
                              int samples_per_cycle, double drift_limit) {
  const std::size_t n = t_s.size();
  if (first >= n) throw std::invalid_argument("bounded-norm check: empty window");
  std::vector<StateBound> bounds;
  for (const StateSeries& s : states) bounds.push_back({s.reference, s.bound, s.name});
  BoundedNormMonitor monitor(std::move(bounds), first, samples_per_cycle, drift_limit);
  std::vector<double> values(states.size());
  for (std::size_t i = first; i < n; ++i) {
    for (std::size_t j = 0; j < states.size(); ++j) values[j] = (*states[j].values)[i];
    monitor.add(i, t_s[i], values.data());
  }
  return monitor.result();
}

}  // namespace orni
