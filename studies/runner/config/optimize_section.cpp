#include "studies/runner/config/optimize_section.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/model/frames.hpp"
#include "core/model/vehicle_validation.hpp"
#include "studies/runner/config/trim_section.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni::studies {

namespace {

using orni::field;
using orni::opt::Algorithm;
using orni::opt::DesignField;
using orni::opt::DesignObjective;
using orni::opt::DesignVariable;

const std::vector<std::pair<std::string, Algorithm>> kAlgorithms = {
    {"cobyla", Algorithm::kCobyla}, {"bobyqa", Algorithm::kBobyqa}, {"isres", Algorithm::kIsres}};
const std::vector<std::pair<std::string, DesignObjective>> kObjectives = {
    {"power", DesignObjective::kPower},
    {"pitch_amplitude", DesignObjective::kPitchAmplitude},
    {"weighted", DesignObjective::kWeighted}};

const std::vector<std::string> kVariableKeys = {"name", "fields", "lower", "upper", "initial"};
const std::vector<std::string> kConstraintKeys = {"bounded", "pitch_amplitude_max_deg",
                                                  "tip_deflection_max_m", "structural_mass_max_kg",
                                                  "floquet_max_modulus"};
const std::vector<std::string> kWeightKeys = {"power_per_W", "pitch_amplitude_per_deg"};

bool isVariableNameChar(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.' || c == '*';
}

/// A key only meaningful for isres: rejected (named) for the other algorithms.
void rejectUnlessIsres(const TableReader& r, std::string_view key, Algorithm a) {
  if (a == Algorithm::kIsres || !r.has(key)) return;
  throw InputError::unknownKey(r.fileOf(key), r.lineOf(key), r.keyPath(key),
                               "only used by algorithm = \"isres\", this study uses \"" +
                                   std::string(orni::opt::toString(a)) + "\"");
}

std::vector<std::string> readFieldNames(TableReader& v, const std::string& name) {
  const toml::node* n = v.take("fields");
  if (!n) return {name};
  const std::string expected = "a non-empty array of design field names";
  const toml::array* a = n->as_array();
  if (!a || a->empty()) throw v.valueError("fields", expected, describeNode(*n));
  std::vector<std::string> names;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const auto* s = a->get(i)->as_string();
    if (!s)
      throw v.valueError("fields", expected,
                         describeNode(*a->get(i)) + " at index " + std::to_string(i));
    names.push_back(s->get());
  }
  return names;
}

DesignVariable readVariable(TableReader& v, const orni::VehicleModel& vehicle,
                            std::set<std::string>* names, std::set<std::string>* fields_used) {
  DesignVariable var;
  var.name = v.requiredString("name");
  for (const char c : var.name)
    if (!isVariableNameChar(c))
      throw v.valueError("name", "a name of letters, digits, '_', '-', '.' and '*'",
                         describeNode(*v.table().get("name")));
  if (!names->insert(var.name).second)
    throw v.valueError("name", "a name not used by another variable",
                       describeNode(*v.table().get("name")) + " twice");
  const std::string field_key = v.has("fields") ? "fields" : "name";
  var.field_names = readFieldNames(v, var.name);
  for (const std::string& f : var.field_names) {
    std::string why;
    std::vector<DesignField> resolved;
    if (!orni::opt::resolveDesignField(f, vehicle, &resolved, &why))
      throw v.valueError(field_key, "a design field of this vehicle",
                         TomlWriter::stringText(f) + ": " + why);
    for (const DesignField& d : resolved) {
      if (!fields_used->insert(d.name).second)
        throw v.valueError(field_key, "fields not set by another variable",
                           TomlWriter::stringText(f) + " (" + d.name + " twice)");
      var.fields.push_back(d);
    }
  }
  // Bounds and initial value inside the range of every field the variable sets (the field
  // table's entry of its vehicle key; SI = file units for every design field).
  auto inFieldRanges = [&](const char* key, double value) {
    for (const DesignField& d : var.fields) {
      const orni::FieldSpec& spec = d.spec();
      if (!spec.range.contains(value))
        throw v.valueError(key,
                           spec.range.describe() + " (the range of " + d.name +
                               (d.name == spec.key ? "" : ", " + std::string(spec.key)) + ")",
                           sourceText(*v.table().get(key)));
    }
    return value;
  };
  var.lower = inFieldRanges("lower", v.requiredDouble("lower", Range::any()));
  var.upper = inFieldRanges("upper", v.requiredDouble("upper", Range::any()));
  if (!(var.lower < var.upper))
    throw v.valueError("upper", "an upper bound > lower = " + orni::displayNumber(var.lower),
                       orni::displayNumber(var.upper));
  const std::string interval =
      "[" + orni::displayNumber(var.lower) + ", " + orni::displayNumber(var.upper) + "]";
  if (std::optional<double> initial = v.maybeDouble("initial", Range::any())) {
    inFieldRanges("initial", *initial);
    if (!(*initial >= var.lower && *initial <= var.upper))
      throw v.valueError("initial", "an initial value inside " + interval,
                         sourceText(*v.table().get("initial")));
    var.initial = *initial;
  } else {
    const double value = orni::opt::fieldValue(vehicle, var.fields.front());
    for (const DesignField& d : var.fields)
      if (orni::opt::fieldValue(vehicle, d) != value)
        throw v.missingError("initial",
                             "an initial value: the vehicle's values of the group differ (" +
                                 var.fields.front().name + " = " + orni::displayNumber(value) +
                                 ", " + d.name + " = " +
                                 orni::displayNumber(orni::opt::fieldValue(vehicle, d)) +
                                 ")");
    if (!(value >= var.lower && value <= var.upper))
      throw v.valueError("lower", "bounds " + interval + " containing the vehicle's value " +
                                      orni::displayNumber(value) + " (or an initial value)",
                         interval);
    var.initial = value;
  }
  v.finish();
  return var;
}

}  // namespace

std::vector<std::string> optimizeSectionKeys() {
  return {"algorithm",      "objective",   "max_evaluations", "starts",
          "seed",           "freq_hz",     "initial_step",    "xtol",
          "ftol_rel",       "constraint_tol", "warm_start",   "polish_evaluations",
          "population",     "variables",   "constraints",     "weights",
          "trim"};
}

OptimizeSettings readOptimizeSection(TableReader& r, const orni::VehicleModel& vehicle,
                                     const orni::OperatingPoint& design_point) {
  OptimizeSettings s;
  orni::opt::OptimizerOptions& o = s.optimizer;
  orni::opt::DesignProblemOptions& p = s.problem;

  o.algorithm = r.optionalEnum("algorithm", o.algorithm, kAlgorithms);
  p.objective = r.optionalEnum("objective", p.objective, kObjectives);
  o.max_evaluations = r.optionalInt(field("optimize.max_evaluations"), o.max_evaluations);
  o.starts = r.optionalInt(field("optimize.starts"), o.starts);
  o.seed = r.optionalInt(field("optimize.seed"), static_cast<int>(o.seed));
  const double freq_hz =
      r.optionalDouble(field("optimize.freq_hz"), design_point.freq_hz);
  o.initial_step = r.optionalDouble(field("optimize.initial_step"), o.initial_step);
  o.xtol = r.optionalDouble(field("optimize.xtol"), o.xtol);
  o.ftol_rel = r.optionalDouble(field("optimize.ftol_rel"), o.ftol_rel);
  o.constraint_tol = r.optionalDouble(field("optimize.constraint_tol"), o.constraint_tol);
  p.warm_start = r.optionalBool("warm_start", p.warm_start);
  rejectUnlessIsres(r, "polish_evaluations", o.algorithm);
  rejectUnlessIsres(r, "population", o.algorithm);
  o.polish_evaluations = r.optionalInt(field("optimize.polish_evaluations"), o.polish_evaluations);
  if (o.polish_evaluations > o.max_evaluations - 1)
    throw r.valueError("polish_evaluations",
                       "an integer in [0, " + std::to_string(o.max_evaluations - 1) +
                           "] (below max_evaluations)",
                       sourceText(*r.table().get("polish_evaluations")));
  o.population = r.optionalInt(field("optimize.population"), o.population);
  if (o.population == 1)
    throw r.valueError("population", "0 (automatic) or a size in [2, 100000]", "1");

  // Design variables.
  const toml::node* vars_node = r.table().get("variables");
  if (!vars_node)
    throw r.missingError("variables", "an array of design variables [[optimize.variables]] with "
                                      "name, lower, upper (fields, initial optional)");
  std::vector<TableReader> vars = r.optionalTableArray("variables", kVariableKeys);
  if (vars.empty())
    throw r.valueError("variables", "at least one design variable", "an empty array");
  std::set<std::string> names, fields_used;
  for (TableReader& v : vars) s.space.variables.push_back(readVariable(v, vehicle, &names, &fields_used));
  if (o.algorithm == Algorithm::kBobyqa && s.space.size() < 2)
    throw r.valueError("algorithm", "\"cobyla\" or \"isres\" for a single variable (bobyqa needs "
                                    "at least 2)",
                       "\"bobyqa\"");

  // The initial design must be a valid vehicle.
  std::vector<double> x0;
  for (const DesignVariable& v : s.space.variables) x0.push_back(v.initial);
  const std::vector<orni::ModelProblem> problems =
      orni::vehicleProblems(orni::opt::applyDesign(vehicle, s.space, x0));
  if (!problems.empty())
    throw r.valueError("variables", "initial values that form a valid vehicle",
                       "a design with " + problems.front().message());

  // Constraints.
  if (std::optional<TableReader> c = r.optionalTable("constraints", kConstraintKeys)) {
    orni::opt::DesignConstraints& k = p.constraints;
    k.bounded = c->optionalBool("bounded", k.bounded);
    if (auto d = c->maybeDouble(field("optimize.constraints.pitch_amplitude_max_deg")))
      k.pitch_amplitude_max_rad = *d * orni::kDegToRad;
    k.tip_deflection_max_m = c->optionalDouble(field("optimize.constraints.tip_deflection_max_m"),
                                               k.tip_deflection_max_m);
    k.structural_mass_max_kg = c->optionalDouble(
        field("optimize.constraints.structural_mass_max_kg"), k.structural_mass_max_kg);
    k.floquet_max_modulus = c->optionalDouble(field("optimize.constraints.floquet_max_modulus"),
                                              k.floquet_max_modulus);
    if (k.tip_deflection_max_m > 0.0 && vehicle.wing.structure != orni::StructureLevel::kFlexible)
      throw c->valueError("tip_deflection_max_m",
                          "0 (off) for a rigid wing (set wing.structure = \"flexible\")",
                          sourceText(*c->table().get("tip_deflection_max_m")));
    c->finish();
  }

  // Weights (weighted objective only).
  if (r.has("weights") && p.objective != DesignObjective::kWeighted)
    throw InputError::unknownKey(r.fileOf("weights"), r.lineOf("weights"), r.keyPath("weights"),
                                 "[optimize.weights] is only used with objective = \"weighted\"");
  if (std::optional<TableReader> w = r.optionalTable("weights", kWeightKeys)) {
    p.weights.power_per_W =
        w->optionalDouble(field("optimize.weights.power_per_W"), p.weights.power_per_W);
    p.weights.pitch_amplitude_per_deg = w->optionalDouble(
        field("optimize.weights.pitch_amplitude_per_deg"), p.weights.pitch_amplitude_per_deg);
    if (p.weights.power_per_W + p.weights.pitch_amplitude_per_deg <= 0.0)
      throw w->valueError("power_per_W", "weights with a positive sum", "both 0");
    w->finish();
  }

  // The trim of every evaluation: [optimize.trim] without freq_hz (that is optimize.freq_hz).
  orni::OperatingPoint at_freq = design_point;
  at_freq.freq_hz = freq_hz;
  std::optional<TableReader> trim = r.optionalTable("trim", trimSectionKeys());
  if (trim && trim->has("freq_hz"))
    throw InputError::unknownKey(trim->fileOf("freq_hz"), trim->lineOf("freq_hz"),
                                 trim->keyPath("freq_hz"),
                                 "the trim frequency of an optimisation is optimize.freq_hz");
  if (trim) {
    p.trim = readTrimSection(*trim, at_freq);
  } else {
    toml::table empty;
    TableReader none(empty, r.path().empty() ? "trim" : r.path() + ".trim", r.context(),
                     trimSectionKeys());
    p.trim = readTrimSection(none, at_freq);
  }
  // The design point itself stays the file's (the periodic orbit's tolerance scale).
  p.trim.design_point = design_point;
  r.finish();

  if (p.constraints.floquet_max_modulus > 0.0 &&
      !(p.trim.method == orni::TrimMethod::kPeriodic && p.trim.periodic.floquet)) {
    TableReader c = r.requiredTable("constraints", kConstraintKeys);
    throw c.valueError("floquet_max_modulus",
                       "0 (off) unless [optimize.trim] has method = \"periodic\" with its Floquet "
                       "analysis on (the multipliers come from the periodic orbit)",
                       sourceText(*c.table().get("floquet_max_modulus")));
  }
  std::string why;
  if (!p.IsValid(&why)) throw r.valueError("objective", "a consistent design problem", why);
  o.threads = 1;
  if (!o.IsValid(&why)) throw r.valueError("max_evaluations", "valid optimizer options", why);
  return s;
}

void writeOptimizeSection(const OptimizeSettings& s, TomlWriter& out) {
  const orni::opt::OptimizerOptions& o = s.optimizer;
  const orni::opt::DesignProblemOptions& p = s.problem;
  out.header({"optimize"});
  out.string("algorithm", orni::opt::toString(o.algorithm));
  out.string("objective", orni::opt::toString(p.objective),
             std::string("unit ") + orni::opt::objectiveUnit(p.objective));
  out.integer("max_evaluations", o.max_evaluations, "per start, every stage included");
  out.integer("starts", o.starts);
  out.integer("seed", o.seed);
  out.number("freq_hz", p.trim.initial.freq_hz, "flapping frequency of the trim");
  out.number("initial_step", o.initial_step, "fraction of each variable's range");
  out.number("xtol", o.xtol, "fraction of each variable's range");
  out.number("ftol_rel", o.ftol_rel);
  out.number("constraint_tol", o.constraint_tol);
  out.boolean("warm_start", p.warm_start);
  if (o.algorithm == Algorithm::kIsres) {
    out.integer("polish_evaluations", o.polish_evaluations,
                "0 = max_evaluations / 4 (" + std::to_string(o.polishEvaluations()) + ")");
    out.integer("population", o.population, "0 = NLopt's default 20 (n + 1)");
  }
  const orni::opt::DesignConstraints& c = p.constraints;
  out.header({"optimize", "constraints"});
  out.boolean("bounded", c.bounded, "free flight bounded (paper Eq. 5); the trim is always required");
  out.scaled("pitch_amplitude_max_deg", c.pitch_amplitude_max_rad, orni::kDegToRad, "0 = off");
  out.number("tip_deflection_max_m", c.tip_deflection_max_m, "0 = off");
  out.number("structural_mass_max_kg", c.structural_mass_max_kg, "0 = off; both wings");
  if (c.floquet_max_modulus > 0.0)  // written only when on: the resolved files of earlier runs hold
    out.number("floquet_max_modulus", c.floquet_max_modulus,
               "largest |mu| of the trimmed orbit (trim method \"periodic\")");
  if (p.objective == DesignObjective::kWeighted) {
    out.header({"optimize", "weights"});
    out.number("power_per_W", p.weights.power_per_W);
    out.number("pitch_amplitude_per_deg", p.weights.pitch_amplitude_per_deg);
  }
  writeTrimSection(p.trim, out, {"optimize", "trim"}, false);
  for (const DesignVariable& v : s.space.variables) {
    out.arrayHeader({"optimize", "variables"});
    out.string("name", v.name);
    std::vector<std::string> resolved;
    for (const DesignField& f : v.fields) resolved.push_back(f.name);
    out.stringArray("fields", resolved);
    out.number("lower", v.lower);
    out.number("upper", v.upper);
    out.number("initial", v.initial);
  }
}

}  // namespace orni::studies
