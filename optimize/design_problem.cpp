#include "optimize/design_problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/tethered_simulation.hpp"
#include "core/model/frames.hpp"
#include "core/model/invalid_model_error.hpp"
#include "core/model/vehicle_validation.hpp"
#include "core/model/wing_inertia.hpp"
#include "trim/periodic_trim.hpp"
#include "core/model/invariant.hpp"

namespace orni::opt {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// g of a satisfied trim constraint, and the least g of a violated one (a clear gap).
constexpr double kTrimmedFeasible = -1.0;
constexpr double kViolatedFloor = 0.01;

/// The free flight went the distance and was judged (norm and drift exist).
bool flown_analysed(const FreeFlightVerification& f) {
  return (f.status == FreeFlightStatus::kBounded || f.status == FreeFlightStatus::kUnbounded) &&
         std::isfinite(f.norm_ratio_max);
}

struct DesignWorkspace : ProblemWorkspace {
  std::optional<OperatingPoint> last_trim;  ///< last converged trim of this start
};

/// The options of one tethered periodic run at a trim point from the trim's run options.
SimulationOptions tetheredRunAtTrim(const SimulationOptions& trim_simulation, bool record_history) {
  SimulationOptions o = trim_simulation;
  o.mode = FlightMode::kTethered;
  o.stop_when_steady = true;
  o.record_history = record_history;
  return o;
}

/// Max |tip deflection| over the last cycle of a tethered periodic run at `point`.
double tipDeflectionAmplitude(const FlightCoreModel& model, const OperatingPoint& point,
                              const SimulationOptions& trim_simulation) {
  const SimulationOptions o = tetheredRunAtTrim(trim_simulation, true);
  TimeHistory h;
  const SimulationSummary s = simulateTethered(model, point, o, &h);
  if (s.status != SimulationStatus::kOk || h.loads.empty()) return kNaN;
  const std::size_t n = h.loads.size();
  const std::size_t first =
      n > static_cast<std::size_t>(o.samples_per_cycle) ? n - 1 - o.samples_per_cycle : 0;
  double m = 0.0;
  for (std::size_t i = first; i < n; ++i) m = std::max(m, std::abs(h.loads[i].tip_deflection_m));
  return m;
}

/// Cycle means of the tethered periodic run at `point` with the two-stage trim's default run
/// tolerances (the periodic trim loosens its own: usePeriodicMethod): the power of a periodic
/// trim's design, defined as the two-stage trim's (its final tethered periodic run). NaN when the
/// run fails.
CycleMeans tetheredMeansAt(const FlightCoreModel& model, const OperatingPoint& point,
                           const SimulationOptions& trim_simulation) {
  SimulationOptions o = tetheredRunAtTrim(trim_simulation, false);
  const SimulationOptions defaults = TrimOptions{}.simulation;
  o.rel_tol = std::min(o.rel_tol, defaults.rel_tol);
  o.steady_tol = std::min(o.steady_tol, defaults.steady_tol);
  const SimulationSummary r = simulateTethered(model, point, o, nullptr);
  if (r.status == SimulationStatus::kOk || r.status == SimulationStatus::kNotConverged)
    return r.mean;
  return CycleMeans{kNaN, kNaN, kNaN, kNaN, kNaN};
}

/// The periodic trim (trim/periodic_trim.hpp) of the design, reported in e->trim as described at
/// DesignEvaluation.
void solvePeriodicDesignTrim(const FlightCoreModel& model, const TrimOptions& t,
                             DesignEvaluation* e) {
  const PeriodicTrimSummary p = solvePeriodicTrim(model, t);
  e->periodic = true;
  TrimSummary& s = e->trim;
  s = p.stage1;  // unknowns, reference, termination, evaluation counts of the Eq. (4) start
  s.status = p.status;
  s.converged = p.converged;
  s.message = p.message;
  s.solution = p.solution;
  s.free_flight = p.free_flight;
  s.evaluations = static_cast<int>(p.shooting.period_maps + p.floquet_maps);
  e->residual_tol = t.residual_tol;
  if (p.stage1.converged) {  // the orbit was sought: its residual says how far from trim
    s.scaled_residual_max = p.shooting.residual_max;
    e->residual_tol = t.periodic.residual_tol;
    e->periodic_residual = p.shooting.residual_max;
  }
  if (p.converged) s.mean = tetheredMeansAt(model, p.solution, t.simulation);
  e->equation4 = p.stage1.solution;
  e->floquet_valid = p.floquet_valid;
  if (p.floquet_valid) e->floquet_max_modulus = p.floquet.max_modulus;
}

}  // namespace

DesignEvaluation evaluateDesign(const VehicleModel& vehicle, const DesignProblemOptions& options,
                                const OperatingPoint& initial_guess, ModalWingCache* modal_wings) {
  DesignEvaluation e;
  try {
    // A design outside the vehicle's rules (core/model/vehicle_validation.hpp) fails here, with
    // the key at fault in the message.
    requireValidVehicle(vehicle);
    e.structural_mass_kg = 2.0 * computeWingInertia(vehicle).total.mass_kg;
    const FlightCoreModel model(vehicle, FlightCoreModel::Checks::kRequired, modal_wings);
    TrimOptions t = options.trim;
    for (TrimUnknown u : t.unknowns) setUnknownValue(&t.initial, u, unknownValue(initial_guess, u));
    if (t.method == TrimMethod::kPeriodic) {
      // The orbit's stability is in its multipliers: the bounded-norm flight only when used.
      if (!options.usesFreeFlight()) t.verify_free_flight = false;
      solvePeriodicDesignTrim(model, t, &e);
    } else {
      e.trim = solveTrim(model, t);
      e.residual_tol = t.residual_tol;
    }
    e.trim_attempted = true;
    const TrimSummary& s = e.trim;
    if (!s.converged) {
      e.message = "trim not converged: " + s.message;
      return e;
    }
    const FreeFlightVerification& f = s.free_flight;
    if (f.status == FreeFlightStatus::kBounded || f.status == FreeFlightStatus::kUnbounded) {
      if (std::isfinite(f.theta_max_rad) && std::isfinite(f.theta_min_rad))
        e.pitch_amplitude_rad = 0.5 * (f.theta_max_rad - f.theta_min_rad);
    }
    if (options.constraints.tip_deflection_max_m > 0.0 && model.flexible)
      e.tip_deflection_m = tipDeflectionAmplitude(model, s.solution, options.trim.simulation);
    switch (f.status) {
      case FreeFlightStatus::kBounded: e.message = "trimmed; free flight bounded"; break;
      case FreeFlightStatus::kUnbounded:
        e.message = "trimmed; free flight unbounded: " + f.message;
        break;
      case FreeFlightStatus::kFailed: e.message = "trimmed; free flight failed: " + f.message; break;
      default: e.message = "trimmed; free flight not checked"; break;
    }
    if (e.periodic) {
      char buf[160];
      if (e.floquet_valid)
        std::snprintf(buf, sizeof buf, "periodic orbit, Floquet max |mu| %.6g (%s)",
                      e.floquet_max_modulus, e.floquet_max_modulus < 1.0 ? "stable" : "unstable");
      else
        std::snprintf(buf, sizeof buf, "periodic orbit, no Floquet analysis");
      e.message.replace(0, 7, std::string("trimmed (") + buf + ")");
    }
  } catch (const std::exception& ex) {
    rethrowIfProgrammingError(ex);  // core/model/invariant.hpp
    e.trim_attempted = false;
    e.message = std::string("design not evaluated: ") + ex.what();
  }
  return e;
}

DesignProblem::DesignProblem(VehicleModel base, DesignSpace space, DesignProblemOptions options)
    : base_(std::move(base)), space_(std::move(space)), options_(std::move(options)) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("design problem: " + why);
  if (space_.variables.empty()) throw std::invalid_argument("design problem: no variables");
  for (const DesignVariable& v : space_.variables) {
    if (v.fields.empty())
      throw std::invalid_argument("design variable '" + v.name + "' sets no field");
    if (!(v.lower < v.upper && v.initial >= v.lower && v.initial <= v.upper))
      throw std::invalid_argument("design variable '" + v.name +
                                  "': expected lower < upper and the initial value inside");
    for (const DesignField& f : v.fields) {
      if (!f.ref.number || f.ref.index >= f.ref.number->count(base_))
        throw std::invalid_argument("design variable '" + v.name + "': member index out of range");
      const FieldSpec& spec = f.spec();
      if (!spec.siRange().contains(v.lower) || !spec.siRange().contains(v.upper))
        throw InvalidModelError("design variable '" + v.name + "': " + f.name + " must stay in " +
                                spec.range.interval() + " (the range of " +
                                std::string(spec.key) + "), got [" + displayNumber(v.lower) +
                                ", " + displayNumber(v.upper) + "]");
    }
  }
  if (options_.constraints.tip_deflection_max_m > 0.0 &&
      base_.wing.structure != StructureLevel::kFlexible)
    throw std::invalid_argument("a tip-deflection limit needs a flexible wing");
  constraint_names_.push_back("trimmed");
  const DesignConstraints& c = options_.constraints;
  if (c.bounded) constraint_names_.push_back("bounded");
  if (c.pitch_amplitude_max_rad > 0.0) constraint_names_.push_back("pitch_amplitude");
  if (c.tip_deflection_max_m > 0.0) constraint_names_.push_back("tip_deflection");
  if (c.structural_mass_max_kg > 0.0) constraint_names_.push_back("structural_mass");
  if (c.floquet_max_modulus > 0.0) constraint_names_.push_back("floquet_max_modulus");
  value_info_ = {
      {"trim_converged", "-", 1.0},       {"theta_mean_deg", "deg", kDegToRad},
      {"speed_mps", "m/s", 1.0},          {"tail_angle_deg", "deg", kDegToRad},
      {"freq_hz", "Hz", 1.0},             {"residual_scaled_max", "-", 1.0},
      {"hinge_power_W", "W", 1.0},        {"aero_power_W", "W", 1.0},
      {"bounded", "-", 1.0},              {"norm_ratio_max", "-", 1.0},
      {"free_flight_time_s", "s", 1.0},   {"drift", "-", 1.0},
      {"pitch_amplitude_deg", "deg", kDegToRad},
      {"tip_deflection_m", "m", 1.0},     {"structural_mass_kg", "kg", 1.0},
      {"periodic_runs", "-", 1.0},
  };
  if (options_.trim.method == TrimMethod::kPeriodic)
    value_info_.insert(value_info_.end(), {{"floquet_max_modulus", "-", 1.0},
                                           {"floquet_stable", "-", 1.0},
                                           {"periodic_residual", "-", 1.0},
                                           {"equation4_theta_mean_deg", "deg", kDegToRad},
                                           {"equation4_speed_mps", "m/s", 1.0},
                                           {"equation4_tail_angle_deg", "deg", kDegToRad}});
}

std::unique_ptr<ProblemWorkspace> DesignProblem::makeWorkspace() const {
  return std::make_unique<DesignWorkspace>();
}

VariableBox DesignProblem::box() const {
  VariableBox b;
  for (const DesignVariable& v : space_.variables) {
    b.lower.push_back(v.lower);
    b.upper.push_back(v.upper);
    b.initial.push_back(v.initial);
  }
  return b;
}

Evaluation DesignProblem::evaluate(const std::vector<double>& x, ProblemWorkspace& workspace) const {
  auto& ws = static_cast<DesignWorkspace&>(workspace);
  const VehicleModel vehicle = applyDesign(base_, space_, x);
  const OperatingPoint guess =
      options_.warm_start && ws.last_trim ? *ws.last_trim : options_.trim.initial;
  const DesignEvaluation d = evaluateDesign(vehicle, options_, guess, modal_wings_.get());

  Evaluation e;
  e.message = d.message;
  e.values.assign(value_info_.size(), kNaN);
  e.values[kStructuralMass] = d.structural_mass_kg;
  if (!d.trim_attempted) {
    e.status = EvaluationStatus::kFailed;
    e.objective = kNaN;
    e.constraints.assign(constraint_names_.size(), kNaN);
    return e;
  }
  const TrimSummary& s = d.trim;
  const bool have_means = s.termination != TrimTermination::kSimulationFailure;
  const FreeFlightVerification& f = s.free_flight;
  const bool flown = f.status == FreeFlightStatus::kBounded ||
                     f.status == FreeFlightStatus::kUnbounded;
  auto& v = e.values;
  v[kTrimConverged] = s.converged ? 1.0 : 0.0;
  v[kTrimTheta] = s.solution.theta_rad;
  v[kTrimSpeed] = s.solution.speed_mps;
  v[kTrimTailAngle] = s.solution.tail_angle_rad;
  v[kTrimFreq] = s.solution.freq_hz;
  v[kTrimResidual] = have_means ? s.scaled_residual_max : kNaN;
  v[kPowerHinge] = have_means ? s.mean.power_hinge_W : kNaN;
  v[kPowerAero] = have_means ? s.mean.power_aero_W : kNaN;
  v[kBounded] = flown ? (f.bounded ? 1.0 : 0.0) : kNaN;
  v[kNormRatioMax] = flown ? f.norm_ratio_max : kNaN;
  v[kFlownTime] = f.flown_s;
  v[kDrift] = f.drift;
  v[kPitchAmplitude] = d.pitch_amplitude_rad;
  v[kTipDeflection] = d.tip_deflection_m;
  v[kPeriodicRuns] = s.evaluations;
  if (d.periodic) {
    v[kFloquetMaxModulus] = d.floquet_max_modulus;
    v[kFloquetStable] = d.floquet_valid ? (d.floquet_max_modulus < 1.0 ? 1.0 : 0.0) : kNaN;
    v[kPeriodicResidual] = d.periodic_residual;
    if (s.converged) {  // the warm start of the next evaluation (observe)
      v[kEquation4Theta] = d.equation4.theta_rad;
      v[kEquation4Speed] = d.equation4.speed_mps;
      v[kEquation4TailAngle] = d.equation4.tail_angle_rad;
    }
  }

  const double amplitude_deg = d.pitch_amplitude_rad / kDegToRad;
  switch (options_.objective) {
    case DesignObjective::kPower: e.objective = v[kPowerHinge]; break;
    case DesignObjective::kPitchAmplitude: e.objective = amplitude_deg; break;
    case DesignObjective::kWeighted: {
      const DesignObjectiveWeights& w = options_.weights;
      e.objective = (w.power_per_W > 0.0 ? w.power_per_W * v[kPowerHinge] : 0.0) +
                    (w.pitch_amplitude_per_deg > 0.0 ? w.pitch_amplitude_per_deg * amplitude_deg
                                                     : 0.0);
      break;
    }
  }

  const DesignConstraints& c = options_.constraints;
  double g_trim = kTrimmedFeasible;
  if (!s.converged)
    g_trim = have_means && s.scaled_residual_max > 0.0
                 ? std::max(std::log10(s.scaled_residual_max / d.residual_tol), kViolatedFloor)
                 : kNaN;
  e.constraints.push_back(g_trim);

  // A diverged free flight: from divergence_ratio (diverging at the end of the horizon, above
  // the flown values) to twice that (at once).
  const double divergence = options_.trim.free_flight.free.divergence_ratio;
  const double diverged =
      divergence * (1.0 + (std::isfinite(f.flown_s) && f.horizon_s > 0.0
                                ? std::clamp(1.0 - f.flown_s / f.horizon_s, 0.0, 1.0)
                                : 1.0));
  // Without a trim the quantities at the trim point do not exist: the constraints that need them
  // are worse than any flown value and follow the trim constraint (so that the largest violation,
  // which COBYLA reduces first, still says how far from trim the design is).
  const double untrimmed = s.converged ? kNaN : g_trim + 2.0 * divergence;
  const bool diverged_flight = f.status == FreeFlightStatus::kUnbounded && !flown_analysed(f);
  if (c.bounded) {
    double g = untrimmed;
    if (flown_analysed(f)) {
      // Eq. (5) holds when the norm stays <= 1 and the drift <= its limit: both as one measure.
      g = f.norm_ratio_max - 1.0;
      if (std::isfinite(f.drift)) g = std::max(g, f.drift - f.drift_limit);
      if (!f.bounded) g = std::max(g, kViolatedFloor);
    } else if (diverged_flight) {
      g = diverged;
    }
    e.constraints.push_back(g);
  }
  if (c.pitch_amplitude_max_rad > 0.0) {
    double g = untrimmed;
    if (std::isfinite(d.pitch_amplitude_rad))
      g = d.pitch_amplitude_rad / c.pitch_amplitude_max_rad - 1.0;
    else if (diverged_flight)
      g = diverged;
    e.constraints.push_back(g);
  }
  if (c.tip_deflection_max_m > 0.0)
    e.constraints.push_back(s.converged ? d.tip_deflection_m / c.tip_deflection_max_m - 1.0
                                        : untrimmed);
  if (c.structural_mass_max_kg > 0.0)
    e.constraints.push_back(d.structural_mass_kg / c.structural_mass_max_kg - 1.0);
  if (c.floquet_max_modulus > 0.0)  // no Floquet analysis at an orbit: NaN, the failure penalty
    e.constraints.push_back(s.converged ? d.floquet_max_modulus / c.floquet_max_modulus - 1.0
                                        : untrimmed);
  return e;
}

void DesignProblem::observe(const std::vector<double>& /*x*/, const Evaluation& result,
                            ProblemWorkspace& workspace) const {
  auto& ws = static_cast<DesignWorkspace&>(workspace);
  const std::vector<double>& v = result.values;
  if (result.status != EvaluationStatus::kOk || v.size() != value_info_.size() ||
      v[kTrimConverged] != 1.0)
    return;
  // The warm start: the trim point, or with the periodic trim its Eq. (4) start (the orbit's
  // cycle means are not an Eq. (4) solution; stage 1 would walk from them again).
  const bool periodic = v.size() == kPeriodicDesignValueCount;
  OperatingPoint p;
  p.theta_rad = v[periodic ? kEquation4Theta : kTrimTheta];
  p.speed_mps = v[periodic ? kEquation4Speed : kTrimSpeed];
  p.tail_angle_rad = v[periodic ? kEquation4TailAngle : kTrimTailAngle];
  p.freq_hz = v[kTrimFreq];
  ws.last_trim = p;
}

VehicleDefinition DesignProblem::designVehicle(const std::vector<double>& x,
                                               const Evaluation& result) const {
  VehicleDefinition v{applyDesign(base_, space_, x), options_.trim.design_point};
  const std::vector<double>& r = result.values;
  if (result.status == EvaluationStatus::kOk && r.size() == value_info_.size() &&
      r[kTrimConverged] == 1.0) {
    v.design_point.theta_rad = r[kTrimTheta];
    v.design_point.speed_mps = r[kTrimSpeed];
    v.design_point.tail_angle_rad = r[kTrimTailAngle];
    v.design_point.freq_hz = r[kTrimFreq];
  }
  return v;
}

}  // namespace orni::opt
