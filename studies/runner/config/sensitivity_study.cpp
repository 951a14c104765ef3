// Sensitivity studies (kind = "sensitivity", sensitivity_study.hpp): the [sensitivity] section,
// its points as trim studies, and the resolved study that re-runs the same points.
//
// A point is read exactly like a trim study file in which the parameter's value was written into
// [override] (readStudyWithValues, the machinery of sweep points), so every check of the ordinary
// loader applies; an error a value causes is reported at that value
// ('sensitivity.parameters[2].low' with its line).
#include "studies/runner/config/sensitivity_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "studies/runner/config/study_reader.hpp"
#include "studies/runner/config/trim_section.hpp"

namespace orni::studies {

namespace fs = std::filesystem;

namespace {

/// Top-level keys a sensitivity study may have.
const std::vector<std::string> kTopKeys = {"kind",     "name", "vehicle",    "vehicle_source",
                                           "override", "trim", "sensitivity", "output"};
/// Sections of other kinds: rejected with a message that says what a sensitivity study runs.
const std::vector<std::string> kOtherSections = {"simulate", "aeromap", "sweep", "optimize",
                                                 "calibrate"};
/// First parts of a dotted key that belong to the study, not to the vehicle.
const std::vector<std::string> kStudyNames = {
    "kind", "name",  "vehicle",  "vehicle_source", "override",    "simulate", "aeromap",
    "trim", "sweep", "optimize", "calibrate",      "sensitivity", "modes"};

const char* const kKeyExpected =
    "a vehicle key as in [override] (e.g. \"body.pitch_inertia_kgm2\")";

/// A parameter as read, with the reader of its table (sensitivity.parameters[i]) for messages.
struct ParameterInput {
  SensitivityParameter parameter;
  TableReader reader;
};

/// Why `key` cannot be a sensitivity parameter, or "" when it can (the loader then checks that
/// the vehicle has it).
std::string keyProblem(const std::string& key) {
  const std::vector<std::string> parts = dottedKeyParts(key);
  if (parts.empty()) return "not a dotted key";
  const std::string& first = parts.front();
  if (first == "vehicle" || first == "override")
    return "vehicle keys are written as in [override], without '" + first + ".'";
  if (first == "trim")
    return "the [trim] settings are the same at every point: a sensitivity study moves vehicle "
           "values";
  if (std::find(kStudyNames.begin(), kStudyNames.end(), first) != kStudyNames.end())
    return "'" + first + "' is a key of the study, not of the vehicle";
  if (first == "operating_point")
    return "the operating point is the trim's initial guess, not a property of the vehicle (set "
           "[trim] initial instead)";
  return {};
}

std::vector<ParameterInput> readParameters(TableReader& section) {
  const std::string expected = "an array of 1 to " + std::to_string(kMaxSensitivityParameters) +
                               " tables { key = \"...\", low = ..., high = ... }";
  const toml::node* n = section.table().get("parameters");
  if (!n) throw section.missingError("parameters", expected);
  const toml::array* a = n->as_array();
  if (!a || a->empty() || a->size() > kMaxSensitivityParameters)
    throw section.valueError("parameters", expected, describeNode(*n));
  std::vector<TableReader> readers =
      section.optionalTableArray("parameters", {"key", "low", "high"});
  std::vector<ParameterInput> inputs;
  for (TableReader& r : readers) {
    SensitivityParameter p;
    p.key = r.requiredString("key");
    const toml::node& key_node = *r.table().get("key");
    const std::string problem = keyProblem(p.key);
    if (!problem.empty())
      throw r.valueError("key", kKeyExpected, describeNode(key_node) + " (" + problem + ")");
    for (std::size_t j = 0; j < inputs.size(); ++j)
      if (inputs[j].parameter.key == p.key)
        throw r.valueError(
            "key", "a key that no other parameter moves",
            describeNode(key_node) + " (also sensitivity.parameters[" + std::to_string(j) + "])");
    // Both ends inside the key's field-table range (checked here, at the parameter; an unknown
    // key is left to the point's loader, which names it).
    const orni::FieldSpec* spec = orni::findField(p.key);
    const bool numeric = spec && spec->type == orni::FieldType::kNumber;
    const Range range = numeric ? spec->range : Range::any();
    const std::string note = numeric ? " (the range of " + p.key + ")" : std::string();
    p.low = r.requiredDouble("low", range, note);
    p.high = r.requiredDouble("high", range, note);
    if (!(p.low < p.high))
      throw r.valueError("high", "a number > low (" + orni::displayNumber(p.low) + ")",
                         orni::displayNumber(p.high));
    r.finish();
    inputs.push_back({std::move(p), std::move(r)});
  }
  return inputs;
}

/// An error caused by the value at `end` ("low" or "high") of a parameter: at its key when the key
/// is what the loader rejects (unknown, or a table without its required keys), else at the value.
[[noreturn]] void throwParameterError(const InputError& e, const ParameterInput& in,
                                      const char* end) {
  const std::string body = inputErrorBody(e);
  const TableReader& r = in.reader;
  const bool key_fault =
      body.rfind("unknown key", 0) == 0 || body.rfind("missing required key", 0) == 0;
  if (key_fault)
    throw r.valueError("key", kKeyExpected,
                       describeNode(*r.table().get("key")) + " (" + body + ")");
  const double value = std::string(end) == "low" ? in.parameter.low : in.parameter.high;
  throw r.valueError(end, "a value valid for \"" + in.parameter.key + "\"",
                     orni::displayNumber(value) + " (" + body + ")");
}

/// Text of the [trim] section and vehicle of a point (or the base) as study.resolved.toml writes
/// them.
std::string sectionsText(const Study& study) {
  TomlWriter out;
  writeStudySections(study, StudyKind::kTrim, out);
  return out.str();
}

/// The value of the vehicle key `key` in the resolved form of `study`'s vehicle, file units; NaN
/// when the resolved vehicle does not write it as a number.
double resolvedVehicleValue(const Study& study, const std::string& key) {
  const toml::table root = parseTomlText(sectionsText(study), "resolved vehicle");
  const toml::node* n = root.get("vehicle");
  for (const std::string& part : dottedKeyParts(key)) {
    const toml::table* t = n ? n->as_table() : nullptr;
    n = t ? t->get(part) : nullptr;
  }
  if (n) {
    if (const std::optional<double> v = n->value<double>()) return *v;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

const char* toString(SensitivitySide side) {
  switch (side) {
    case SensitivitySide::kBase:
      return "base";
    case SensitivitySide::kLow:
      return "low";
    case SensitivitySide::kHigh:
      return "high";
  }
  return "base";
}

std::size_t sensitivityPointCount(std::size_t parameters) { return 2 * parameters + 1; }

SensitivityPointId sensitivityPointId(std::size_t index) {
  if (index == 0) return {};
  return {(index - 1) / 2, (index - 1) % 2 == 0 ? SensitivitySide::kLow : SensitivitySide::kHigh};
}

std::size_t sensitivityPointIndex(std::size_t parameter, SensitivitySide side) {
  if (side == SensitivitySide::kBase) return 0;
  return 1 + 2 * parameter + (side == SensitivitySide::kHigh ? 1 : 0);
}

Study loadSensitivityStudy(toml::table& root, const std::string& text, const fs::path& study_file,
                           bool verify_resolved) {
  auto ctx = std::make_shared<ReadContext>();
  ctx->file = displayPath(study_file);
  std::vector<std::string> allowed = kTopKeys;
  allowed.insert(allowed.end(), kOtherSections.begin(), kOtherSections.end());
  // Only [sensitivity] and the section rules are read here; readStudyRoot checks every other key
  // when it reads the base study below.
  TableReader top(root, std::string(), ctx, allowed);
  for (const std::string& section : kOtherSections) {
    if (!top.has(section)) continue;
    throw InputError::unknownKey(
        top.fileOf(section), top.lineOf(section), section,
        "[" + section +
            "] is not used by a sensitivity study: it trims every point with the "
            "settings of [trim] and flies the checks set in [sensitivity]");
  }
  if (top.has("trim")) {
    TableReader t = top.requiredTable("trim", trimSectionKeys());
    rejectPeriodicMethod(t, "a sensitivity study");
  }
  TableReader section =
      top.requiredTable("sensitivity", {"parameters", "free_flight_cycles", "free"});
  std::vector<ParameterInput> inputs = readParameters(section);
  SensitivitySettings settings;
  settings.free_flight_cycles =
      section.optionalInt(orni::field("sensitivity.free_flight_cycles"),
                          settings.free_flight_cycles);
  if (std::optional<TableReader> free = section.optionalTable("free", freeFlightKeys()))
    readFreeFlightTable(*free, settings.free);
  {
    SimulationOptions check;
    check.mode = FlightMode::kFree;
    check.cycles = settings.free_flight_cycles;
    check.free = settings.free;
    std::string why;
    if (!check.IsValid(&why))  // backstop: the getters above check every range
      throw section.valueError("free", "valid free-flight settings", why);
  }
  section.finish();

  // The base: the study without any parameter moved. Its errors are ordinary study-file errors.
  const std::vector<std::string> drop = {"sensitivity"};
  Study base = readStudyWithValues(text, study_file, StudyKind::kTrim, drop, {});

  std::vector<Study> points;
  points.reserve(sensitivityPointCount(inputs.size()));
  points.push_back(base);
  for (ParameterInput& in : inputs) {
    SensitivityParameter& p = in.parameter;
    p.base = resolvedVehicleValue(base, p.key);
    for (const char* end : {"low", "high"}) {
      const double value = std::string(end) == "low" ? p.low : p.high;
      try {
        points.push_back(
            readStudyWithValues(text, study_file, StudyKind::kTrim, drop, {{p.key, value}}));
      } catch (const InputError& e) {
        throwParameterError(e, in, end);
      }
    }
  }

  Study study = base;
  study.kind = StudyKind::kSensitivity;
  study.study_path = study_file;
  for (const ParameterInput& in : inputs) settings.parameters.push_back(in.parameter);
  settings.points = std::move(points);
  study.settings = std::move(settings);

  if (verify_resolved)  // the contract of study.resolved.toml: it re-runs the same points
    checkResolvedPoints(
        study, study_file, "sensitivity study",
        [](const Study& s) -> const std::vector<Study>& { return s.sensitivity().points; },
        [](const Study& point) { return sectionsText(point); });
  return study;
}

std::string resolvedSensitivityToml(const Study& study) {
  const SensitivitySettings& s = study.sensitivity();
  TomlWriter out;
  writeResolvedOpening(
      study,
      {"Point 0 is this vehicle; each parameter adds the vehicle with its key at low and",
       "at high (an override of [vehicle]), each trimmed with [trim]."},
      out);
  out.header({"sensitivity"});
  out.integer("free_flight_cycles", s.free_flight_cycles, "the free flight from every trim");
  for (const SensitivityParameter& p : s.parameters) {
    out.arrayHeader({"sensitivity", "parameters"});
    out.string("key", p.key,
               std::isfinite(p.base) ? "base vehicle: " + formatNumber(p.base) : std::string());
    out.number("low", p.low);
    out.number("high", p.high);
  }
  writeFreeFlightTable(s.free, {"sensitivity", "free"}, out);
  return out.str() + "\n" + sectionsText(study);
}

}  // namespace orni::studies
