// Options of the periodic-orbit trim (periodic_trim.hpp); light header for TrimOptions and the
// study files.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "core/model/field_table.hpp"

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

/// The multiplier check's grid: the period map's rel_tol times this (PeriodicTrimOptions::
/// multiplier_check). Measured on the magpie against a 100 times finer reference
/// (tests/unit/trim/test_periodic_trim.cpp): every multiplier the check resolved is within 10 % of
/// |mu| of it, and 82 of the 89 it did not resolve are off by more than 5 %.
constexpr double kMultiplierCheckTolFactor = 0.1;

struct PeriodicTrimOptions {
  PeriodicControl control = PeriodicControl::kTailAngle;
  /// Converged when every state returns to its start within this many of its scales (and the
  /// altitude gain within this many 0.1 m), (0, 1e-4].
  double residual_tol = 1e-8;
  /// Step control of the integration grid of the period map, (0, 1e-3]. 1e-5 (50 steps per period
  /// on the flexible magpie at 12 Hz): its orbit's cycle means move by 0.0003 deg and 0.0005 m/s,
  /// the tail angle by 0.0003 deg and the leading multiplier by < 1e-6 against 1e-6 (82 steps).
  /// The strongly damped wing modes' multipliers (|mu| ~0.08) it resolves to 0.01 in modulus only,
  /// not in argument (docs/theory.md 10.4).
  double rel_tol = 1e-5;
  int max_iterations = 40;      ///< Newton iterations, [1, 1000]
  int history_samples = 200;    ///< samples of the orbit's histories (one period), [8, 100000]
  bool floquet = true;          ///< the monodromy at the orbit and its multipliers
  /// Leading multipliers found by Arnoldi (core/analysis/monodromy.hpp), [1, 100]; 0 = all of
  /// them from the full monodromy matrix (one period map per state: 107 on the flexible magpie
  /// against about 20 for the leading 8).
  int multipliers = 8;
  /// Check every multiplier against a second full monodromy on a grid kMultiplierCheckTolFactor
  /// times finer (one period map per state): its change there, and whether it is resolved
  /// (core/analysis/floquet.hpp). `stability` turns it on: the strongly damped wing
  /// modes' multipliers are not resolved at the default grid (docs/theory.md 10.4).
  bool multiplier_check = false;

  /// True when every field is inside the range of its [trim.periodic] key in the field table
  /// (core/model/field_table.hpp); otherwise false with the reason in *why.
  bool IsValid(std::string* why) const {
    const std::pair<const char*, double> keyed[] = {
        {"trim.periodic.residual_tol", residual_tol},
        {"trim.periodic.rel_tol", rel_tol},
        {"trim.periodic.max_iterations", max_iterations},
        {"trim.periodic.history_samples", history_samples},
        {"trim.periodic.multipliers", multipliers}};
    for (const auto& [key, value] : keyed)
      if (!field(key).range.contains(value)) {
        if (why) *why = "periodic " + std::string(key).substr(14) + " must be in " +
                        field(key).range.interval();
        return false;
      }
    return true;
  }
};

}  // namespace orni
