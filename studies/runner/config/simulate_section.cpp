// [simulate] and [simulate.free] of a study file (study_file.hpp documents the keys; ranges: the
// field table's simulate.* entries), and the integrator tolerances [simulate] shares with
// [aeromap].
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/model/frames.hpp"
#include "studies/runner/config/study_reader.hpp"
#include "studies/runner/config/study_sections.hpp"

namespace orni::studies {

namespace {

using orni::field;

const std::vector<std::pair<std::string, FlightMode>> kModes = {{"tethered", FlightMode::kTethered},
                                                                {"free", FlightMode::kFree}};
const std::vector<std::pair<std::string, bool>> kSampledLoads = {{"evaluated", false},
                                                                 {"interpolated", true}};

const std::vector<std::string> kFreeKeys = {
    "bound_speed_mps", "bound_W_mps",        "bound_theta_deg",  "bound_Q_degps",
    "bound_h_m",       "transient_fraction", "divergence_ratio", "initial_altitude_m"};

/// An angle key in degrees, stored in radians: `rad` is left alone when the key is absent.
void readDegrees(TableReader& r, std::string_view key, double& rad) {
  if (auto d = r.maybeDouble(field(key))) rad = *d * orni::kDegToRad;
}

}  // namespace

void throwInvalidOptions(const TableReader& section, const std::string& why) {
  // The fields are named like the keys, so the error names the key.
  const std::size_t space = why.find(' ');
  const std::string key = why.substr(0, space);
  const std::string must = " must be ";
  std::string expected = why;
  if (why.compare(space, must.size(), must) == 0)
    expected = "a value " + why.substr(space + must.size());
  const toml::node* n = section.table().get(key);
  throw section.valueError(key, expected, n ? describeNode(*n) : std::string("the default"));
}

void readTolerances(TableReader& r, SimulationOptions& o, const std::string& section) {
  o.rel_tol = r.optionalDouble(field(section + ".rel_tol"), o.rel_tol);
  o.abs_tol = r.optionalDouble(field(section + ".abs_tol"), o.abs_tol);
  o.separation_abs_tol =
      r.optionalDouble(field(section + ".separation_abs_tol"), o.separation_abs_tol);
  o.steady_tol = r.optionalDouble(field(section + ".steady_tol"), o.steady_tol);
}

void writeTolerances(const SimulationOptions& o, TomlWriter& out) {
  out.number("rel_tol", o.rel_tol);
  out.number("abs_tol", o.abs_tol);
  out.number("separation_abs_tol", o.separation_abs_tol);
  out.number("steady_tol", o.steady_tol);
}

std::vector<std::string> freeFlightKeys() { return kFreeKeys; }

void readFreeFlightTable(TableReader& r, FreeFlightOptions& f) {
  FreeFlightBounds& b = f.bounds;
  b.U_mps = r.optionalDouble(field("simulate.free.bound_speed_mps"), b.U_mps);
  b.W_mps = r.optionalDouble(field("simulate.free.bound_W_mps"), b.W_mps);
  readDegrees(r, "simulate.free.bound_theta_deg", b.theta_rad);
  readDegrees(r, "simulate.free.bound_Q_degps", b.Q_radps);
  b.h_m = r.optionalDouble(field("simulate.free.bound_h_m"), b.h_m);
  f.transient_fraction =
      r.optionalDouble(field("simulate.free.transient_fraction"), f.transient_fraction);
  f.divergence_ratio =
      r.optionalDouble(field("simulate.free.divergence_ratio"), f.divergence_ratio);
  f.initial_altitude_m =
      r.optionalDouble(field("simulate.free.initial_altitude_m"), f.initial_altitude_m);
  r.finish();
}

void writeFreeFlightTable(const FreeFlightOptions& f, const std::vector<std::string>& header,
                          TomlWriter& out) {
  out.header(header);
  out.number("bound_speed_mps", f.bounds.U_mps);
  out.number("bound_W_mps", f.bounds.W_mps);
  out.scaled("bound_theta_deg", f.bounds.theta_rad, orni::kDegToRad);
  out.scaled("bound_Q_degps", f.bounds.Q_radps, orni::kDegToRad,
             "0 = automatic: 2 pi f bound_theta");
  out.number("bound_h_m", f.bounds.h_m);
  out.number("transient_fraction", f.transient_fraction);
  out.number("divergence_ratio", f.divergence_ratio);
  out.number("initial_altitude_m", f.initial_altitude_m);
}

void readSimulateSection(StudyDocument doc, Study& study) {
  std::optional<TableReader> sim = doc.top.optionalTable(
      "simulate", {"mode", "speed_mps", "freq_hz", "theta_deg", "tail_angle_deg", "cycles",
                   "rel_tol", "abs_tol", "separation_abs_tol", "steady_tol", "samples_per_cycle",
                   "sampled_loads", "history_every", "wing_only", "at_trim", "free"});
  SimulateSettings& settings = study.settings.emplace<SimulateSettings>();
  if (!sim) {
    applyWingTolerance(study);
    return;
  }
  SimulationOptions& o = settings.options;
  OperatingPoint& p = study.point;
  o.mode = sim->optionalEnum("mode", o.mode, kModes);
  if (sim->has("free") && o.mode != FlightMode::kFree)
    throw InputError::unknownKey(sim->fileOf("free"), sim->lineOf("free"), sim->keyPath("free"),
                                 "[simulate.free] is only allowed with mode = \"free\", this "
                                 "[simulate] is mode = \"tethered\"");
  if (std::optional<TableReader> free = sim->optionalTable("free", kFreeKeys))
    readFreeFlightTable(*free, o.free);
  p.speed_mps = sim->optionalDouble(field("simulate.speed_mps"), p.speed_mps);
  p.freq_hz = sim->optionalDouble(field("simulate.freq_hz"), p.freq_hz);
  readDegrees(*sim, "simulate.theta_deg", p.theta_rad);
  readDegrees(*sim, "simulate.tail_angle_deg", p.tail_angle_rad);
  // 0 is what a resolved study writes for a tail-less rig; any other angle would be ignored.
  if (sim->has("tail_angle_deg") && !study.vehicle.tail.present && p.tail_angle_rad != 0.0)
    throw sim->valueError("tail_angle_deg",
                          "0 or no tail angle: the vehicle has no [tail] (a tail angle would be "
                          "silently ignored)",
                          describeNode(*sim->table().get("tail_angle_deg")));
  o.cycles = sim->optionalInt(field("simulate.cycles"), o.cycles);
  readTolerances(*sim, o, "simulate");
  settings.rel_tol_given = sim->has("rel_tol");
  o.samples_per_cycle = sim->optionalInt(field("simulate.samples_per_cycle"), o.samples_per_cycle);
  o.interpolate_sampled_loads =
      sim->optionalEnum("sampled_loads", o.interpolate_sampled_loads, kSampledLoads);
  settings.history_every =
      sim->optionalInt(field("simulate.history_every"), settings.history_every);
  settings.wing_only = sim->optionalBool("wing_only", settings.wing_only);
  settings.at_trim = sim->optionalBool("at_trim", settings.at_trim);
  if (settings.at_trim && !study.vehicle.body.present)
    throw sim->valueError("at_trim", "false for a vehicle without [body] (no weight to trim)",
                          "true");
  if (settings.wing_only && o.mode == FlightMode::kFree)
    throw sim->valueError("wing_only", "false in free flight (the main wing alone cannot fly)",
                          "true");
  std::string why;
  if (!o.IsValid(&why)) throwInvalidOptions(*sim, why);
  if (o.mode == FlightMode::kFree && !study.vehicle.body.present)
    throw sim->valueError("mode",
                          "\"tethered\" for a vehicle without a [body] table (free flight "
                          "needs the vehicle's mass and pitch inertia)",
                          "\"free\"");
  sim->finish();
  applyWingTolerance(study);
}

void applyWingTolerance(Study& study) {
  SimulateSettings& settings = study.simulate();
  const WingModel& wing = study.vehicle.wing;
  const bool nonlinear = wing.structure == StructureLevel::kFlexible && wing.fe.nonlinear;
  if (settings.options.mode == FlightMode::kFree && nonlinear && !settings.rel_tol_given)
    settings.options.rel_tol = kNonlinearWingFreeFlightRelTol;
}

void writeSimulateSection(const SimulateSettings& settings, const OperatingPoint& p,
                          TomlWriter& out) {
  const SimulationOptions& o = settings.options;
  out.header({"simulate"});
  out.string("mode", o.mode == FlightMode::kFree ? "free" : "tethered");
  out.number("speed_mps", p.speed_mps);
  out.number("freq_hz", p.freq_hz);
  out.scaled("theta_deg", p.theta_rad, orni::kDegToRad);
  out.scaled("tail_angle_deg", p.tail_angle_rad, orni::kDegToRad);
  out.integer("cycles", o.cycles);
  writeTolerances(o, out);
  out.integer("samples_per_cycle", o.samples_per_cycle);
  if (o.mode == FlightMode::kTethered)
    out.string("sampled_loads", o.interpolate_sampled_loads ? "interpolated" : "evaluated");
  out.integer("history_every", settings.history_every);
  if (o.mode == FlightMode::kTethered)
    out.boolean("wing_only", settings.wing_only,
                "true = the main wing alone (no tail, no body drag)");
  out.boolean("at_trim", settings.at_trim,
              "true = at the trim point at freq_hz (speed, theta, tail: the initial guess)");
  if (o.mode == FlightMode::kFree) writeFreeFlightTable(o.free, {"simulate", "free"}, out);
}

}  // namespace orni::studies
