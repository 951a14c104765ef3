// Options of a settled free flight (free_flight_trim.hpp); light header for the study files.
#pragma once

namespace orni {

struct SettledFlightOptions {
  int cycles = 120;            ///< flapping cycles flown at least, [6, 100000]
  int window_cycles = 40;      ///< the last cycles averaged, [1, cycles - 1]
  /// Settled when the window's means of theta and of the climb angle are within this (rad), and
  /// its mean airspeed within this fraction, of the values the flight settles to: predicted from
  /// the decay of its slowest motion (free_flight_trim.hpp), or, where no slow motion is left to
  /// fit, the cycle means over the window all within this band. 0.005 deg: half the climb-angle
  /// tolerance of the free-flight trim (FreeFlightTrimOptions, 0.01 deg), so that the settled
  /// climb angle it iterates on is good to that tolerance.
  double settled_tol_rad = 8.7e-5;
  /// A flight not settled after `cycles` goes on, cycle by cycle, until it is, up to this many
  /// cycles in all (at least `cycles`): the slowest motion, the phugoid, may need several times
  /// `cycles` (the committed magpie: Floquet multiplier 0.985 a cycle, e-folding in 66 cycles).
  int max_cycles = 1200;
  /// Stop as soon as the values the flight settles to are known, not when it has flown there:
  /// when the slowest motion fitted over the flight's second half and over its last third
  /// (both clean and decaying) predict the same settled theta, airspeed and climb angle within
  /// settled_tol_rad, those predictions are the settled means (SettledFlight::extrapolated).
  /// Two fits over stretches of different transient amplitude agree only where the motion left
  /// is the linear decay the fit assumes. false: fly until the window's means are there.
  bool extrapolate = true;
};

}  // namespace orni
