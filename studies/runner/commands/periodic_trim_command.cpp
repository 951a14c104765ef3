#include "studies/runner/commands/periodic_trim_command.hpp"
#include "studies/runner/output/console.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/model/frames.hpp"
#include "studies/runner/commands/failed_run.hpp"
#include "studies/runner/commands/trim_command.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "studies/runner/plotting/trim_figures.hpp"
#include "trim/periodic_trim.hpp"

namespace orni::studies {

namespace {

// "U 0.61; theta 0.30; W 0.05": the states carrying most of the eigenvector (shares of |v|^2).
std::string dominantText(const FloquetMultiplier& m) {
  std::string s;
  for (const auto& [name, share] : m.dominant_states)
    s += (s.empty() ? "" : "; ") + name + " " + formatFixed(share, 3);
  return s;
}

JsonObject multiplierObject(const FloquetMultiplier& m) {
  std::vector<std::string> names;
  std::vector<double> shares;
  for (const auto& [name, share] : m.dominant_states) {
    names.push_back(name);
    shares.push_back(share);
  }
  JsonObject o;
  o.set("modulus", m.modulus)
      .set("argument_deg", m.argument_rad * kRadToDeg)
      .set("real", m.mu.real())
      .set("imag", m.mu.imag())
      .set("exponent_real_per_s", m.exponent_per_s.real())
      .set("exponent_imag_radps", m.exponent_per_s.imag())
      .set("oscillatory", m.oscillatory)
      .set("damping_ratio", m.damping_ratio)
      .set("period_s", m.oscillatory ? m.period_s : 0.0)
      .set("label", m.label)
      .setStrings("dominant_states", names)
      .set("dominant_shares", shares)
      .set("refinement_change", m.refinement_change);  // null when not checked
  if (std::isnan(m.refinement_change))
    o.setNull("resolved");
  else
    o.set("resolved", m.resolved());
  return o;
}

JsonObject floquetObject(const PeriodicTrimSummary& s) {
  JsonObject o;
  const FloquetAnalysis& f = s.floquet;
  if (!s.floquet_valid) {
    o.set("valid", false).set("message", s.floquet_message.empty()
                                             ? std::string("no Floquet analysis (floquet = false "
                                                           "or no orbit)")
                                             : s.floquet_message);
    o.setObjects("multipliers", {}).setNull("stable").setNull("max_modulus").setNull("margin");
    return o;
  }
  std::vector<JsonObject> list;
  for (const FloquetMultiplier& m : f.multipliers) list.push_back(multiplierObject(m));
  o.set("valid", true)
      .setObjects("multipliers", list)
      .set("stable", f.stable)
      .set("max_modulus", f.max_modulus)
      .set("margin", f.margin)
      .set("leading_label", f.multipliers.front().label)
      .set("count", static_cast<int>(f.multipliers.size()))
      .set("state_count", f.state_count)
      .set("complete", f.complete)
      .set("method", f.method)
      .set("period_maps", s.floquet_maps)
      .set("checked", f.checked)
      .set("check_method", f.check_method.empty() ? std::string("not checked") : f.check_method)
      .set("note",
           "multipliers of the monodromy matrix of the orbit's states (body theta, U, W, Q; wing "
           "modes and rates; MST-TD states), altitude and horizontal position excluded (they are "
           "ignorable: each would add a multiplier 1); stable = every multiplier inside the unit "
           "circle, margin = 1 - max_modulus; eigenvectors in scaled states");
  return o;
}

// One period of the orbit from flap phase 0.
CsvTable orbitTable(const PeriodicTrimSummary& s) {
  const OrbitHistory& h = s.history;
  const double T = 1.0 / s.solution.freq_hz;
  auto body = [&h](std::size_t k) -> const BodyState& { return h.body[k]; };
  auto loads = [&h](std::size_t k) -> const LoadSample& { return h.samples[k].loads; };
  return RowTable("periodic_orbit.csv", rowIndices(h.t_s.size()))
      .number("t", [&](std::size_t k) { return h.t_s[k]; })
      .number("phase", [&](std::size_t k) { return h.t_s[k] / T; })
      .number("delta_M", [&](std::size_t k) { return h.delta_M_rad[k] * kRadToDeg; })
      .number("theta", [&](std::size_t k) { return body(k).theta_rad * kRadToDeg; })
      .number("U", [&](std::size_t k) { return body(k).U_mps; })
      .number("W", [&](std::size_t k) { return body(k).W_mps; })
      .number("Q", [&](std::size_t k) { return body(k).Q_radps * kRadToDeg; })
      .number("airspeed", [&](std::size_t k) { return std::hypot(body(k).U_mps, body(k).W_mps); })
      .number("x", [&](std::size_t k) { return body(k).x_I_m; })
      .number("h", [&](std::size_t k) { return body(k).h_m; })
      .number("FV", [&](std::size_t k) { return loads(k).FV_N; })
      .number("FH", [&](std::size_t k) { return loads(k).FH_N; })
      .number("M", [&](std::size_t k) { return loads(k).M_Nm; })
      .number("power_aero", [&](std::size_t k) { return loads(k).power_aero_W; })
      .table();
}

CsvTable iterationTable(const PeriodicTrimSummary& s) {
  auto it = [&s](std::size_t i) -> const ShootingIteration& { return s.newton_log[i]; };
  return RowTable("periodic_iterations.csv", rowIndices(s.newton_log.size()))
      .number("pass", [&](std::size_t i) { return s.newton_pass[i]; })
      .number("iteration", [&](std::size_t i) { return it(i).iteration; })
      .number("residual_max", [&](std::size_t i) { return it(i).residual_max; })
      .number("residual_norm", [&](std::size_t i) { return it(i).residual_norm; })
      .number("step_norm", [&](std::size_t i) { return it(i).step_norm; })
      .number("damping", [&](std::size_t i) { return it(i).damping; })
      .number("fresh_jacobian", [&](std::size_t i) { return it(i).fresh_jacobian ? 1.0 : 0.0; })
      .number("grid_refreshed", [&](std::size_t i) { return it(i).refreshed ? 1.0 : 0.0; })
      .number("period_maps", [&](std::size_t i) { return it(i).period_maps; })
      .table();
}

CsvTable floquetTable(const PeriodicTrimSummary& s) {
  using M = FloquetMultiplier;
  static const std::vector<M> kNone;
  const std::vector<M>& ms = s.floquet_valid ? s.floquet.multipliers : kNone;
  return RowTable("floquet.csv", rowIndices(ms.size()))
      .number("rank", [](std::size_t k) { return k + 1; })
      .number("mu_real", [&](std::size_t k) { return ms[k].mu.real(); })
      .number("mu_imag", [&](std::size_t k) { return ms[k].mu.imag(); })
      .number("modulus", [&](std::size_t k) { return ms[k].modulus; })
      .number("argument", [&](std::size_t k) { return ms[k].argument_rad * kRadToDeg; })
      .number("exponent_real", [&](std::size_t k) { return ms[k].exponent_per_s.real(); })
      .number("exponent_imag", [&](std::size_t k) { return ms[k].exponent_per_s.imag(); })
      .number("damping_ratio", [&](std::size_t k) { return ms[k].damping_ratio; })
      .number("period", [&](std::size_t k) { return ms[k].oscillatory ? ms[k].period_s : 0.0; })
      .number("inside_unit_circle", [&](std::size_t k) { return ms[k].modulus < 1.0 ? 1.0 : 0.0; })
      .text("label", [&](std::size_t k) { return ms[k].label; })
      .text("dominant_states", [&](std::size_t k) { return dominantText(ms[k]); })
      .text("refinement_change",  // empty when not checked (trim.periodic.multiplier_check)
            [&](std::size_t k) { return formatCell(ms[k].refinement_change); })
      .text("resolved", [&](std::size_t k) {
        return s.floquet.checked ? std::string(ms[k].resolved() ? "1" : "0") : std::string();
      })
      .table();
}

}  // namespace

int runPeriodicTrimStudy(const Study& study, const std::filesystem::path& out_dir,
                         PeriodicRunKind kind) {
  const FlightCoreModel model(study.vehicle);
  const PeriodicTrimSummary s = solvePeriodicTrim(model, study.trim);
  const double W = study.vehicle.body.mass_kg * study.vehicle.air.gravity_mps2;
  const bool have_orbit = s.converged;

  writeFileAtomic(out_dir / "study.resolved.toml", resolvedStudyToml(study));
  writeFileAtomic(out_dir / "periodic_iterations.csv", iterationTable(s).toString());
  writeFileAtomic(out_dir / "floquet.csv", floquetTable(s).toString());
  if (have_orbit) writeFileAtomic(out_dir / "periodic_orbit.csv", orbitTable(s).toString());
  // What this run does not produce must not be left from an earlier run into the folder.
  if (!have_orbit) removeRunOutputs(out_dir, {"periodic_orbit.csv"}, {"periodic_orbit"});
  if (!s.floquet_valid) removeRunOutputs(out_dir, {}, {"floquet_multipliers"});

  const PeriodicCycleMeans& m = s.mean;
  JsonObject start;
  if (have_orbit)
    start.set("theta_deg", s.orbit_start[0] * kRadToDeg)
        .set("U_mps", s.orbit_start[1])
        .set("W_mps", s.orbit_start[2])
        .set("Q_degps", s.orbit_start[3] * kRadToDeg)
        .set("wing_and_aero_states", static_cast<int>(s.orbit_start.size()) - 4);
  const TrimSummary& e4 = s.stage1;
  JsonObject stage1;
  stage1.set("converged", e4.converged).set("message", e4.message);
  setOperatingPoint(stage1, e4.solution)
      .set("residual_scaled_max", e4.scaled_residual_max)
      .set("residual_tolerance", study.trim.residual_tol)
      .set("evaluations", e4.evaluations);
  const ShootingSummary& sh = s.shooting;
  JsonObject solver;
  solver.set("method",
             "single shooting over one flapping period: Newton on the scaled periodic residual "
             "(x(T) - x(0) per state scale, altitude gain / 0.1 m), Jacobian by forward "
             "differences on a fixed step grid (body columns first, then Broyden updates), "
             "backtracking line search")
      .set("control", toString(study.trim.periodic.control))
      .set("message", sh.message)
      .set("residual_tolerance", study.trim.periodic.residual_tol)
      .set("iterations", sh.iterations)
      .set("period_maps", sh.period_maps)
      .set("jacobians", sh.jacobians)
      .set("partial_jacobians", sh.partial_jacobians)
      .set("broyden_updates", sh.broyden_updates)
      .set("grid_refreshes", sh.refreshes)
      .set("grid_steps", s.grid_steps)
      .set("rhs_evaluations", s.rhs_evaluations)
      .set("integrator", s.integrator)
      .set("rel_tol", study.trim.periodic.rel_tol)
      .set("friction_speed_mps", s.friction_speed_mps)
      .set("orbit_check_scaled", s.orbit_check)
      .set("orbit_check_note",
           "max |x(T) - x(0)| in state scales when the orbit start is flown one period by the "
           "free-flight integrator (ARKODE, adaptive, the same rel_tol): the integration error of "
           "the orbit, independent of the shooting's fixed grid")
      .set("cg_shift_m", s.cg_shift_m);

  JsonObject summary =
      summaryHeader(kind == PeriodicRunKind::kStability ? "stability" : "trim",
                    toString(s.status), s.message, s.wall_time_s);
  summary.set("converged", s.converged).set("method", toString(TrimMethod::kPeriodic));
  setOperatingPoint(summary, s.solution);
  if (have_orbit) {
    summary.set("periodic_residual", sh.residual_max)
        .set("residual", JsonObject()
                             .set("FV_N", m.FV_N - W)
                             .set("FH_N", m.FH_N)
                             .set("M_Nm", m.M_Nm));
  } else {
    summary.setNull("periodic_residual")
        .set("residual", JsonObject().setNull("FV_N").setNull("FH_N").setNull("M_Nm"));
  }
  summary.set("residual_source",
           "periodic_residual: max |x(T) - x(0)| of the orbit in state scales (and the altitude "
           "gain in 0.1 m); residual: the orbit's cycle means of the aerodynamic loads (both "
           "wings with their apparent mass, tail, fuselage drag) in the flight-path frame minus "
           "the weight, not driven to zero: they balance the mean of the vehicle's inertial "
           "loads in that rotating frame")
      .set("floquet", floquetObject(s))
      .set("free_flight", freeFlightObject(s.free_flight))
      .set("orbit_start", start)
      .set("mean", JsonObject()
                       .set("theta_deg", m.theta_rad * kRadToDeg)
                       .set("airspeed_mps", m.airspeed_mps)
                       .set("U_mps", m.U_mps)
                       .set("W_mps", m.W_mps)
                       .set("FV_N", m.FV_N)
                       .set("FH_N", m.FH_N)
                       .set("M_Nm", m.M_Nm)
                       .set("power_W", m.power_aero_W)
                       .set("theta_min_deg", m.theta_min_rad * kRadToDeg)
                       .set("theta_max_deg", m.theta_max_rad * kRadToDeg)
                       .set("altitude_p2p_m", m.altitude_p2p_m))
      .set("weight_N", W)
      .set("stage1_equation4", stage1)
      .set("periodic", solver)
      .set("time_s", JsonObject()
                         .set("equation4_start", s.stage1_time_s)
                         .set("orbit", s.orbit_time_s)
                         .set("floquet", s.floquet_time_s));
  writeSummary(out_dir, summary);
  if (have_orbit) drawFigure(out_dir, "periodic_orbit", periodicOrbitFigure(study, s));
  if (s.floquet_valid)
    drawFigure(out_dir, "floquet_multipliers", floquetMultiplierFigure(study, s));
  consoleOut() << study.name << ": " << s.BriefReport() << "\n  " << s.message << "\n  -> "
            << out_dir.string() << "\n";
  return 0;
}

}  // namespace orni::studies
