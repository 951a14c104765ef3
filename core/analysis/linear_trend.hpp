// Least-squares slope of a sequence against its index, fed one value at a time (the secular-drift
// test of the bounded-norm criterion, bounded_norm.hpp, on one mean per flapping cycle).
#pragma once

#include <cstddef>
#include <vector>

namespace orni {

/// Least-squares slope of y against its index (two-pass: mean first, then the centred sums); 0 for
/// fewer than two values.
double leastSquaresSlope(const std::vector<double>& y);

class LinearTrend {
 public:
  /// Values kept for the exact two-pass slope: up to this many the slope is the two-pass formula
  /// bit for bit; beyond it the values are folded into running sums (Welford's co-moment update,
  /// the same slope to rounding), so that memory stays bounded for any sequence length.
  static constexpr std::size_t kExactValues = 4096;

  void add(double y);
  std::size_t count() const { return count_; }
  /// Slope per index step; 0 for fewer than two values.
  double slope() const;

 private:
  void fold(double y);
  std::vector<double> kept_;  // while count_ <= kExactValues
  std::size_t count_ = 0;
  bool folded_ = false;
  double mean_x_ = 0.0, mean_y_ = 0.0, c_xy_ = 0.0, m2_x_ = 0.0;
};

}  // namespace orni
