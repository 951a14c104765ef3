#include "core/analysis/linear_trend.hpp"

namespace orni {

double leastSquaresSlope(const std::vector<double>& y) {
  const std::size_t n = y.size();
  if (n < 2) return 0.0;
  const double xm = 0.5 * static_cast<double>(n - 1);
  double ym = 0.0;
  for (const double v : y) ym += v;
  ym /= static_cast<double>(n);
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = static_cast<double>(i) - xm;
    sxy += dx * (y[i] - ym);
    sxx += dx * dx;
  }
  return sxy / sxx;
}

void LinearTrend::fold(double y) {
  // Welford's update with x = the value's index (count_ already counts it).
  const double n = static_cast<double>(count_);
  const double x = n - 1.0;
  const double dx = x - mean_x_;
  mean_x_ += dx / n;
  mean_y_ += (y - mean_y_) / n;
  c_xy_ += dx * (y - mean_y_);
  m2_x_ += dx * (x - mean_x_);
}

void LinearTrend::add(double y) {
  ++count_;
  if (!folded_ && count_ <= kExactValues) {
    kept_.push_back(y);
    return;
  }
  if (!folded_) {  // the first value past the exact range: fold the kept ones in order
    folded_ = true;
    const std::size_t total = count_;
    count_ = 0;
    for (const double v : kept_) {
      ++count_;
      fold(v);
    }
    std::vector<double>().swap(kept_);
    count_ = total;
  }
  fold(y);
}

double LinearTrend::slope() const {
  if (count_ < 2) return 0.0;
  if (folded_) return c_xy_ / m2_x_;
  return leastSquaresSlope(kept_);
}

}  // namespace orni
