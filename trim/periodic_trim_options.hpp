// Options of the periodic-orbit trim (periodic_trim.hpp); light header for TrimOptions and the
// study files.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace orni {

/// How a trim is solved: the paper's two stages (Eq. 4 on tethered means, then level settled free
/// flight; trim_solver.hpp) or the periodic orbit of free flight (periodic_trim.hpp).
enum class TrimMethod { kTwoStage, kPeriodic };
/// "two_stage", "periodic".
const char* toString(TrimMethod m);
std::optional<TrimMethod> parseTrimMethod(std::string_view text);

/// The control the periodic trim frees to make the orbit level (the others are held at the
/// Eq. (4) solution).
enum class PeriodicControl { kTailAngle, kFrequency, kCgPosition };
/// "tail_angle_deg", "freq_hz", "cg_shift_m".
const char* toString(PeriodicControl c);
/// From those names or the short ones "tail", "freq", "cg".
std::optional<PeriodicControl> parsePeriodicControl(std::string_view text);

struct PeriodicTrimOptions {
  PeriodicControl control = PeriodicControl::kTailAngle;
  /// Converged when every state returns to its start within this many of its scales (and the
  /// altitude gain within this many 0.1 m), (0, 1e-4].
  double residual_tol = 1e-8;
  /// Step control of the integration grid of the period map, (0, 1e-3]. 1e-5 (50 steps per period
  /// on the flexible magpie at 12 Hz): its orbit's cycle means move by 0.0003 deg and 0.0005 m/s,
  /// the tail angle by 0.0003 deg and the leading multiplier by < 1e-6 against 1e-6 (82 steps).
  double rel_tol = 1e-5;
  int max_iterations = 40;      ///< Newton iterations, [1, 1000]
  int history_samples = 200;    ///< samples of the orbit's histories (one period), [8, 100000]
  bool floquet = true;          ///< the monodromy at the orbit and its multipliers
  /// Leading multipliers found by Arnoldi (core/analysis/monodromy.hpp), [1, 100]; 0 = all of
  /// them from the full monodromy matrix (one period map per state: 107 on the flexible magpie
  /// against about 20 for the leading 8).
  int multipliers = 8;

  bool IsValid(std::string* why) const {
    auto fail = [why](const char* m) {
      if (why) *why = m;
      return false;
    };
    if (!(residual_tol > 0.0 && residual_tol <= 1e-4))
      return fail("periodic residual_tol must be in (0, 1e-4]");
    if (!(rel_tol > 0.0 && rel_tol <= 1e-3)) return fail("periodic rel_tol must be in (0, 1e-3]");
    if (max_iterations < 1 || max_iterations > 1000)
      return fail("periodic max_iterations must be in [1, 1000]");
    if (history_samples < 8 || history_samples > 100000)
      return fail("periodic history_samples must be in [8, 100000]");
    if (multipliers < 0 || multipliers > 100) return fail("periodic multipliers must be in [0, 100]");
    return true;
  }
};

}  // namespace orni
