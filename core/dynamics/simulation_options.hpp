// Options of one periodic-flight simulation (style.md habit 5: plain struct, defaults, IsValid).
#pragma once

#include <string>

namespace orni {

enum class FlightMode { kTethered, kFree };

struct SimulationOptions {
  FlightMode mode = FlightMode::kTethered;
  int cycles = 10;               ///< flapping cycles to simulate, [1, 100000]
  double rel_tol = 1e-4;         ///< SUNDIALS relative tolerance, (0, 1e-2]; cycle means move
                                 ///< < 0.1 % when tightened tenfold (tests/unit/dynamics)
  double abs_tol = 1e-6;         ///< absolute tolerance on the circulation-lag states (rad),
                                 ///< (0, 1e-2]
  double separation_abs_tol = 1e-5;  ///< absolute tolerance on the separation fractions f in
                                     ///< [0, 1], (0, 1e-2]; the suction force goes with sqrt(f),
                                     ///< so f near 0 needs this to keep FH converged
  double steady_tol = 1e-3;      ///< periodic steady state: cycle-to-cycle change of the cycle
                                 ///< means relative to q S (forces), q S c (moment), q S U (power),
                                 ///< and of the aero states (rad), (0, 0.1]
  int samples_per_cycle = 100;   ///< time-history output resolution, [8, 100000]
  bool record_history = true;    ///< keep the sampled time histories (off for maps and trim)
  bool stop_when_steady = false; ///< end the run at the first cycle that meets steady_tol
                                 ///< (aero maps, trim); `cycles` is then the maximum

  /// True when every field is inside its range; otherwise false with the reason in *why.
  bool IsValid(std::string* why) const {
    auto fail = [why](const char* m) {
      if (why) *why = m;
      return false;
    };
    if (cycles < 1 || cycles > 100000) return fail("cycles must be in [1, 100000]");
    if (!(rel_tol > 0 && rel_tol <= 1e-2)) return fail("rel_tol must be in (0, 1e-2]");
    if (!(abs_tol > 0 && abs_tol <= 1e-2)) return fail("abs_tol must be in (0, 1e-2]");
    if (!(separation_abs_tol > 0 && separation_abs_tol <= 1e-2))
      return fail("separation_abs_tol must be in (0, 1e-2]");
    if (!(steady_tol > 0 && steady_tol <= 0.1)) return fail("steady_tol must be in (0, 0.1]");
    if (samples_per_cycle < 8 || samples_per_cycle > 100000)
      return fail("samples_per_cycle must be in [8, 100000]");
    return true;
  }
};

}  // namespace orni
