// The analysis keys of [simulate] and [trim] and their getters (analysis_fields.hpp).
#include "studies/runner/config/analysis_fields.hpp"

#include <cmath>
#include <cstddef>

#include "trim/trim_unknowns.hpp"

namespace orni::studies {

namespace {

bool always(const Study&) { return true; }
bool tethered(const Study& s) { return s.simulate().options.mode == FlightMode::kTethered; }
bool freeFlight(const Study& s) { return s.simulate().options.mode == FlightMode::kFree; }
bool twoStage(const Study& s) { return s.trim.method != TrimMethod::kPeriodic; }
bool periodic(const Study& s) { return s.trim.method == TrimMethod::kPeriodic; }

/// A trim unknown's initial value and bounds (SI), by unknown.
template <TrimUnknown U>
AnalysisValue initialValue(const Study& s) {
  return unknownValue(s.trim.initial, U);
}
template <TrimUnknown U>
AnalysisValue boundsValue(const Study& s) {
  const TrimBounds& b = s.trim.bounds[static_cast<std::size_t>(trimIndex(U))];
  return std::vector<double>{b.lower, b.upper};
}

const std::vector<AnalysisField> kSimulateFields = {
    {"simulate.mode",
     [](const Study& s) -> AnalysisValue {
       return std::string(s.simulate().options.mode == FlightMode::kFree ? "free" : "tethered");
     },
     always},
    {"simulate.speed_mps", [](const Study& s) -> AnalysisValue { return s.point.speed_mps; },
     always},
    {"simulate.freq_hz", [](const Study& s) -> AnalysisValue { return s.point.freq_hz; }, always},
    {"simulate.theta_deg", [](const Study& s) -> AnalysisValue { return s.point.theta_rad; },
     always},
    {"simulate.tail_angle_deg",
     [](const Study& s) -> AnalysisValue { return s.point.tail_angle_rad; }, always},
    {"simulate.cycles",
     [](const Study& s) -> AnalysisValue {
       return static_cast<long long>(s.simulate().options.cycles);
     },
     always},
    {"simulate.rel_tol",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.rel_tol; }, always},
    {"simulate.abs_tol",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.abs_tol; }, always},
    {"simulate.separation_abs_tol",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.separation_abs_tol; },
     always},
    {"simulate.steady_tol",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.steady_tol; }, always},
    {"simulate.samples_per_cycle",
     [](const Study& s) -> AnalysisValue {
       return static_cast<long long>(s.simulate().options.samples_per_cycle);
     },
     always},
    {"simulate.sampled_loads",
     [](const Study& s) -> AnalysisValue {
       return std::string(s.simulate().options.interpolate_sampled_loads ? "interpolated"
                                                                         : "evaluated");
     },
     tethered},
    {"simulate.history_every",
     [](const Study& s) -> AnalysisValue {
       return static_cast<long long>(s.simulate().history_every);
     },
     always},
    {"simulate.wing_only", [](const Study& s) -> AnalysisValue { return s.simulate().wing_only; },
     tethered},
    {"simulate.at_trim", [](const Study& s) -> AnalysisValue { return s.simulate().at_trim; },
     always},
    {"simulate.free.bound_speed_mps",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.free.bounds.U_mps; },
     freeFlight},
    {"simulate.free.bound_W_mps",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.free.bounds.W_mps; },
     freeFlight},
    {"simulate.free.bound_theta_deg",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.free.bounds.theta_rad; },
     freeFlight},
    {"simulate.free.bound_Q_degps",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.free.bounds.Q_radps; },
     freeFlight},
    {"simulate.free.bound_h_m",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.free.bounds.h_m; },
     freeFlight},
    {"simulate.free.transient_fraction",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.free.transient_fraction; },
     freeFlight},
    {"simulate.free.divergence_ratio",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.free.divergence_ratio; },
     freeFlight},
    {"simulate.free.initial_altitude_m",
     [](const Study& s) -> AnalysisValue { return s.simulate().options.free.initial_altitude_m; },
     freeFlight},
};

const std::vector<AnalysisField> kTrimFields = {
    {"trim.freq_hz", [](const Study& s) -> AnalysisValue { return s.trim.initial.freq_hz; },
     always},
    {"trim.unknowns",
     [](const Study& s) -> AnalysisValue {
       std::vector<std::string> names;
       for (const TrimUnknown u : s.trim.unknowns) names.emplace_back(trimUnknownName(u));
       return names;
     },
     always},
    {"trim.max_iterations",
     [](const Study& s) -> AnalysisValue { return static_cast<long long>(s.trim.max_iterations); },
     always},
    {"trim.residual_tol", [](const Study& s) -> AnalysisValue { return s.trim.residual_tol; },
     always},
    {"trim.function_tol", [](const Study& s) -> AnalysisValue { return s.trim.function_tol; },
     always},
    {"trim.rel_tol", [](const Study& s) -> AnalysisValue { return s.trim.simulation.rel_tol; },
     always},
    {"trim.steady_tol",
     [](const Study& s) -> AnalysisValue { return s.trim.simulation.steady_tol; }, always},
    {"trim.max_cycles",
     [](const Study& s) -> AnalysisValue {
       return static_cast<long long>(s.trim.simulation.cycles);
     },
     always},
    {"trim.derivative_cycles",
     [](const Study& s) -> AnalysisValue {
       return static_cast<long long>(s.trim.derivative_cycles);
     },
     always},
    {"trim.method",
     [](const Study& s) -> AnalysisValue { return std::string(toString(s.trim.method)); }, always},
    {"trim.refine_in_free_flight",
     [](const Study& s) -> AnalysisValue { return s.trim.refine_in_free_flight; }, twoStage},
    {"trim.refine_cycles",
     [](const Study& s) -> AnalysisValue { return static_cast<long long>(s.trim.refine_cycles); },
     twoStage},
    {"trim.initial.theta_mean_deg", initialValue<TrimUnknown::kThetaMean>, always},
    {"trim.initial.speed_mps", initialValue<TrimUnknown::kSpeed>, always},
    {"trim.initial.tail_angle_deg", initialValue<TrimUnknown::kTailAngle>, always},
    {"trim.periodic.control",
     [](const Study& s) -> AnalysisValue { return std::string(toString(s.trim.periodic.control)); },
     periodic},
    {"trim.periodic.residual_tol",
     [](const Study& s) -> AnalysisValue { return s.trim.periodic.residual_tol; }, periodic},
    {"trim.periodic.rel_tol",
     [](const Study& s) -> AnalysisValue { return s.trim.periodic.rel_tol; }, periodic},
    {"trim.periodic.max_iterations",
     [](const Study& s) -> AnalysisValue {
       return static_cast<long long>(s.trim.periodic.max_iterations);
     },
     periodic},
    {"trim.periodic.history_samples",
     [](const Study& s) -> AnalysisValue {
       return static_cast<long long>(s.trim.periodic.history_samples);
     },
     periodic},
    {"trim.periodic.floquet",
     [](const Study& s) -> AnalysisValue { return s.trim.periodic.floquet; }, periodic},
    {"trim.periodic.multipliers",
     [](const Study& s) -> AnalysisValue {
       return static_cast<long long>(s.trim.periodic.multipliers);
     },
     periodic},
    {"trim.periodic.multiplier_check",
     [](const Study& s) -> AnalysisValue { return s.trim.periodic.multiplier_check; }, periodic},
    {"trim.bounds.theta_mean_deg", boundsValue<TrimUnknown::kThetaMean>, always},
    {"trim.bounds.speed_mps", boundsValue<TrimUnknown::kSpeed>, always},
    {"trim.bounds.tail_angle_deg", boundsValue<TrimUnknown::kTailAngle>, always},
    {"trim.bounds.freq_hz", boundsValue<TrimUnknown::kFreq>, always},
};

bool sameNumber(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }

}  // namespace

const std::vector<AnalysisField>& analysisFields(StudyKind run) {
  static const std::vector<AnalysisField> kNone;
  if (run == StudyKind::kSimulate) return kSimulateFields;
  if (run == StudyKind::kTrim) return kTrimFields;
  return kNone;
}

bool sameAnalysisValue(const AnalysisValue& a, const AnalysisValue& b) {
  if (a.index() != b.index()) return false;
  if (const auto* x = std::get_if<double>(&a)) return sameNumber(*x, std::get<double>(b));
  if (const auto* x = std::get_if<std::vector<double>>(&a)) {
    const auto& y = std::get<std::vector<double>>(b);
    if (x->size() != y.size()) return false;
    for (std::size_t i = 0; i < x->size(); ++i)
      if (!sameNumber((*x)[i], y[i])) return false;
    return true;
  }
  return a == b;
}

}  // namespace orni::studies
