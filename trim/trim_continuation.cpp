#include "trim/trim_continuation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/analysis/floquet.hpp"
#include "trim/free_flight_period_map.hpp"

namespace orni {

namespace {

int mapIndex(PeriodicControl c) {
  switch (c) {
    case PeriodicControl::kTailAngle: return kPeriodTailAngle;
    case PeriodicControl::kFrequency: return kPeriodFrequency;
    case PeriodicControl::kCgPosition: return kPeriodCgShift;
  }
  return kPeriodFrequency;
}

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The smallest first step, as a fraction of |to - start|.
constexpr double kStepFloorOfRange = 1e-6;

/// "completed" only when the last regular point is at `to`: the core stops at either end of
/// [min(start, to), max(start, to)], and a branch that comes back to its start (turned by a fold,
/// or wandering without moving the parameter) has not reached the end the study asked for.
void checkEndReached(const TrimContinuationOptions& options, double lambda0,
                     const std::vector<TrimContinuationPoint>& resume,
                     const ContinuationSummary& c, TrimContinuationSummary* s) {
  const ContinuationPoint* last = nullptr;
  bool fold = false;
  auto see = [&](const ContinuationPoint& pt) {
    if (pt.event.empty()) last = &pt;
    fold = fold || pt.event == "fold";
  };
  for (const TrimContinuationPoint& pt : resume) see(pt.orbit);  // a resumed run's first part
  for (const ContinuationPoint& pt : c.points) see(pt);
  const double tol = 1e-9 * std::max(1.0, std::abs(options.to));
  if (last && std::abs(last->lambda - options.to) <= tol) return;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "the branch did not reach the end of the range %.6g: %s at %.6g after %d points",
                options.to,
                fold ? "it turned back at a fold and left the range at its start value"
                     : "the parameter did not advance (no fold) and the branch left the range "
                       "at its start value",
                last ? last->lambda : lambda0, last ? last->index : 0);
  // A fold that turns the branch back is a physical outcome; a parameter that does not advance
  // without one is a failure to make progress.
  s->status = fold ? ContinuationStatus::kNotConverged : ContinuationStatus::kFailed;
  s->message = buf;
}

}  // namespace

bool TrimContinuationOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!std::isfinite(to)) return fail("the end of the branch must be finite");
  if (!(step > 0.0 && std::isfinite(step))) return fail("the first step must be > 0");
  if (max_points < 1 || max_points > 10000) return fail("max_points must be in [1, 10000]");
  if (!(locate_tol > 0.0)) return fail("locate_tol must be > 0");
  if (samples < 8 || samples > 100000) return fail("samples must be in [8, 100000]");
  if (threads < 1 || threads > 64) return fail("threads must be in [1, 64]");
  return true;
}

double continuationParameterValue(PeriodicControl parameter, const OperatingPoint& point,
                                  double cg_shift_m) {
  switch (parameter) {
    case PeriodicControl::kTailAngle: return point.tail_angle_rad;
    case PeriodicControl::kFrequency: return point.freq_hz;
    case PeriodicControl::kCgPosition: return cg_shift_m;
  }
  return point.freq_hz;
}

TrimContinuationSummary continueTrim(const FlightCoreModel& model, const TrimOptions& trim,
                                     const TrimContinuationOptions& options,
                                     const TrimContinuationCallback& on_point,
                                     const std::vector<TrimContinuationPoint>& resume) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("continuation options: " + why);
  if (options.parameter == trim.periodic.control)
    throw std::invalid_argument(
        "continuation: the parameter must differ from the periodic trim's control (" +
        std::string(toString(trim.periodic.control)) + ")");
  if (!resume.empty() && !resume.back().orbit.event.empty())
    throw std::invalid_argument("continuation: a resumed branch must end with a regular point");

  TrimContinuationSummary s;
  // The start: the periodic trim (no Floquet analysis or free-flight check: every point of the
  // branch gets its multipliers).
  TrimOptions o = trim;
  o.method = TrimMethod::kPeriodic;
  o.periodic.floquet = false;
  o.verify_free_flight = false;
  s.start = solvePeriodicTrim(model, o);
  if (!s.start.converged) {
    s.message = "no periodic trim to start the branch from: " + s.start.message;
    s.wall_time_s = seconds(t0);
    return s;
  }
  const double lambda0 =
      continuationParameterValue(options.parameter, s.start.solution, s.start.cg_shift_m);
  if (options.to == lambda0) {
    s.status = ContinuationStatus::kFailed;
    s.message = "the end of the branch equals the start value";
    s.wall_time_s = seconds(t0);
    return s;
  }
  // A first step below its floor cannot move the parameter measurably: the corrector's noise
  // (residual_tol) moves the point more than the step does, and the branch may wander back to its
  // start and "reach the end of the range" there, a false result.
  const double step_floor = kStepFloorOfRange * std::abs(options.to - lambda0);
  if (options.step < step_floor) {
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "the first step %.3g is below its floor %.3g (%.0e of the range from the start "
                  "%.6g to %.6g; parameter units, rad for an angle): the parameter cannot move "
                  "measurably; give a larger step",
                  options.step, step_floor, kStepFloorOfRange, lambda0, options.to);
    s.status = ContinuationStatus::kFailed;
    s.message = buf;
    s.wall_time_s = seconds(t0);
    return s;
  }

  FreeFlightPeriodMapOptions mo;
  mo.rel_tol = o.periodic.rel_tol;
  mo.friction_speed_mps = s.start.friction_speed_mps;
  mo.design_point = o.design_point;
  FreeFlightPeriodMap map(model, mo);
  s.friction_speed_mps = map.frictionSpeed_mps();
  const int parameter = mapIndex(options.parameter);

  ShootingOptions so;
  so.free_parameters = {mapIndex(o.periodic.control)};
  so.conditions = {kPeriodAltitudeGain};
  so.residual_tol = o.periodic.residual_tol;
  so.max_iterations = o.periodic.max_iterations;
  so.jacobian_threads = options.threads;

  ContinuationOptions co;
  co.parameter = parameter;
  co.lambda_min = std::min(lambda0, options.to);
  co.lambda_max = std::max(lambda0, options.to);
  co.direction = options.to > lambda0 ? 1 : -1;
  const double scale = map.parameterScale(parameter);
  co.initial_step = options.step / scale;
  co.max_step = 5.0 * co.initial_step;
  co.min_step = 1e-4 * co.initial_step;
  co.steps_in_parameter = true;
  // A corrector iteration costs one period map, a point ~110 (its Jacobian): let the steps grow
  // while the corrector needs fewer than 6 (of 8). Over 12 -> 16 Hz: 16 points against 33 with 4.
  co.target_iterations = 6;
  co.max_points = options.max_points;
  co.residual_tol = o.periodic.residual_tol;
  co.locate_events = options.locate_events;
  co.locate_tol = options.locate_tol;
  // trim.periodic.multipliers, as the periodic trim's Floquet analysis: the leading ones by
  // Arnoldi with the body's columns differenced (the wing and the MST-TD states decay in a
  // period, as in the periodic trim's first Jacobian), or all from the full Jacobian (0).
  co.leading_multipliers = o.periodic.multipliers;
  co.slow_states = {0, 1, 2, 3};
  co.max_krylov = std::max(48, o.periodic.multipliers + 1);

  const std::vector<FloquetStateInfo>& info = map.stateInfo();
  std::string sample_why;
  double grid_friction_mps = 0.0;  // the friction when the last regular point's grid was chosen
  auto describe = [&](const ContinuationPoint& pt, TrimContinuationPoint* tp) {
    tp->orbit = pt;
    tp->friction_speed_mps = map.frictionSpeed_mps();
    // The start's grid is chosen after its prepare; a regular point's before (prepare records it).
    tp->grid_friction_speed_mps =
        pt.index == 0 && pt.event.empty() ? tp->friction_speed_mps : grid_friction_mps;
    OrbitHistory h;
    if (!map.sampleOrbit(pt.x.data(), pt.p.data(), options.samples, &h, &sample_why)) return false;
    const double T = 1.0 / pt.p[kPeriodFrequency];
    tp->mean = cycleMeans(h, T);
    tp->solution.theta_rad = tp->mean.theta_rad;
    tp->solution.speed_mps = tp->mean.airspeed_mps;
    tp->solution.tail_angle_rad = pt.p[kPeriodTailAngle];
    tp->solution.freq_hz = pt.p[kPeriodFrequency];
    tp->cg_shift_m = pt.p[kPeriodCgShift];
    MonodromyEigen lead;
    lead.ok = true;
    lead.state_count = static_cast<int>(pt.x.size());
    lead.multipliers = pt.multipliers.head(1);
    lead.vectors = pt.leading_vector;
    lead.message = "leading multiplier";
    tp->leading_label = analyseFloquet(lead, T, info).multipliers.front().label;
    return true;
  };
  bool sampling_failed = false;
  const ContinuationCallback forward = [&](const ContinuationPoint& pt) {
    TrimContinuationPoint tp;
    if (!describe(pt, &tp)) {
      sampling_failed = true;
      return false;
    }
    s.points.push_back(tp);
    return !on_point || on_point(tp);
  };

  // Each corrected point: the friction moved to its orbit's mean airspeed (16 samples, as the
  // periodic trim's first pass) and the point corrected again: the periodic trim's second pass.
  const ContinuationPrepare prepare = [&](const ContinuationPoint& pt) {
    grid_friction_mps = map.frictionSpeed_mps();
    OrbitHistory h;
    if (!map.sampleOrbit(pt.x.data(), pt.p.data(), 16, &h, &sample_why)) return false;
    const double airspeed = cycleMeans(h, 1.0 / pt.p[kPeriodFrequency]).airspeed_mps;
    if (!(airspeed > 0.0) || airspeed == map.frictionSpeed_mps()) return false;
    map.setFrictionSpeed(airspeed);
    return true;
  };
  const ContinuationPoint* from = nullptr;
  if (!resume.empty()) {
    from = &resume.back().orbit;
    map.setFrictionSpeed(resume.back().grid_friction_speed_mps);  // as when its grid was chosen
  }
  const ContinuationResumeHook on_resume = [&] {
    map.setFrictionSpeed(resume.back().friction_speed_mps);  // as when it was accepted
  };
  const ContinuationSummary c = continuePeriodicOrbits(
      map, s.start.orbit_start, FreeFlightPeriodMap::parameters(s.start.solution, s.start.cg_shift_m),
      so, co, forward, prepare, from, on_resume);
  s.status = c.status;
  s.message = c.message;
  if (c.status == ContinuationStatus::kCompleted) checkEndReached(options, lambda0, resume, c, &s);
  if (sampling_failed) {
    s.status = ContinuationStatus::kFailed;
    s.message = "a point's orbit could not be sampled: " + sample_why;
  }
  s.period_maps = c.period_maps + s.start.shooting.period_maps;
  s.events = c.events;
  s.wall_time_s = seconds(t0);
  return s;
}

}  // namespace orni
