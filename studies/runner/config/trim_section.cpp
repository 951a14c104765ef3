#include "studies/runner/config/trim_section.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "core/model/frames.hpp"

namespace orni::studies {

namespace {

using orni::TrimBounds;
using orni::TrimOptions;
using orni::TrimUnknown;

std::vector<std::string> unknownNames() {
  std::vector<std::string> names;
  for (TrimUnknown u : orni::kAllTrimUnknowns) names.emplace_back(orni::trimUnknownName(u));
  return names;
}

std::string quotedList(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i)
    s += (i ? ", " : "") + TomlWriter::stringText(names[i]);
  return s;
}

using orni::field;

/// The field-table entry of an unknown's initial value ("trim.initial.speed_mps", or
/// "trim.freq_hz" for the frequency) and of its bounds ("trim.bounds.speed_mps").
const orni::FieldSpec& initialField(TrimUnknown u) {
  if (u == TrimUnknown::kFreq) return field("trim.freq_hz");
  return field(std::string("trim.initial.") + orni::trimUnknownName(u));
}
const orni::FieldSpec& boundsField(TrimUnknown u) {
  return field(std::string("trim.bounds.") + orni::trimUnknownName(u));
}

std::string intervalText(double lo, double hi) {
  return "[" + orni::displayNumber(lo) + ", " + orni::displayNumber(hi) + "]";
}

/// File-unit value that converts back to exactly `si` (see TomlWriter::scaled).
double fileValue(double si, double scale) { return std::stod(TomlWriter::scaledText(si, scale)); }

std::vector<TrimUnknown> readUnknowns(TableReader& trim) {
  const std::vector<std::string> names = unknownNames();
  const std::string expected = "an array of 1 to 3 distinct names from " + quotedList(names);
  const toml::node* n = trim.take("unknowns");
  if (!n) return TrimOptions().unknowns;
  const toml::array* a = n->as_array();
  if (!a || a->empty() || a->size() > 3)
    throw trim.valueError("unknowns", expected, describeNode(*n));
  std::vector<TrimUnknown> unknowns;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    const std::string at = " at index " + std::to_string(i);
    const auto* s = e.as_string();
    if (!s) throw trim.valueError("unknowns", expected, describeNode(e) + at);
    const auto it = std::find(names.begin(), names.end(), s->get());
    if (it == names.end()) {
      std::string got = describeNode(e) + at;
      const std::string near = closestMatch(s->get(), names);
      if (!near.empty()) got += " (did you mean " + TomlWriter::stringText(near) + "?)";
      throw trim.valueError("unknowns", expected, got);
    }
    const TrimUnknown u = orni::kAllTrimUnknowns[static_cast<std::size_t>(it - names.begin())];
    if (std::find(unknowns.begin(), unknowns.end(), u) != unknowns.end())
      throw trim.valueError("unknowns", expected, describeNode(e) + " twice");
    unknowns.push_back(u);
  }
  return unknowns;
}

std::vector<std::pair<std::string, orni::TrimMethod>> methodChoices() {
  return {{"two_stage", orni::TrimMethod::kTwoStage}, {"periodic", orni::TrimMethod::kPeriodic}};
}

std::vector<std::pair<std::string, orni::PeriodicControl>> controlChoices() {
  return {{"tail_angle_deg", orni::PeriodicControl::kTailAngle},
          {"freq_hz", orni::PeriodicControl::kFrequency},
          {"cg_shift_m", orni::PeriodicControl::kCgPosition}};
}

// [trim.periodic] into o.periodic.
void readPeriodicTable(TableReader& t, orni::PeriodicTrimOptions* o) {
  o->control = t.optionalEnum("control", o->control, controlChoices());
  o->residual_tol = t.optionalDouble(field("trim.periodic.residual_tol"), o->residual_tol);
  o->rel_tol = t.optionalDouble(field("trim.periodic.rel_tol"), o->rel_tol);
  o->max_iterations = t.optionalInt(field("trim.periodic.max_iterations"), o->max_iterations);
  o->history_samples = t.optionalInt(field("trim.periodic.history_samples"), o->history_samples);
  o->floquet = t.optionalBool("floquet", o->floquet);
  o->multipliers = t.optionalInt(field("trim.periodic.multipliers"), o->multipliers);
  o->multiplier_check = t.optionalBool("multiplier_check", o->multiplier_check);
  t.finish();
}

const std::vector<std::string> kPeriodicKeys = {"control",         "residual_tol", "rel_tol",
                                                "max_iterations",  "history_samples",
                                                "floquet",         "multipliers",
                                                "multiplier_check"};

}  // namespace

std::vector<std::string> trimSectionKeys() {
  return {"freq_hz",      "unknowns", "initial",    "bounds",     "max_iterations",
          "residual_tol", "function_tol", "rel_tol", "steady_tol", "max_cycles",
          "derivative_cycles", "refine_in_free_flight", "refine_cycles", "method", "periodic"};
}

void rejectPeriodicMethod(TableReader& trim, const std::string& where) {
  if (!trim.has("method")) return;
  const orni::TrimMethod m = trim.requiredEnum("method", methodChoices());
  if (m == orni::TrimMethod::kPeriodic)
    throw trim.valueError("method", "\"two_stage\" (" + where +
                                        " runs the two-stage trim; periodic trims in " + where +
                                        " are not available yet)",
                          "\"periodic\"");
}

orni::TrimOptions readTrimSection(TableReader& trim, const orni::OperatingPoint& design_point) {
  TrimOptions o = orni::defaultTrimOptions(design_point);
  const std::vector<std::string> names = unknownNames();
  if (trim.optionalEnum("method", orni::TrimMethod::kTwoStage, methodChoices()) ==
      orni::TrimMethod::kPeriodic)
    orni::usePeriodicMethod(&o);
  const bool periodic = o.method == orni::TrimMethod::kPeriodic;
  if (periodic) {
    for (const char* key : {"refine_in_free_flight", "refine_cycles"})
      if (trim.has(key))
        throw InputError::unknownKey(trim.fileOf(key), trim.lineOf(key), trim.keyPath(key),
                                     "it belongs to method = \"two_stage\"; this trim's method is "
                                     "\"periodic\" (settings in [trim.periodic])");
    if (std::optional<TableReader> t = trim.optionalTable("periodic", kPeriodicKeys))
      readPeriodicTable(*t, &o.periodic);
  } else if (trim.has("periodic")) {
    throw InputError::unknownKey(trim.fileOf("periodic"), trim.lineOf("periodic"),
                                 trim.keyPath("periodic"),
                                 "[trim.periodic] applies to method = \"periodic\"; this trim's "
                                 "method is \"two_stage\"");
  }

  o.initial.freq_hz = trim.optionalDouble(field("trim.freq_hz"), o.initial.freq_hz);
  o.unknowns = readUnknowns(trim);

  // Initial guess (and fixed values) of theta, U and delta_T; the frequency is freq_hz.
  std::optional<TableReader> initial =
      trim.optionalTable("initial", {"theta_mean_deg", "speed_mps", "tail_angle_deg"});
  if (initial) {
    for (TrimUnknown u : {TrimUnknown::kThetaMean, TrimUnknown::kSpeed, TrimUnknown::kTailAngle}) {
      if (auto v = initial->maybeDouble(initialField(u)))
        orni::setUnknownValue(&o.initial, u, *v * orni::trimUnknownScale(u));
    }
    initial->finish();
  }

  // Bounds per unknown: [lower, upper].
  std::optional<TableReader> bounds =
      trim.optionalTable("bounds", std::vector<std::string>(names.begin(), names.end()));
  if (bounds) {
    for (TrimUnknown u : orni::kAllTrimUnknowns) {
      const char* name = orni::trimUnknownName(u);
      if (!bounds->has(name)) {
        bounds->take(name);
        continue;
      }
      const std::vector<double> b = bounds->requiredPair(boundsField(u));
      if (!(b[0] < b[1]))
        throw bounds->valueError(name, "[lower, upper] with lower < upper",
                                 intervalText(b[0], b[1]));
      const double scale = orni::trimUnknownScale(u);
      const std::size_t i = static_cast<std::size_t>(orni::trimIndex(u));
      if (!(o.fd_steps[i] <= 0.25 * (b[1] - b[0]) * scale))
        throw bounds->valueError(name,
                                 "an interval at least four finite-difference steps wide (" +
                                     orni::displayNumber(4.0 * o.fd_steps[i] / scale) + " " +
                                     orni::trimUnknownUnit(u) + ")",
                                 intervalText(b[0], b[1]));
      o.bounds[i] = TrimBounds{b[0] * scale, b[1] * scale};
    }
    bounds->finish();
  }

  // Every unknown's initial value inside its bounds; the error names the key that was given.
  for (TrimUnknown u : o.unknowns) {
    const char* name = orni::trimUnknownName(u);
    const double scale = orni::trimUnknownScale(u);
    const TrimBounds& b = o.bounds[static_cast<std::size_t>(orni::trimIndex(u))];
    const double v = orni::unknownValue(o.initial, u);
    if (v >= b.lower && v <= b.upper) continue;
    const std::string interval = intervalText(fileValue(b.lower, scale), fileValue(b.upper, scale));
    const std::string value = orni::displayNumber(fileValue(v, scale));
    if (u == TrimUnknown::kFreq && trim.has("freq_hz"))
      throw trim.valueError("freq_hz", "an initial frequency inside bounds " + interval, value);
    if (initial && initial->has(name))
      throw initial->valueError(name, "an initial value inside bounds " + interval, value);
    if (bounds && bounds->has(name))
      throw bounds->valueError(name,
                               "bounds containing the initial value " + value +
                                   " (the vehicle's operating point)",
                               interval);
    throw trim.valueError(u == TrimUnknown::kFreq ? "freq_hz" : "initial",
                          std::string("an initial ") + name + " inside the default bounds " +
                              interval,
                          value + " (the vehicle's operating point)");
  }

  o.max_iterations = trim.optionalInt(field("trim.max_iterations"), o.max_iterations);
  o.residual_tol = trim.optionalDouble(field("trim.residual_tol"), o.residual_tol);
  o.function_tol = trim.optionalDouble(field("trim.function_tol"), o.function_tol);
  o.simulation.rel_tol = trim.optionalDouble(field("trim.rel_tol"), o.simulation.rel_tol);
  o.simulation.steady_tol = trim.optionalDouble(field("trim.steady_tol"), o.simulation.steady_tol);
  o.simulation.cycles = trim.optionalInt(field("trim.max_cycles"), o.simulation.cycles);
  o.derivative_cycles = trim.optionalInt(field("trim.derivative_cycles"), o.derivative_cycles);
  if (!periodic) {  // two-stage keys; with method = "periodic" they were rejected above
    o.refine_in_free_flight = trim.optionalBool("refine_in_free_flight", o.refine_in_free_flight);
    o.refine_cycles = trim.optionalInt(field("trim.refine_cycles"), o.refine_cycles);
  }
  trim.finish();

  std::string why;
  if (!o.IsValid(&why)) {
    // Backstop: the checks above name the key for every case known to fail IsValid.
    const toml::table& t = trim.table();
    const auto& src = t.source();
    throw InputError::wrongValue(src.path ? *src.path : trim.context()->file,
                                 static_cast<int>(src.begin.line), trim.path(),
                                 "valid trim options", why);
  }
  return o;
}

void writeTrimSection(const orni::TrimOptions& o, TomlWriter& out,
                      const std::vector<std::string>& prefix, bool with_freq) {
  auto sub = [&prefix](const char* name) {
    std::vector<std::string> parts = prefix;
    parts.emplace_back(name);
    return parts;
  };
  out.header(prefix);
  if (with_freq)
    out.number("freq_hz", o.initial.freq_hz,
               "fixed, or the initial guess when freq_hz is an unknown");
  std::vector<std::string> unknowns;
  for (TrimUnknown u : o.unknowns) unknowns.emplace_back(orni::trimUnknownName(u));
  out.stringArray("unknowns", unknowns,
                  o.unknowns.size() == 3 ? "square solve" : "least-squares solve");
  out.integer("max_iterations", o.max_iterations);
  out.number("residual_tol", o.residual_tol, "fraction of the weight");
  out.number("function_tol", o.function_tol);
  out.number("rel_tol", o.simulation.rel_tol);
  out.number("steady_tol", o.simulation.steady_tol);
  out.integer("max_cycles", o.simulation.cycles);
  out.integer("derivative_cycles", o.derivative_cycles);
  const bool periodic = o.method == orni::TrimMethod::kPeriodic;
  out.string("method", orni::toString(o.method),
             periodic ? "the periodic orbit of free flight; the keys above set its Eq. (4) start"
                      : "Eq. (4), then level settled free flight");
  if (!periodic) {
    out.boolean("refine_in_free_flight", o.refine_in_free_flight,
                "level settled free flight (trim/free_flight_trim.hpp)");
    out.integer("refine_cycles", o.refine_cycles);
  }
  out.header(sub("initial"));
  for (TrimUnknown u : {TrimUnknown::kThetaMean, TrimUnknown::kSpeed, TrimUnknown::kTailAngle})
    out.scaled(orni::trimUnknownName(u), orni::unknownValue(o.initial, u),
               orni::trimUnknownScale(u));
  if (periodic) {
    const orni::PeriodicTrimOptions& p = o.periodic;
    out.header(sub("periodic"));
    out.string("control", orni::toString(p.control), "the control freed for level flight");
    out.number("residual_tol", p.residual_tol, "max |scaled periodic residual|");
    out.number("rel_tol", p.rel_tol, "step control of the period map's grid");
    out.integer("max_iterations", p.max_iterations);
    out.integer("history_samples", p.history_samples);
    out.boolean("floquet", p.floquet);
    out.integer("multipliers", p.multipliers, "leading multipliers by Arnoldi; 0 = all");
    if (p.multiplier_check)  // written only when on: earlier runs' resolved files stay as they were
      out.boolean("multiplier_check", true, "each multiplier against a 10 times finer grid");
  }
  out.header(sub("bounds"));
  for (TrimUnknown u : orni::kAllTrimUnknowns) {
    const TrimBounds& b = o.bounds[static_cast<std::size_t>(orni::trimIndex(u))];
    const double scale = orni::trimUnknownScale(u);
    out.numberArray(orni::trimUnknownName(u),
                    {fileValue(b.lower, scale), fileValue(b.upper, scale)});
  }
}

}  // namespace orni::studies
