// Sweep studies (kind = "sweep", study_file.hpp): the [sweep] section, its points as studies of
// the run kind, and the resolved study that re-runs the same points.
//
// A point is read exactly like a study file of the run kind in which its axis values were written:
// the sweep text is parsed afresh (so every node keeps its file and line), the values go into
// [override] (vehicle keys) or the run's section (analysis keys), and readStudyRoot does the rest,
// with every check of the ordinary loader. Errors a value causes are reported at its axis.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/grid/sweep_grid.hpp"
#include "core/model/vehicle_fields.hpp"
#include "studies/runner/config/analysis_fields.hpp"
#include "studies/runner/config/study_reader.hpp"
#include "studies/runner/config/trim_section.hpp"

namespace orni::studies {

namespace fs = std::filesystem;

namespace {

const std::vector<std::pair<std::string, StudyKind>> kRuns = {{"trim", StudyKind::kTrim},
                                                              {"simulate", StudyKind::kSimulate}};

/// The run's analysis section ("trim", "simulate").
std::string sectionOf(StudyKind run) { return std::string(toString(run)); }

/// First parts that are study keys or sections, never vehicle keys.
const std::vector<std::string> kStudyNames = {"kind",     "name",     "vehicle", "vehicle_source",
                                              "override", "simulate", "aeromap", "trim",
                                              "optimize", "sweep",    "modes"};

bool isBareKey(std::string_view part) {
  if (part.empty()) return false;
  for (const char c : part) {
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

/// The parts of a dotted key of bare parts ("tail.arm_m" -> {"tail", "arm_m"}); empty when the
/// text is not such a key.
std::vector<std::string> keyParts(const std::string& key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = key.find('.', start);
    const std::string part = key.substr(start, dot == std::string::npos ? dot : dot - start);
    if (!isBareKey(part)) return {};
    parts.push_back(part);
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

std::string keyExpectation(StudyKind run) {
  const std::string s = sectionOf(run);
  return "a vehicle key as in [override] (e.g. \"tail.arm_m\") or a key of [" + s +
         "] prefixed with \"" + s + ".\" (e.g. \"" +
         (run == StudyKind::kTrim ? "trim.freq_hz" : "simulate.speed_mps") + "\")";
}

/// The path of an axis key in the resolved sections ("vehicle.tail.arm_m", "trim.freq_hz").
std::string resolvedPath(const SweepAxis& axis, StudyKind run) {
  return isAnalysisKey(axis.key, run) ? axis.key : "vehicle." + axis.key;
}

/// An axis as read, with the reader of its table (sweep.axes[i]) for messages.
struct AxisInput {
  SweepAxis axis;
  TableReader reader;
};

std::vector<AxisInput> readAxes(TableReader& sweep, StudyKind run) {
  const std::string expected = "an array of 1 to " + std::to_string(kMaxSweepAxes) +
                               " tables { key = \"...\", values = ... }";
  const toml::node* n = sweep.table().get("axes");
  if (!n) throw sweep.missingError("axes", expected);
  const toml::array* a = n->as_array();
  if (!a || a->empty() || a->size() > kMaxSweepAxes)
    throw sweep.valueError("axes", expected, describeNode(*n));
  std::vector<TableReader> readers = sweep.optionalTableArray("axes", {"key", "values"});
  std::vector<AxisInput> axes;
  for (std::size_t i = 0; i < readers.size(); ++i) {
    TableReader& r = readers[i];
    SweepAxis axis;
    axis.key = r.requiredString("key");
    const toml::node& key_node = *r.table().get("key");
    const std::vector<std::string> parts = keyParts(axis.key);
    const std::string section = sectionOf(run);
    if (parts.empty())
      throw r.valueError("key", keyExpectation(run),
                         describeNode(key_node) + " (not a dotted key)");
    if (parts.front() == section && parts.size() < 2)
      throw r.valueError("key", keyExpectation(run),
                         describeNode(key_node) + " (the whole section, not one of its keys)");
    if (parts.front() != section &&
        std::find(kStudyNames.begin(), kStudyNames.end(), parts.front()) != kStudyNames.end()) {
      std::string why = "'" + parts.front() + "' is a key of the study, not of the vehicle";
      if (parts.front() == "vehicle" || parts.front() == "override")
        why = "vehicle keys are written as in [override], without '" + parts.front() + ".'";
      else if (parts.front() == "trim" || parts.front() == "simulate" || parts.front() == "aeromap")
        why = "this sweep runs \"" + section + "\": only [" + section + "] keys can be swept";
      throw r.valueError("key", keyExpectation(run), describeNode(key_node) + " (" + why + ")");
    }
    for (std::size_t j = 0; j < axes.size(); ++j)
      if (axes[j].axis.key == axis.key)
        throw r.valueError(
            "key", "a key that no other axis sweeps",
            describeNode(key_node) + " (also sweep.axes[" + std::to_string(j) + "])");
    // The values of a known key are checked against its field-table entry here, at the axis
    // (the same range as in the file, [override] or the run's section); an unknown key is left to
    // the point's loader, which names it.
    const orni::FieldSpec* spec = orni::findField(axis.key);
    const bool numeric = spec && (spec->type == orni::FieldType::kNumber ||
                                  spec->type == orni::FieldType::kInteger);
    axis.values = numeric ? readGridAxis(r, "values", spec->range,
                                         " (the range of " + axis.key + ")")
                          : readGridAxis(r, "values", Range::any());
    if (numeric && spec->type == orni::FieldType::kInteger)
      for (const double v : axis.values.values)
        if (std::floor(v) != v)
          throw r.valueError("values",
                             "whole numbers in " + spec->range.interval() + " (" + axis.key +
                                 " is an integer)",
                             orni::displayNumber(v));
    r.finish();
    axes.push_back({std::move(axis), std::move(r)});
  }
  return axes;
}

/// Writes `value` at the dotted path `parts` under `table`, creating tables on the way (a whole
/// number as an integer, anything else as a float).
void insertValue(toml::table& table, const std::vector<std::string>& parts, double value) {
  toml::table* t = &table;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* n = t->get(parts[i]);
    if (!n || !n->is_table()) {
      t->insert_or_assign(parts[i], toml::table{});
      n = t->get(parts[i]);
    }
    t = n->as_table();
  }
  constexpr double kExactIntegers = 9007199254740992.0;  // 2^53
  if (std::floor(value) == value && std::abs(value) < kExactIntegers)
    t->insert_or_assign(parts.back(), static_cast<std::int64_t>(value));
  else
    t->insert_or_assign(parts.back(), value);
}

/// The table `name` of `root`, created when absent (an existing non-table is left to the loader's
/// messages by replacing it only when it is not a table).
toml::table& tableAt(toml::table& root, const std::string& name) {
  toml::node* n = root.get(name);
  if (!n || !n->is_table()) {
    root.insert_or_assign(name, toml::table{});
    n = root.get(name);
  }
  return *n->as_table();
}

/// The value of each axis at one point; nullopt = the axis is not applied.
using PointValues = std::vector<std::optional<double>>;

/// The study of kind `run` at a point: `text` parsed afresh, kind set to the run, [sweep] removed,
/// the values written in, read by readStudyRoot.
Study readPoint(const std::string& text, const fs::path& study_file, StudyKind run,
                const std::vector<AxisInput>& axes, const PointValues& values) {
  std::vector<std::pair<std::string, double>> keyed;
  for (std::size_t k = 0; k < axes.size(); ++k)
    if (values[k]) keyed.emplace_back(axes[k].axis.key, *values[k]);
  return readStudyWithValues(text, study_file, run, {"sweep"}, keyed);
}

/// The message of an InputError without its "FILE:LINE: " prefix.
std::string bodyOf(const InputError& e) {
  const std::string what = e.what();
  std::string prefix = e.file().empty() ? std::string("<input>") : e.file();
  if (e.line() > 0) prefix += ":" + std::to_string(e.line());
  prefix += ": ";
  return what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what;
}

/// An error caused by one value of one axis: at its key when the key is what the loader rejects
/// (unknown, or a table without its required keys), else at the value.
[[noreturn]] void throwAxisError(const InputError& e, const AxisInput& in, std::size_t j,
                                 StudyKind run) {
  const std::string body = bodyOf(e);
  const TableReader& r = in.reader;
  // The loader rejecting a table on the axis key's own path (wing.members.LE1.diameter_m: "key
  // 'wing.members': expected an array of tables, got a table") is the key's fault too, not the
  // value's: the message names the key (docs/design.md 3.2).
  const std::string& bad = e.key();
  const bool on_path = !bad.empty() && bad.size() < in.axis.key.size() &&
                       in.axis.key.compare(0, bad.size() + 1, bad + ".") == 0;
  const bool key_fault = on_path || body.rfind("unknown key", 0) == 0 ||
                         body.rfind("missing required key", 0) == 0;
  if (key_fault)
    throw r.valueError("key", keyExpectation(run),
                       describeNode(*r.table().get("key")) + " (" + body + ")");
  const toml::node& values = *r.table().get("values");
  const toml::array* list = values.as_array();
  const toml::node& at = list && j < list->size() ? *list->get(j) : values;
  const int line =
      at.source().begin.line > 0 ? static_cast<int>(at.source().begin.line) : r.lineOf("values");
  throw InputError::wrongValue(r.fileOf("values"), line, r.keyPath("values"),
                               "values valid for \"" + in.axis.key + "\"",
                               orni::displayNumber(in.axis.values.values[j]) + " (" + body + ")");
}

/// Text of the analysis section and vehicle of a point (or the base) as study.resolved.toml
/// writes them.
std::string sectionsText(const Study& study, StudyKind run) {
  TomlWriter out;
  writeStudySections(study, run, out);
  return out.str();
}

/// A key line of the resolved [vehicle]: its path ("vehicle.wing.members.diameter_m" for every
/// member, "vehicle.materials.LE1.density_kgpm3") and the numbers it writes (a pair's two).
struct VehicleLine {
  std::string path;
  std::vector<orni::VehicleNumberRef> numbers;
};

/// The number lines of the resolved [vehicle] of `v`, in the order writeVehicleToml writes them:
/// the field table's (core/model/vehicle_fields.hpp), the keys of a member or material together,
/// element by element. Left out, as the writer leaves them out: the keys of an absent [body] or
/// [tail], and aero.aspect_ratio when 0 (then "from the planform", a comment).
std::vector<VehicleLine> vehicleLines(const orni::VehicleModel& v) {
  const std::vector<orni::VehicleNumber>& numbers = orni::vehicleNumbers();
  std::vector<VehicleLine> lines;
  auto add = [&](const orni::VehicleNumber& n, std::size_t index) {
    if (!n.presentIn(v)) return;
    if (n.key == "aero.aspect_ratio" && !(n.get(v, index) > 0.0)) return;
    if (n.component > 0) {  // a pair's y: on the line of its x
      lines.back().numbers.push_back({&n, index});
      return;
    }
    std::string path = "vehicle." + std::string(n.key);
    if (n.element == orni::VehicleElement::kMember) path.erase(path.find("[]"), 2);
    if (n.element == orni::VehicleElement::kMaterial)
      path.replace(path.find('*'), 1, v.materials.at(index).name);
    lines.push_back({path, {{&n, index}}});
  };
  for (std::size_t i = 0; i < numbers.size();) {
    std::size_t end = i + 1;  // a block of keys of the same array's elements
    if (numbers[i].element != orni::VehicleElement::kNone)
      while (end < numbers.size() && numbers[end].element == numbers[i].element) ++end;
    for (std::size_t e = 0; e < numbers[i].count(v); ++e)
      for (std::size_t k = i; k < end; ++k) add(numbers[k], e);
    i = end;
  }
  return lines;
}

/// The same value as the resolved writer sees it (a sign of zero included).
bool sameValue(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }

/// The written analysis fields of `study`'s section of `run`, in the order of analysisFields.
std::vector<const AnalysisField*> writtenFields(const Study& study, StudyKind run) {
  std::vector<const AnalysisField*> fields;
  for (const AnalysisField& f : analysisFields(run))
    if (f.written(study)) fields.push_back(&f);
  return fields;
}

/// The keys of the base's sections that vary between points although no axis sets them, in the
/// order of the resolved sections. Compared by value: the run's analysis section ([trim],
/// [simulate]) through analysis_fields.hpp's getters, the vehicle's numbers and its design point
/// through the field table's accessors (core/model/vehicle_fields.hpp).
std::vector<std::string> derivedKeys(const Study& base, const std::vector<Study>& points,
                                     StudyKind run, const std::vector<AxisInput>& axes) {
  const std::vector<const AnalysisField*> base_fields = writtenFields(base, run);
  const std::vector<VehicleLine> base_vehicle = vehicleLines(base.vehicle);
  std::vector<bool> varies(base_fields.size(), false);
  std::vector<bool> vehicle_varies(base_vehicle.size(), false);
  // The design point ([vehicle.operating_point]) is written last, after the vehicle's numbers.
  const std::vector<orni::DesignPointNumber>& point_numbers = orni::designPointNumbers();
  std::vector<bool> point_varies(point_numbers.size(), false);
  for (const Study& p : points) {
    // A point of another shape is reported by the loader's self-check.
    if (writtenFields(p, run) != base_fields) continue;
    if (vehicleLines(p.vehicle).size() != base_vehicle.size()) continue;
    for (std::size_t i = 0; i < base_fields.size(); ++i)
      if (!sameAnalysisValue(base_fields[i]->get(p), base_fields[i]->get(base))) varies[i] = true;
    for (std::size_t i = 0; i < base_vehicle.size(); ++i)
      for (const orni::VehicleNumberRef& n : base_vehicle[i].numbers)
        if (!sameValue(n.get(p.vehicle), n.get(base.vehicle))) vehicle_varies[i] = true;
    for (std::size_t i = 0; i < point_numbers.size(); ++i)
      if (!sameValue(point_numbers[i].get(p.design_point), point_numbers[i].get(base.design_point)))
        point_varies[i] = true;
  }
  std::vector<std::string> swept;
  for (const AxisInput& a : axes) swept.push_back(resolvedPath(a.axis, run));
  std::vector<std::string> derived;
  auto note = [&](const std::string& key) {
    if (std::find(swept.begin(), swept.end(), key) == swept.end() &&
        std::find(derived.begin(), derived.end(), key) == derived.end())
      derived.push_back(key);
  };
  for (std::size_t i = 0; i < base_fields.size(); ++i)
    if (varies[i]) note(std::string(base_fields[i]->key));
  for (std::size_t i = 0; i < base_vehicle.size(); ++i)
    if (vehicle_varies[i]) note(base_vehicle[i].path);
  for (std::size_t i = 0; i < point_numbers.size(); ++i)
    if (point_varies[i]) note("vehicle." + std::string(point_numbers[i].key));
  return derived;
}

}  // namespace

Study readStudyWithValues(const std::string& text, const fs::path& study_file, StudyKind run,
                          const std::vector<std::string>& drop,
                          const std::vector<std::pair<std::string, double>>& values) {
  toml::table root = parseTomlText(text, study_file);
  root.insert_or_assign("kind", sectionOf(run));
  for (const std::string& key : drop) root.erase(key);
  for (const auto& [key, value] : values) {
    std::vector<std::string> parts = keyParts(key);
    if (parts.empty()) throw std::invalid_argument("readStudyWithValues: not a dotted key: " + key);
    if (isAnalysisKey(key, run)) {
      parts.erase(parts.begin());
      insertValue(tableAt(root, sectionOf(run)), parts, value);
    } else {
      insertValue(tableAt(root, "override"), parts, value);
    }
  }
  return readStudyRoot(root, study_file);
}

std::vector<std::string> dottedKeyParts(const std::string& key) { return keyParts(key); }

std::string inputErrorBody(const InputError& e) { return bodyOf(e); }

bool isAnalysisKey(const std::string& key, StudyKind run) {
  const std::string prefix = sectionOf(run) + ".";
  return key.compare(0, prefix.size(), prefix) == 0;
}

std::string keyUnit(const std::string& key) {
  static const std::vector<std::pair<std::string, std::string>> kUnits = {
      {"_N_per_m", "N/m"},  {"_kgpm3", "kg/m^3"}, {"_kgm2", "kg m^2"}, {"_m2ps", "m^2/s"},
      {"_mps2", "m/s^2"},
      {"_degps", "deg/s"},  {"_mps", "m/s"},     {"_deg", "deg"},    {"_gpa", "GPa"},
      {"_hz", "Hz"},        {"_kg", "kg"},       {"_m2", "m^2"},     {"_m", "m"},
      {"_s", "s"},          {"_w", "W"},         {"_n", "N"},        {"_nm", "N m"}};
  for (const auto& [suffix, unit] : kUnits)
    if (key.size() > suffix.size() &&
        key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0)
      return unit;
  return "-";
}

Study loadSweepStudy(toml::table& root, const std::string& text, const fs::path& study_file,
                     bool verify_resolved) {
  auto ctx = std::make_shared<ReadContext>();
  ctx->file = displayPath(study_file);
  // Only [sweep] and the section rules are read here; readStudyRoot checks every other key when it
  // reads the base study below.
  TableReader top(root, std::string(), ctx,
                  {"kind", "name", "vehicle", "vehicle_source", "override", "simulate", "aeromap",
                   "trim", "sweep", "output"});
  TableReader sweep = top.requiredTable("sweep", {"run", "axes"});
  const StudyKind run = sweep.requiredEnum("run", kRuns);
  std::vector<AxisInput> axes = readAxes(sweep, run);
  sweep.finish();

  for (const char* section : {"simulate", "trim", "aeromap"}) {
    if (!top.has(section) || section == sectionOf(run)) continue;
    throw InputError::unknownKey(
        top.fileOf(section), top.lineOf(section), section,
        "[" + std::string(section) + "] is not used by this sweep: it runs \"" + sectionOf(run) +
            "\" at every point, with the settings of [" + sectionOf(run) + "]");
  }

  SweepGrid grid;
  for (const AxisInput& a : axes) grid.sizes.push_back(a.axis.values.values.size());
  std::string why;
  if (!grid.IsValid(&why))
    throw sweep.valueError(
        "axes",
        "at most " + std::to_string(kMaxSweepPoints) + " points (the product of the axis sizes)",
        "a larger grid (" + why + ")");

  // The base: the study without the axes. Its errors are ordinary study-file errors.
  const PointValues none(axes.size());
  Study base = readPoint(text, study_file, run, axes, none);

  // Every point, in point order. A failing point is diagnosed by trying its axes one at a time.
  std::vector<Study> points;
  points.reserve(grid.size());
  for (std::size_t index = 0; index < grid.size(); ++index) {
    const std::vector<std::size_t> at = grid.axisIndices(index);
    PointValues values(axes.size());
    for (std::size_t k = 0; k < axes.size(); ++k) values[k] = axes[k].axis.values.values[at[k]];
    try {
      points.push_back(readPoint(text, study_file, run, axes, values));
    } catch (const InputError& e) {
      for (std::size_t k = 0; k < axes.size(); ++k) {
        PointValues one(axes.size());
        one[k] = values[k];
        try {
          (void)readPoint(text, study_file, run, axes, one);
        } catch (const InputError& ek) {
          throwAxisError(ek, axes[k], at[k], run);
        }
      }
      std::string list;
      for (std::size_t k = 0; k < axes.size(); ++k)
        list += (k ? ", " : "") + axes[k].axis.key + " = " + orni::displayNumber(*values[k]);
      throw sweep.valueError("axes", "axes whose every combination is a valid study",
                             "point " + std::to_string(index) + " (" + list + "): " + bodyOf(e));
    }
  }

  Study study = base;
  study.kind = StudyKind::kSweep;
  study.study_path = study_file;
  const SimulateSettings base_simulate =
      run == StudyKind::kSimulate ? base.simulate() : SimulateSettings{};
  SweepSettings& sweep_settings = study.settings.emplace<SweepSettings>();
  sweep_settings.base_simulate = base_simulate;
  sweep_settings.run = run;
  for (const AxisInput& a : axes) sweep_settings.axes.push_back(a.axis);
  sweep_settings.derived_keys = derivedKeys(base, points, run, axes);
  sweep_settings.points = std::move(points);

  if (verify_resolved)  // the contract of study.resolved.toml: it re-runs the same points
    checkResolvedPoints(
        study, study_file, "sweep", [](const Study& s) -> const std::vector<Study>& {
          return s.sweep().points;
        },
        [run](const Study& point) { return sectionsText(point, run); });
  return study;
}

std::string resolvedSweepToml(const Study& study) {
  const SweepSettings& s = study.sweep();
  TomlWriter out;
  writeResolvedOpening(
      study,
      {"Each point is this study with its axis values written in (vehicle keys as",
       "overrides of [vehicle], analysis keys into [" + sectionOf(s.run) + "])."},
      out);
  out.header({"sweep"});
  out.string("run", sectionOf(s.run));
  for (const SweepAxis& a : s.axes) {
    out.arrayHeader({"sweep", "axes"});
    out.string("key", a.key);
    writeGridAxis(out, "values", a.values);
  }

  // The base's sections; keys that follow the swept values are left to their defaults.
  TomlWriter sections;
  sections.leaveOut(s.derived_keys,
                    "not fixed here: its default follows the swept keys at every point");
  writeStudySections(study, s.run, sections);
  const std::string text = out.str() + "\n" + sections.str();
  return text;
}

}  // namespace orni::studies
