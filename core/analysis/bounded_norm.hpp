// Bounded-norm trim criterion (paper Eq. 5) on a free flight: x = [U W theta Q h] deviations from
// their trimmed (reference) values, each divided by its bound R_i; the verdict is bounded when the
// 2-norm stays <= 1 over the window after the transient and no secular drift is found (the linear
// trend of the cycle means of a scaled deviation, extrapolated over the window length, exceeds
// `drift_limit`). BoundedNormMonitor judges sample by sample in bounded memory (a run of any
// length); boundedNorm judges stored histories with it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/analysis/linear_trend.hpp"

namespace orni {

struct BoundedNormResult {
  bool bounded = false;
  double norm_ratio_max = 0;    ///< max over the window of ||x_scaled||_2
  double time_of_max_s = 0;
  std::string worst_state;      ///< the state with the largest scaled deviation at that time
  bool drift = false;
  std::string drift_state;
  double drift_per_window = 0;  ///< scaled trend change over the window of the worst drift
  std::string reason;           ///< one line: why bounded or not
};

/// Default drift limit (scaled trend change over the window).
constexpr double kDefaultDriftLimit = 0.5;

/// One judged state: its trimmed value, its bound R_i (> 0) and its name.
struct StateBound {
  double reference;
  double bound;
  const char* name;
};

class BoundedNormMonitor {
 public:
  /// Judges the samples from index `first` (a cycle boundary; samples_per_cycle per cycle) on.
  BoundedNormMonitor(std::vector<StateBound> states, std::size_t first, int samples_per_cycle,
                     double drift_limit = kDefaultDriftLimit);
  /// Sample `index` (consecutive, from 0 or from `first`) at time t_s; values[j] is the value of
  /// state j. Samples before `first` are ignored.
  void add(std::size_t index, double t_s, const double* values);
  /// The verdict over the samples added from `first` on; the drift over the whole cycles among
  /// them (a cycle counts once the sample that ends it was added). Throws std::invalid_argument
  /// when no sample from `first` on was added.
  BoundedNormResult result() const;

 private:
  std::vector<StateBound> states_;
  std::size_t first_, spc_;
  double drift_limit_;
  bool any_ = false;
  double norm_max_ = 0.0;
  double time_of_max_s_ = 0.0;
  std::vector<double> worst_values_;  // the states at the time of the maximum
  std::vector<double> cycle_sums_;    // scaled deviations summed over the current cycle
  std::vector<LinearTrend> cycle_means_;
};

/// Stored histories: states[j].values holds state j, sample i at t_s[i]; the window is samples
/// [first, t_s.size()).
struct StateSeries {
  const std::vector<double>* values;  ///< samples
  double reference;                   ///< trimmed value
  double bound;                       ///< R_i
  const char* name;
};

BoundedNormResult boundedNorm(const std::vector<double>& t_s,
                              const std::vector<StateSeries>& states, std::size_t first,
                              int samples_per_cycle, double drift_limit = kDefaultDriftLimit);

}  // namespace orni
