// Continuation of trimmed flapping flight (docs/theory.md 10.5): the periodic-orbit trim
// (periodic_trim.hpp) followed over one parameter of the free-flight period map (the flapping
// frequency, the tail angle or a forward CG shift) by pseudo-arclength continuation
// (core/analysis/periodic_continuation.hpp), with the Floquet multipliers of every point and the
// folds and stability changes located on the branch.
//
// The branch starts at the periodic trim of `trim` (its control, e.g. the tail angle, is the free
// unknown that keeps the orbit level along the branch) at the parameter's value there (the trim's
// frequency, its tail angle, or CG shift 0) and is followed towards `to`. The skin friction, which
// a periodic trim freezes at its orbit's mean airspeed, is frozen during each step at the previous
// point's mean airspeed (a lag of one step: the map must not change during a solve, and a resumed
// run must see the map an uninterrupted one saw), so a point differs from a periodic trim solved
// there directly by the friction's change over one step (tests/unit/trim/
// test_trim_continuation.cpp measures it).
//
// Per point: the orbit, its cycle means (theta, airspeed, power; 32 uniform samples of the period)
// and all Floquet multipliers (the full monodromy from the point's Jacobian). No I/O;
// thread-compatible.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/analysis/periodic_continuation.hpp"
#include "core/dynamics/flight_core.hpp"
#include "trim/periodic_trim.hpp"
#include "trim/trim_options.hpp"

namespace orni {

/// Options of continueTrim (docs/design.md 7.5). Units of the parameter: Hz, rad, m.
struct TrimContinuationOptions {
  PeriodicControl parameter = PeriodicControl::kFrequency;  ///< must differ from the control
  double to = 14.0;             ///< the end of the branch (parameter units)
  /// First step in the parameter (its units; > 0); the arclength steps adapt from there.
  double step = 0.2;
  int max_points = 30;          ///< regular points after the start, [1, 10000]
  bool locate_events = true;    ///< bisection on folds and stability changes
  double locate_tol = 1e-6;     ///< events located to this in the parameter (its units)
  int samples = 32;             ///< samples of a period for the cycle means, [8, 100000]
  /// Threads for the finite-difference columns of each point's Jacobian
  /// (ShootingOptions::jacobian_threads), [1, 64]; the branch has the same bits for any count.
  int threads = 1;

  bool IsValid(std::string* why) const;
};

/// One point of the trim branch.
struct TrimContinuationPoint {
  ContinuationPoint orbit;      ///< state, parameters, multipliers, event (periodic_continuation)
  OperatingPoint solution;      ///< cycle-mean theta and airspeed, tail angle, frequency
  double cg_shift_m = 0.0;
  PeriodicCycleMeans mean;
  std::string leading_label;    ///< what the leading multiplier's eigenvector is ("phugoid-like")
  double friction_speed_mps = 0.0;  ///< the skin friction's speed while this point was solved
  double grid_friction_speed_mps = 0.0;  ///< ... when its step grid was chosen (resume)
};

struct TrimContinuationSummary {
  ContinuationStatus status = ContinuationStatus::kFailed;
  std::string message;
  PeriodicTrimSummary start;    ///< the periodic trim the branch starts from
  std::vector<TrimContinuationPoint> points;
  double friction_speed_mps = 0.0;
  long period_maps = 0;
  int events = 0;
  double wall_time_s = 0.0;
};

/// Called with each point as it is accepted; false stops the run (status interrupted).
using TrimContinuationCallback = std::function<bool(const TrimContinuationPoint&)>;

/// The parameter's value at an operating point and CG shift (Hz, rad or m).
double continuationParameterValue(PeriodicControl parameter, const OperatingPoint& point,
                                  double cg_shift_m);

/// Follow the trim branch of `model` from the periodic trim of `trim` (its method is taken as
/// periodic, without the Floquet analysis and the free-flight check of the start: every point has
/// its multipliers). `resume` (may be empty): the points of an interrupted run of the same inputs,
/// ending with a regular point; the run continues after the last one and reports only the new
/// points (the start trim is solved again, for the friction speed). Throws std::invalid_argument
/// for invalid options; every numerical outcome is in the summary.
TrimContinuationSummary continueTrim(const FlightCoreModel& model, const TrimOptions& trim,
                                     const TrimContinuationOptions& options,
                                     const TrimContinuationCallback& on_point = {},
                                     const std::vector<TrimContinuationPoint>& resume = {});

}  // namespace orni
