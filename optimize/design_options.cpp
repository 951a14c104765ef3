#include "optimize/design_options.hpp"

#include <cmath>

namespace orni::opt {

bool DesignProblemOptions::usesFreeFlight() const {
  return objective != DesignObjective::kPower || constraints.bounded ||
         constraints.pitch_amplitude_max_rad > 0.0;
}

const char* toString(DesignObjective o) {
  switch (o) {
    case DesignObjective::kPower: return "power";
    case DesignObjective::kPitchAmplitude: return "pitch_amplitude";
    case DesignObjective::kWeighted: return "weighted";
  }
  return "power";
}

const char* objectiveUnit(DesignObjective o) {
  switch (o) {
    case DesignObjective::kPower: return "W";
    case DesignObjective::kPitchAmplitude: return "deg";
    case DesignObjective::kWeighted: return "-";
  }
  return "-";
}

bool DesignProblemOptions::IsValid(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  std::string w;
  if (!trim.IsValid(&w)) return fail("trim options: " + w);
  if (!(weights.power_per_W >= 0.0 && weights.pitch_amplitude_per_deg >= 0.0 &&
        std::isfinite(weights.power_per_W) && std::isfinite(weights.pitch_amplitude_per_deg)))
    return fail("objective weights must be finite and >= 0");
  if (objective == DesignObjective::kWeighted &&
      weights.power_per_W + weights.pitch_amplitude_per_deg <= 0.0)
    return fail("the weighted objective needs a positive weight");
  for (double limit : {constraints.pitch_amplitude_max_rad, constraints.tip_deflection_max_m,
                       constraints.structural_mass_max_kg, constraints.floquet_max_modulus})
    if (!(limit >= 0.0 && std::isfinite(limit)))
      return fail("constraint limits must be finite and >= 0 (0 = off)");
  if (constraints.floquet_max_modulus > 0.0 &&
      !(trim.method == TrimMethod::kPeriodic && trim.periodic.floquet))
    return fail("the floquet_max_modulus constraint needs the periodic trim (trim method "
                "\"periodic\") with its Floquet analysis on (trim.periodic.floquet)");
  if (usesFreeFlight() && !trim.verify_free_flight)
    return fail("the objective or constraints use the free flight, but the trim's free-flight "
                "check is off");
  return true;
}

}  // namespace orni::opt
