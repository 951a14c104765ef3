#include "core/dynamics/last_cycle_harmonics.hpp"

namespace orni {

std::optional<LastCycleHarmonics> lastCycleHarmonics(const std::vector<LoadSample>& loads,
                                                     std::size_t samples_per_cycle) {
  const std::size_t n = samples_per_cycle;
  if (n < 1 || loads.size() < n + 1) return std::nullopt;
  const std::size_t start = loads.size() - 1 - n;
  // One channel of the cycle, contiguous.
  std::vector<double> x(n);
  auto channel = [&](double LoadSample::*field) -> const double* {
    for (std::size_t i = 0; i < n; ++i) x[i] = loads[start + i].*field;
    return x.data();
  };
  LastCycleHarmonics h;
  h.FV_1f = periodHarmonic(channel(&LoadSample::FV_N), n, 1);
  h.FV_2f = periodHarmonic(x.data(), n, 2);
  h.FV_peak_phase = peakPhase(x.data(), n);
  h.FH_1f = periodHarmonic(channel(&LoadSample::FH_N), n, 1);
  h.FH_2f = periodHarmonic(x.data(), n, 2);
  h.FH_peak_phase = peakPhase(x.data(), n);
  h.M_1f = periodHarmonic(channel(&LoadSample::M_Nm), n, 1);
  h.tip_deflection_amplitude_m = periodHalfRange(channel(&LoadSample::tip_deflection_m), n);
  h.tip_twist_amplitude_rad = periodHalfRange(channel(&LoadSample::tip_twist_rad), n);
  return h;
}

}  // namespace orni
