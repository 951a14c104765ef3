#include "core/model/wing_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "core/model/frames.hpp"

namespace orni {

double chordAt(const WingModel& wing, double y_W_m) {
  if (wing.planform == Planform::kRectangular) return wing.root_chord_m;
  const double eta = std::clamp(y_W_m / wing.semispan_m, 0.0, 1.0);
  return wing.root_chord_m * std::sqrt(1.0 - eta * eta);
}

namespace {
// Integral of sqrt(1 - u^2) du from 0 to u.
double ellipseIntegral(double u) {
  u = std::clamp(u, -1.0, 1.0);
  return 0.5 * (u * std::sqrt(1.0 - u * u) + std::asin(u));
}
}  // namespace

double areaBetween(const WingModel& wing, double y0_m, double y1_m) {
  if (wing.planform == Planform::kRectangular) return wing.root_chord_m * (y1_m - y0_m);
  const double s = wing.semispan_m;
  return wing.root_chord_m * s * (ellipseIntegral(y1_m / s) - ellipseIntegral(y0_m / s));
}

double halfWingArea(const WingModel& wing) { return areaBetween(wing, 0.0, wing.semispan_m); }

double aerodynamicAspectRatio(const VehicleModel& vehicle) {
  if (vehicle.aero.aspect_ratio > 0.0) return vehicle.aero.aspect_ratio;
  const double span_m = 2.0 * vehicle.wing.semispan_m;
  return span_m * span_m / (2.0 * halfWingArea(vehicle.wing));
}

std::vector<Strip> makeStrips(const WingModel& wing) {
  std::vector<Strip> strips(static_cast<std::size_t>(wing.strip_count));
  const double dy = wing.semispan_m / wing.strip_count;
  for (int j = 0; j < wing.strip_count; ++j) {
    Strip& s = strips[static_cast<std::size_t>(j)];
    s.y_inner_m = j * dy;
    s.y_outer_m = (j + 1) * dy;
    s.y_center_m = (j + 0.5) * dy;
    s.width_m = dy;
    s.chord_m = areaBetween(wing, s.y_inner_m, s.y_outer_m) / dy;
  }
  return strips;
}

}  // namespace orni
