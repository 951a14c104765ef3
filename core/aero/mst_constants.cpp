// Finite-wing constants, Scherer's modified Theodorsen function and the friction coefficient of
// DeLaurier's MST (docs/theory.md 5.2 (M3, M11) and 5.6).
#include <cmath>

#include "core/aero/mst_strip.hpp"

namespace orni::aero {

MstConstants MstConstants::fromAspectRatio(double aspect_ratio) {
  MstConstants constants;
  constants.aspect_ratio = aspect_ratio;
  if (std::isinf(aspect_ratio)) {
    // 2-D limit of M3: C1 -> 0.5, C2 -> 0.181, AR/(2+AR) -> 1 (docs/theory.md 5.10, O2).
    constants.C1 = 0.5;
    constants.C2 = 0.181;
    constants.jones_factor = 1.0;
    return constants;
  }
  constants.C1 = 0.5 * aspect_ratio / (2.32 + aspect_ratio);     // M3
  constants.C2 = 0.181 + 0.772 / aspect_ratio;                    // M3
  constants.jones_factor = aspect_ratio / (2.0 + aspect_ratio);   // R.T. Jones, docs/theory.md 5.2
  return constants;
}

SchererFunction schererFunction(const MstConstants& constants, double reduced_frequency) {
  // M3: F' = 1 - C1 k^2/(k^2 + C2^2), G'/k = -C1 C2/(k^2 + C2^2) (finite at k = 0, pitfall 4).
  const double k = reduced_frequency;
  const double inv_denominator = 1.0 / (k * k + constants.C2 * constants.C2);
  SchererFunction result;
  result.F = 1.0 - constants.C1 * k * k * inv_denominator;
  result.G_over_k = -constants.C1 * constants.C2 * inv_denominator;
  result.G = result.G_over_k * k;
  return result;
}

double frictionCoefficient(double reynolds_number) {
  // M11: Cd_f = 0.89/(log10 Re)^2.58, Re clamped to >= 1e3 (pitfall 11). One log10 and one pow.
  constexpr double kMinReynolds = 1.0e3;
  const double re = reynolds_number > kMinReynolds ? reynolds_number : kMinReynolds;
  return 0.89 * std::pow(std::log10(re), -2.58);
}

}  // namespace orni::aero
