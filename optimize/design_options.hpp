// Options of the design problem (design_problem.hpp): objective, constraints, the trim of every
// evaluation. Light header (no dynamics) so that the study files can hold them.
#pragma once

#include <string>

#include "core/model/vehicle_model.hpp"
#include "trim/trim_options.hpp"

namespace orni::opt {

enum class DesignObjective { kPower, kPitchAmplitude, kWeighted };
/// "power", "pitch_amplitude", "weighted".
const char* toString(DesignObjective o);
/// Unit of the objective value: "W", "deg", "-".
const char* objectiveUnit(DesignObjective o);

/// Weights of the weighted objective (per unit of each term), >= 0, not both 0.
struct DesignObjectiveWeights {
  double power_per_W = 1.0;
  double pitch_amplitude_per_deg = 0.0;
};

/// Optional constraints besides "trimmed" (always on). 0 = off for the limits.
struct DesignConstraints {
  bool bounded = true;                  ///< free flight bounded (paper Eq. 5)
  double pitch_amplitude_max_rad = 0.0; ///< >= 0
  double tip_deflection_max_m = 0.0;    ///< >= 0, flexible wing only
  double structural_mass_max_kg = 0.0;  ///< >= 0, both wings
  /// Largest Floquet multiplier modulus of the trimmed periodic orbit, >= 0 (0 = off); needs the
  /// periodic trim (trim.method = kPeriodic) with its Floquet analysis on.
  double floquet_max_modulus = 0.0;
};

struct DesignProblemOptions {
  /// The trim of every evaluation: frequency, unknowns, bounds, tolerances and the free-flight
  /// check (TrimOptions::verify_free_flight must be on when a free-flight quantity is used).
  /// method kTwoStage (Eq. (4), then the tail angle of settled free flight) or kPeriodic (the
  /// periodic orbit of free flight and its Floquet multipliers, trim/periodic_trim.hpp).
  TrimOptions trim;
  DesignObjective objective = DesignObjective::kPower;
  DesignObjectiveWeights weights;
  DesignConstraints constraints;
  /// Start each trim from the last converged trim of the same start (else from trim.initial).
  bool warm_start = true;

  /// The objective or a constraint needs the bounded-norm free flight (paper Eq. 5) at the trim.
  bool usesFreeFlight() const;
  bool IsValid(std::string* why) const;
};

}  // namespace orni::opt
