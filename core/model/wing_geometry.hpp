// Planform geometry of the right wing and its aerodynamic strips (docs/theory.md 2.1).
#pragma once

#include <vector>

#include "core/model/vehicle_model.hpp"

namespace orni {

/// Local chord c(y) at span station y in [0, s] (W frame), metres.
double chordAt(const WingModel& wing, double y_W_m);

/// Planform area of ONE wing, m^2 (exact: c0 s, or pi s c0 / 4).
double halfWingArea(const WingModel& wing);

/// Area of one wing between stations y0 < y1, m^2 (exact).
double areaBetween(const WingModel& wing, double y0_m, double y1_m);

/// Aspect ratio of the wing pair used by the aerodynamics: the file's value when given (> 0),
/// else b^2/S = (2 s)^2 / (2 A_half).
double aerodynamicAspectRatio(const VehicleModel& vehicle);

/// One aerodynamic strip of the right wing.
struct Strip {
  double y_center_m = 0.0;  ///< mid-station, W frame
  double y_inner_m = 0.0;
  double y_outer_m = 0.0;
  double width_m = 0.0;     ///< dy
  double chord_m = 0.0;     ///< area-preserving mean chord of the strip, A_strip / dy
};

/// Equal-width strips over [0, s]; chords are strip-mean chords, so the strip areas sum to the
/// planform area exactly and no strip centre sits on a zero-chord tip (docs/theory.md 2.1).
std::vector<Strip> makeStrips(const WingModel& wing);

}  // namespace orni
