#include "core/dynamics/zero_moment_point.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/dynamics/flapping.hpp"

namespace orni {

namespace {

ChannelStats channelStats(const std::vector<ZmpSample>& samples, double LoadCoefficients::*field) {
  ChannelStats st;
  st.min = st.max = samples.front().coefficients.*field;
  double sum = 0.0;
  for (const ZmpSample& s : samples) {
    const double v = s.coefficients.*field;
    sum += v;
    st.min = std::min(st.min, v);
    st.max = std::max(st.max, v);
  }
  st.mean = sum / static_cast<double>(samples.size());
  st.amplitude = 0.5 * (st.max - st.min);
  return st;
}

/// epsilon metrics over the samples for which `take` is true.
template <class Take>
EpsilonMetrics epsilonMetrics(const std::vector<ZmpSample>& samples, double threshold,
                              Take take) {
  EpsilonMetrics m;
  double sum_cm = 0.0, sum_d = 0.0;               // all samples: mean loads
  double sum_abs_d = 0.0, sum_cm_sign_d = 0.0;    // defined samples: weighted mean
  for (const ZmpSample& s : samples) {
    if (!take(s)) continue;
    ++m.samples;
    sum_cm += s.coefficients.CM_CG;
    sum_d += s.denominator;
    if (!s.epsilon) continue;
    ++m.defined_samples;
    sum_abs_d += std::abs(s.denominator);
    sum_cm_sign_d += s.denominator > 0.0 ? s.coefficients.CM_CG : -s.coefficients.CM_CG;
    m.min = m.min ? std::min(*m.min, *s.epsilon) : *s.epsilon;
    m.max = m.max ? std::max(*m.max, *s.epsilon) : *s.epsilon;
  }
  if (m.defined_samples > 0 && sum_abs_d > 0.0) m.weighted_mean = -sum_cm_sign_d / sum_abs_d;
  if (m.samples > 0) {
    const double mean_d = sum_d / m.samples;
    if (std::abs(mean_d) >= threshold && mean_d != 0.0)
      m.of_mean_loads = -(sum_cm / m.samples) / mean_d;
  }
  return m;
}

}  // namespace

CoefficientReference coefficientReference(const FlightCoreModel& model,
                                          const OperatingPoint& point) {
  CoefficientReference r;
  r.dynamic_pressure_Pa =
      0.5 * model.vehicle.air.density_kgpm3 * point.speed_mps * point.speed_mps;
  r.wing_area_m2 = model.wing_area_both_m2;
  r.mean_chord_m = model.mean_chord_m;
  r.theta_mean_rad = point.theta_rad;
  return r;
}

LoadCoefficients loadCoefficients(const LoadSample& s, const CoefficientReference& ref) {
  const double force = ref.dynamic_pressure_Pa * ref.wing_area_m2;
  LoadCoefficients c;
  c.CF_V = s.FV_N / force;
  c.CF_H = s.FH_N / force;
  c.CM_CG = s.M_Nm / (force * ref.mean_chord_m);
  return c;
}

double zmpDenominator(const LoadCoefficients& c, double theta_rad) {
  return c.CF_V * std::cos(theta_rad) - c.CF_H * std::sin(theta_rad);
}

std::optional<double> zmpEpsilon(const LoadCoefficients& c, double theta_rad,
                                 double min_abs_denominator) {
  const double d = zmpDenominator(c, theta_rad);
  if (d == 0.0 || std::abs(d) < min_abs_denominator || !std::isfinite(d) ||
      !std::isfinite(c.CM_CG))
    return std::nullopt;
  return -c.CM_CG / d;
}

const char* toString(Stroke s) { return s == Stroke::kDown ? "down" : "up"; }

Stroke strokeOf(double delta_rad, double delta_dot_radps, double reversal_tol_radps) {
  if (delta_dot_radps < -reversal_tol_radps) return Stroke::kDown;
  if (delta_dot_radps > reversal_tol_radps) return Stroke::kUp;
  return delta_rad > 0.0 ? Stroke::kDown : Stroke::kUp;
}

ConstrainedFlightTest analyseConstrainedFlightTest(const std::vector<double>& t_s,
                                                   const std::vector<double>& delta_rad,
                                                   const std::vector<double>& delta_dot_radps,
                                                   const std::vector<LoadSample>& loads,
                                                   const CoefficientReference& reference,
                                                   const ZmpOptions& options) {
  const std::size_t n = t_s.size();
  if (n == 0 || delta_rad.size() != n || delta_dot_radps.size() != n || loads.size() != n)
    throw std::invalid_argument(
        "constrained flight test: t, delta, delta_dot and loads need the same length >= 1");
  if (!(reference.dynamic_pressure_Pa > 0.0 && reference.wing_area_m2 > 0.0 &&
        reference.mean_chord_m > 0.0))
    throw std::invalid_argument(
        "constrained flight test: dynamic pressure, wing area and mean chord must be > 0");
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("constrained flight test: " + why);

  ConstrainedFlightTest r;
  r.reference = reference;
  r.options = options;
  r.samples.resize(n);
  double max_rate = 0.0;
  for (const double d : delta_dot_radps) max_rate = std::max(max_rate, std::abs(d));
  const double reversal_tol = 1e-9 * max_rate;
  for (std::size_t i = 0; i < n; ++i) {
    ZmpSample& s = r.samples[i];
    s.t_s = t_s[i];
    s.delta_rad = delta_rad[i];
    s.stroke = strokeOf(delta_rad[i], delta_dot_radps[i], reversal_tol);
    s.coefficients = loadCoefficients(loads[i], reference);
    s.denominator = zmpDenominator(s.coefficients, reference.theta_mean_rad);
    if (std::isfinite(s.denominator))
      r.denominator_max_abs = std::max(r.denominator_max_abs, std::abs(s.denominator));
  }
  r.singular_threshold = options.singular_fraction * r.denominator_max_abs;
  for (ZmpSample& s : r.samples)
    s.epsilon = zmpEpsilon(s.coefficients, reference.theta_mean_rad, r.singular_threshold);

  r.CF_V = channelStats(r.samples, &LoadCoefficients::CF_V);
  r.CF_H = channelStats(r.samples, &LoadCoefficients::CF_H);
  r.CM_CG = channelStats(r.samples, &LoadCoefficients::CM_CG);
  const double th = r.singular_threshold;
  r.cycle = epsilonMetrics(r.samples, th, [](const ZmpSample&) { return true; });
  r.upstroke =
      epsilonMetrics(r.samples, th, [](const ZmpSample& s) { return s.stroke == Stroke::kUp; });
  r.downstroke =
      epsilonMetrics(r.samples, th, [](const ZmpSample& s) { return s.stroke == Stroke::kDown; });
  return r;
}

std::optional<ConstrainedFlightTest> lastCycleConstrainedFlightTest(const FlightCoreModel& model,
                                                                    const OperatingPoint& point,
                                                                    const TimeHistory& history,
                                                                    int samples_per_cycle) {
  const std::size_t spc = static_cast<std::size_t>(samples_per_cycle);
  const std::size_t size = history.loads.size();
  if (spc == 0 || size < spc + 1 || (size - 1) % spc != 0) return std::nullopt;
  const std::size_t start = size - 1 - spc;
  std::vector<double> t(history.t_s.begin() + static_cast<std::ptrdiff_t>(start),
                        history.t_s.end() - 1);
  std::vector<double> delta(history.delta_M_rad.begin() + static_cast<std::ptrdiff_t>(start),
                            history.delta_M_rad.end() - 1);
  std::vector<LoadSample> loads(history.loads.begin() + static_cast<std::ptrdiff_t>(start),
                                history.loads.end() - 1);
  std::vector<double> delta_dot;
  delta_dot.reserve(t.size());
  for (const double ti : t)
    delta_dot.push_back(
        flapStateAt(model.vehicle.flapping.amplitude_rad, point.freq_hz, ti).delta_dot_radps);
  return analyseConstrainedFlightTest(t, delta, delta_dot, loads,
                                      coefficientReference(model, point));
}

}  // namespace orni
