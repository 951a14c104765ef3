#include "studies/runner/config/study_file.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/model/frames.hpp"
#include "studies/runner/config/study_reader.hpp"
#include "studies/runner/config/optimize_section.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "studies/runner/config/calibrate_section.hpp"
#include "studies/runner/config/continuation_section.hpp"
#include "studies/runner/config/trim_section.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni::studies {

namespace fs = std::filesystem;

namespace {

using orni::field;

constexpr std::array<std::pair<std::string_view, StudyKind>, 9> kKinds = {{
    {"simulate", StudyKind::kSimulate},
    {"modes", StudyKind::kModes},
    {"aeromap", StudyKind::kAeromap},
    {"trim", StudyKind::kTrim},
    {"optimize", StudyKind::kOptimize},
    {"sweep", StudyKind::kSweep},
    {"calibrate", StudyKind::kCalibrate},
    {"sensitivity", StudyKind::kSensitivity},
    {"continuation", StudyKind::kContinuation},
}};

const std::vector<std::pair<std::string, FlightMode>> kModes = {{"tethered", FlightMode::kTethered},
                                                                {"free", FlightMode::kFree}};

std::vector<std::pair<std::string, StudyKind>> kindChoices() {
  std::vector<std::pair<std::string, StudyKind>> c;
  for (const auto& k : kKinds) c.emplace_back(std::string(k.first), k.second);
  return c;
}

bool isRunNameChar(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.';
}

bool validRunName(const std::string& name) {
  if (name.empty() || name[0] == '.') return false;
  for (const char c : name)
    if (!isRunNameChar(c)) return false;
  return true;
}

/// The file stem as a valid run name (invalid characters become '_').
std::string runNameFromStem(const fs::path& file) {
  std::string name = file.stem().string();
  for (char& c : name)
    if (!isRunNameChar(c)) c = '_';
  if (name.empty() || name[0] == '.') name = "run" + name;
  return name;
}

/// Merges `from` into `into`: tables are merged key by key, everything else is replaced. Nodes are
/// moved, so they keep their source (file and line) for messages.
void mergeOverride(toml::table& into, toml::table& from) {
  for (auto&& [key, node] : from) {
    const std::string k(key.str());
    toml::table* from_table = node.as_table();
    toml::node* target = into.get(k);
    if (from_table && target && target->is_table()) {
      mergeOverride(*target->as_table(), *from_table);
    } else {
      into.insert_or_assign(k, std::move(node));
    }
  }
}

/// SimulationOptions::IsValid says "<field> must be <condition>"; the fields are named like the
/// keys, so the error names the key (or the section header when the default is at fault).
[[noreturn]] void throwInvalidOptions(const TableReader& section, const std::string& why) {
  const std::size_t space = why.find(' ');
  const std::string key = why.substr(0, space);
  const std::string must = " must be ";
  std::string expected = why;
  if (why.compare(space, must.size(), must) == 0)
    expected = "a value " + why.substr(space + must.size());
  const toml::node* n = section.table().get(key);
  throw section.valueError(key, expected, n ? describeNode(*n) : std::string("the default"));
}

/// The integrator tolerances shared by [simulate] and [aeromap] (`section`).
void readTolerances(TableReader& r, SimulationOptions& o, const std::string& section) {
  o.rel_tol = r.optionalDouble(field(section + ".rel_tol"), o.rel_tol);
  o.abs_tol = r.optionalDouble(field(section + ".abs_tol"), o.abs_tol);
  o.separation_abs_tol =
      r.optionalDouble(field(section + ".separation_abs_tol"), o.separation_abs_tol);
  o.steady_tol = r.optionalDouble(field(section + ".steady_tol"), o.steady_tol);
}

/// The value d in file units with d * si_per_file_unit == si exactly, when one exists.
double fileUnits(double si, double si_per_file_unit) {
  const std::string text = TomlWriter::scaledText(si, si_per_file_unit);
  double d = si / si_per_file_unit;
  std::from_chars(text.data(), text.data() + text.size(), d);
  return d;
}

const std::vector<std::string> kFreeKeys = {
    "bound_speed_mps", "bound_W_mps",        "bound_theta_deg",   "bound_Q_degps",
    "bound_h_m",       "transient_fraction", "divergence_ratio", "initial_altitude_m"};

/// [simulate.free] (and [sensitivity.free]): the bounded-norm bounds and the free-flight run
/// settings, in the ranges of the field table's simulate.free.* entries.
void readFreeFlight(TableReader& r, FreeFlightOptions& f) {
  FreeFlightBounds& b = f.bounds;
  b.U_mps = r.optionalDouble(field("simulate.free.bound_speed_mps"), b.U_mps);
  b.W_mps = r.optionalDouble(field("simulate.free.bound_W_mps"), b.W_mps);
  if (auto d = r.maybeDouble(field("simulate.free.bound_theta_deg")))
    b.theta_rad = *d * orni::kDegToRad;
  if (auto d = r.maybeDouble(field("simulate.free.bound_Q_degps")))
    b.Q_radps = *d * orni::kDegToRad;
  b.h_m = r.optionalDouble(field("simulate.free.bound_h_m"), b.h_m);
  f.transient_fraction =
      r.optionalDouble(field("simulate.free.transient_fraction"), f.transient_fraction);
  f.divergence_ratio =
      r.optionalDouble(field("simulate.free.divergence_ratio"), f.divergence_ratio);
  f.initial_altitude_m =
      r.optionalDouble(field("simulate.free.initial_altitude_m"), f.initial_altitude_m);
  r.finish();
}

void readAeromap(TableReader& am, Study& study) {
  AeromapSettings& a = study.settings.emplace<AeromapSettings>();
  a.speed_mps = readGridAxis(am, "speed_mps", field("aeromap.speed_mps").range);
  a.freq_hz = readGridAxis(am, "freq_hz", field("aeromap.freq_hz").range);
  a.theta_deg = readGridAxis(am, "theta_deg", field("aeromap.theta_deg").range);
  if (am.has("tail_angle_deg")) {
    a.tail_angle_deg = readGridAxis(am, "tail_angle_deg", field("aeromap.tail_angle_deg").range);
  } else {
    a.tail_angle_deg.values = {fileUnits(study.point.tail_angle_rad, orni::kDegToRad)};
  }
  std::size_t points = 1;
  for (const GridAxis* axis : {&a.speed_mps, &a.freq_hz, &a.theta_deg, &a.tail_angle_deg}) {
    if (axis->values.size() > kMaxAeroMapPoints / points)
      throw am.valueError("speed_mps",
                          "a grid of at most " + std::to_string(kMaxAeroMapPoints) + " points",
                          "a larger grid");
    points *= axis->values.size();
  }
  a.wing_only = am.optionalBool("wing_only", a.wing_only);
  SimulationOptions& o = a.options;
  o.cycles = am.optionalInt(field("aeromap.cycles"), o.cycles);
  readTolerances(am, o, "aeromap");
  std::string why;
  if (!o.IsValid(&why)) throwInvalidOptions(am, why);
  am.finish();
}

}  // namespace

GridAxis readGridAxis(TableReader& r, std::string_view key, const Range& range,
                      std::string_view note) {
  const bool bounded = std::isfinite(range.lo) || std::isfinite(range.hi);
  const std::string expected = std::string("a grid spec \"A:B:N\" (") + kGridSpecMeaning +
                               "), an array of values or a number" +
                               (bounded ? ", " + range.describe("each value") : std::string()) +
                               std::string(note);
  const toml::node* n = r.take(key);
  if (!n) throw r.missingError(key, expected);
  GridAxis axis;
  if (const auto* text = n->as_string()) {
    GridSpec spec;
    std::string reason;
    if (!tryParseGridSpec(text->get(), &spec, &reason))
      throw r.valueError(key, expected, describeNode(*n) + " (" + reason + ")");
    axis = gridAxis(spec);
    for (const double v : axis.values)
      if (!range.contains(v))
        throw r.valueError(key, expected,
                           describeNode(*n) + " (value " + orni::displayNumber(v) + ")");
  } else if (const toml::array* a = n->as_array()) {
    if (a->empty()) throw r.valueError(key, expected, "an empty array");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::node& e = *a->get(i);
      const std::optional<double> v = e.is_number() ? e.value<double>() : std::nullopt;
      if (!v) throw r.valueError(key, expected, describeNode(e) + " at index " + std::to_string(i));
      if (!range.contains(*v))
        throw InputError::wrongValue(r.fileOf(key),
                                     e.source().begin.line > 0
                                         ? static_cast<int>(e.source().begin.line)
                                         : r.lineOf(key),
                                     r.keyPath(key), expected,
                                     sourceText(e) + " at index " + std::to_string(i));
      axis.values.push_back(*v);
    }
  } else if (n->is_number()) {
    const std::optional<double> v = n->value<double>();
    if (!v || !range.contains(*v)) throw r.valueError(key, expected, sourceText(*n));
    axis.values = {*v};
  } else {
    throw r.valueError(key, expected, describeNode(*n));
  }
  return axis;
}

void writeGridAxis(TomlWriter& out, std::string_view key, const GridAxis& axis) {
  if (axis.spec)
    out.string(key, toString(*axis.spec));
  else
    out.numberArray(key, axis.values);
}

GridAxis gridAxis(const GridSpec& spec) {
  GridAxis axis;
  axis.spec = spec;
  axis.values = gridValues(spec);
  return axis;
}

namespace {

/// The alternative T of study.settings, or a logic_error naming the accessor and the kind.
template <class T, class S>
T& kindSettings(S& study, std::string_view accessor) {
  if (auto* t = std::get_if<std::remove_const_t<T>>(&study.settings)) return *t;
  throw std::logic_error("Study::" + std::string(accessor) + "(): this study is kind \"" +
                         std::string(toString(study.kind)) + "\", it has no [" +
                         std::string(accessor) + "] settings");
}

}  // namespace

const AeromapSettings& Study::aeromap() const {
  return kindSettings<const AeromapSettings>(*this, "aeromap");
}
AeromapSettings& Study::aeromap() { return kindSettings<AeromapSettings>(*this, "aeromap"); }
const orni::CalibrationOptions& Study::calibrate() const {
  return kindSettings<const orni::CalibrationOptions>(*this, "calibrate");
}
orni::CalibrationOptions& Study::calibrate() {
  return kindSettings<orni::CalibrationOptions>(*this, "calibrate");
}
const SweepSettings& Study::sweep() const {
  return kindSettings<const SweepSettings>(*this, "sweep");
}
SweepSettings& Study::sweep() { return kindSettings<SweepSettings>(*this, "sweep"); }
const OptimizeSettings& Study::optimize() const {
  return kindSettings<const OptimizeSettings>(*this, "optimize");
}
OptimizeSettings& Study::optimize() { return kindSettings<OptimizeSettings>(*this, "optimize"); }
const SensitivitySettings& Study::sensitivity() const {
  return kindSettings<const SensitivitySettings>(*this, "sensitivity");
}
SensitivitySettings& Study::sensitivity() {
  return kindSettings<SensitivitySettings>(*this, "sensitivity");
}
const orni::TrimContinuationOptions& Study::continuation() const {
  return kindSettings<const orni::TrimContinuationOptions>(*this, "continuation");
}
orni::TrimContinuationOptions& Study::continuation() {
  return kindSettings<orni::TrimContinuationOptions>(*this, "continuation");
}

std::string_view toString(StudyKind kind) {
  for (const auto& k : kKinds)
    if (k.second == kind) return k.first;
  return "simulate";
}

std::optional<StudyKind> parseStudyKind(std::string_view text) {
  for (const auto& k : kKinds)
    if (k.first == text) return k.second;
  return std::nullopt;
}

Study loadStudyFile(const fs::path& study_file) {
  return loadStudyText(readTomlFileText(study_file), study_file, true);
}

Study loadStudyText(const std::string& text, const fs::path& study_file, bool verify_resolved) {
  toml::table root = parseTomlText(text, study_file);
  const toml::node* kind = root.get("kind");
  if (kind && kind->value<std::string>() == std::string(toString(StudyKind::kSweep)))
    return loadSweepStudy(root, text, study_file, verify_resolved);
  if (kind && kind->value<std::string>() == std::string(toString(StudyKind::kSensitivity)))
    return loadSensitivityStudy(root, text, study_file, verify_resolved);
  return readStudyRoot(root, study_file);
}

namespace {

/// The kinds whose study may hold each top-level section; any other kind's is an error at it.
struct SectionKinds {
  std::string_view section;
  std::vector<StudyKind> kinds;
};

const std::vector<SectionKinds> kSectionKinds = {
    {"simulate", {StudyKind::kSimulate}},
    {"aeromap", {StudyKind::kAeromap}},
    {"trim", {StudyKind::kTrim, StudyKind::kContinuation}},
    {"continuation", {StudyKind::kContinuation}},
    {"calibrate", {StudyKind::kCalibrate}},
    {"optimize", {StudyKind::kOptimize}},
    {"sweep", {StudyKind::kSweep}},
    {"sensitivity", {StudyKind::kSensitivity}},
};

bool isOneOf(StudyKind kind, const std::vector<StudyKind>& kinds) {
  return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
}

/// "[trim] is only allowed in a study of kind "trim" or "continuation", this one is kind ..."
/// at `section` when the study has it but its kind may not.
void rejectSectionOfOtherKind(const TableReader& top, std::string_view section, StudyKind kind) {
  const std::string key(section);
  for (const SectionKinds& s : kSectionKinds) {
    if (s.section != section) continue;
    if (!top.has(key) || isOneOf(kind, s.kinds)) return;
    std::string allowed;
    for (std::size_t i = 0; i < s.kinds.size(); ++i)
      allowed += std::string(i ? " or " : "") + "\"" + std::string(toString(s.kinds[i])) + "\"";
    throw InputError::unknownKey(top.fileOf(key), top.lineOf(key), key,
                                 "[" + key + "] is only allowed in a study of kind " + allowed +
                                     ", this one is kind \"" + std::string(toString(kind)) +
                                     "\"");
  }
  throw std::logic_error("rejectSectionOfOtherKind: no kinds for [" + key + "]");
}

/// An error at 'vehicle' unless the study's vehicle has a [body]; `why` says what needs it.
void requireBody(const TableReader& top, const Study& study, const std::string& why) {
  if (!study.vehicle.body.present)
    throw top.valueError("vehicle", "a vehicle with a [body] section (" + why + ")",
                         "a vehicle without [body]");
}

/// The top-level table, the parsed document and its read context: what a kind's reader reads.
struct StudyDocument {
  TableReader& top;
  toml::table& root;
  const std::shared_ptr<ReadContext>& context;
};

/// The study's vehicle: `vehicle` (a path relative to the study's folder, or an inline table),
/// vehicle_source and [override]; sets study.vehicle, vehicle_path and point.
void readStudyVehicle(StudyDocument doc, const fs::path& study_file, Study& study) {
  TableReader& top = doc.top;
  const std::string study_name = doc.context->file;
  toml::table vehicle_table;
  ReadContext vehicle_ctx;
  std::string vehicle_root_path;
  const std::string vehicle_expected =
      "a vehicle file path relative to the study's folder, or a [vehicle] table";
  const toml::node* vehicle_node = top.take("vehicle");
  const toml::node* source_node = top.take("vehicle_source");
  if (!vehicle_node) throw top.missingError("vehicle", vehicle_expected);
  if (const auto* s = vehicle_node->as_string()) {
    if (source_node)
      throw InputError::unknownKey(top.fileOf("vehicle_source"), top.lineOf("vehicle_source"),
                                   "vehicle_source", "only allowed with an inline [vehicle] table");
    const fs::path given = s->get();
    const fs::path resolved = study_file.parent_path() / given;
    const std::string expected =
        "the path of an existing vehicle file, relative to the study's folder";
    const std::string unreadable = given.empty() ? "no such file" : notARegularFile(resolved);
    if (!unreadable.empty())
      throw top.valueError("vehicle", expected,
                           describeNode(*vehicle_node) + " (" +
                               TomlWriter::stringText(displayPath(resolved)) + ": " +
                               unreadable + ")");
    std::error_code ec;
    if (fs::equivalent(resolved, study_file, ec))
      throw top.valueError("vehicle", expected + ", not the study itself",
                           describeNode(*vehicle_node) + " (this study file)");
    vehicle_table = parseTomlFile(resolved);
    if (vehicle_table.contains("kind"))
      throw top.valueError("vehicle", expected + ", not a study",
                           describeNode(*vehicle_node) + " (" +
                               TomlWriter::stringText(displayPath(resolved)) +
                               " is a study file: it has a top-level 'kind' key)");
    vehicle_ctx.file = displayPath(resolved);
    vehicle_ctx.foreign_file = study_name;
    vehicle_ctx.foreign_prefix = "override.";
    study.vehicle_path = given;
  } else if (toml::table* t = doc.root.get("vehicle")->as_table()) {
    vehicle_table = std::move(*t);
    vehicle_ctx.file = study_name;
    vehicle_root_path = "vehicle";
    if (source_node) study.vehicle_path = top.requiredString("vehicle_source");
  } else {
    throw top.valueError("vehicle", vehicle_expected, describeNode(*vehicle_node));
  }

  if (const toml::node* o = top.take("override")) {
    toml::table* ot = doc.root.get("override")->as_table();
    if (!ot)
      throw top.valueError("override", "a table [override] of vehicle keys", describeNode(*o));
    mergeOverride(vehicle_table, *ot);
  }
  study.vehicle = parseVehicleTable(vehicle_table, vehicle_ctx, vehicle_root_path);
  study.point = study.vehicle.operating_point;
}

/// [simulate] (optional; kind simulate): the operating point, the options and [simulate.free].
void readSimulateStudy(StudyDocument doc, Study& study) {
  std::optional<TableReader> sim = doc.top.optionalTable(
      "simulate", {"mode", "speed_mps", "freq_hz", "theta_deg", "tail_angle_deg", "cycles",
                   "rel_tol", "abs_tol", "separation_abs_tol", "steady_tol", "samples_per_cycle",
                   "history_every", "wing_only", "at_trim", "free"});
  if (!sim) return;
  SimulationOptions& o = study.simulate;
  OperatingPoint& p = study.point;
  o.mode = sim->optionalEnum("mode", o.mode, kModes);
  if (sim->has("free") && o.mode != FlightMode::kFree)
    throw InputError::unknownKey(sim->fileOf("free"), sim->lineOf("free"), sim->keyPath("free"),
                                 "[simulate.free] is only allowed with mode = \"free\", this "
                                 "[simulate] is mode = \"tethered\"");
  if (std::optional<TableReader> free = sim->optionalTable("free", kFreeKeys))
    readFreeFlight(*free, o.free);
  p.speed_mps = sim->optionalDouble(field("simulate.speed_mps"), p.speed_mps);
  p.freq_hz = sim->optionalDouble(field("simulate.freq_hz"), p.freq_hz);
  if (auto d = sim->maybeDouble(field("simulate.theta_deg"))) p.theta_rad = *d * orni::kDegToRad;
  if (auto d = sim->maybeDouble(field("simulate.tail_angle_deg")))
    p.tail_angle_rad = *d * orni::kDegToRad;
  o.cycles = sim->optionalInt(field("simulate.cycles"), o.cycles);
  readTolerances(*sim, o, "simulate");
  o.samples_per_cycle = sim->optionalInt(field("simulate.samples_per_cycle"), o.samples_per_cycle);
  study.history_every = sim->optionalInt(field("simulate.history_every"), study.history_every);
  study.wing_only = sim->optionalBool("wing_only", study.wing_only);
  study.at_trim = sim->optionalBool("at_trim", study.at_trim);
  if (study.at_trim && !study.vehicle.body.present)
    throw sim->valueError("at_trim", "false for a vehicle without [body] (no weight to trim)",
                          "true");
  if (study.wing_only && o.mode == FlightMode::kFree)
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
}

/// [aeromap] (required; kind aeromap).
void readAeromapStudy(StudyDocument doc, Study& study) {
  TableReader am = doc.top.requiredTable(
      "aeromap", {"speed_mps", "freq_hz", "theta_deg", "tail_angle_deg", "wing_only", "cycles",
                  "rel_tol", "abs_tol", "separation_abs_tol", "steady_tol"});
  readAeromap(am, study);
}

/// A continuation's branch is made of periodic trims: [trim] method "periodic" unless the file
/// says otherwise (which is an error at its line).
void defaultToPeriodicTrim(StudyDocument doc) {
  toml::table& root = doc.root;
  if (toml::table* t = root.get("trim") ? root.get("trim")->as_table() : nullptr) {
    if (const toml::node* m = t->get("method")) {
      if (m->value<std::string>() != std::string("periodic")) {
        const TableReader tr(*t, "trim", doc.context, trimSectionKeys());
        throw tr.valueError("method",
                            "\"periodic\" (a continuation follows periodic trims; the default "
                            "here)",
                            describeNode(*m));
      }
    } else {
      t->insert("method", "periodic");
    }
  } else if (!root.contains("trim")) {
    root.insert("trim", toml::table{{"method", "periodic"}});
  }
}

/// [trim] (optional; kinds trim and continuation) and [continuation] (required; kind
/// continuation).
void readTrimStudy(StudyDocument doc, Study& study) {
  const bool continuation = study.kind == StudyKind::kContinuation;
  if (continuation) defaultToPeriodicTrim(doc);
  requireBody(doc.top, study, "its mass is the weight to trim");
  if (std::optional<TableReader> trim = doc.top.optionalTable("trim", trimSectionKeys())) {
    study.trim = readTrimSection(*trim, study.vehicle);
  } else {
    // No [trim]: the defaults, validated like an empty section.
    toml::table empty;
    TableReader none(empty, "trim", doc.context, trimSectionKeys());
    study.trim = readTrimSection(none, study.vehicle);
  }
  if (!continuation) return;
  TableReader c = doc.top.requiredTable("continuation", continuationSectionKeys());
  const orni::TrimContinuationOptions& options =
      study.settings.emplace<orni::TrimContinuationOptions>(readContinuationSection(c));
  if (options.parameter == study.trim.periodic.control)
    throw c.valueError("parameter",
                       std::string("a parameter other than the [trim.periodic] control \"") +
                           orni::toString(study.trim.periodic.control) +
                           "\" (the control keeps every orbit of the branch level)",
                       std::string("\"") + continuationParameterName(options.parameter) + "\"");
}

/// [calibrate] (required; kind calibrate).
void readCalibrateStudy(StudyDocument doc, Study& study) {
  requireBody(doc.top, study, "a calibration flies it");
  TableReader c = doc.top.requiredTable("calibrate", calibrateSectionKeys());
  study.settings = readCalibrateSection(c, study.vehicle);
}

/// [optimize] (required; kind optimize).
void readOptimizeStudy(StudyDocument doc, Study& study) {
  requireBody(doc.top, study, "its mass is the weight to trim");
  TableReader opt = doc.top.requiredTable("optimize", optimizeSectionKeys());
  study.settings = readOptimizeSection(opt, study.vehicle);
}

/// What readStudyRoot reads after the vehicle, in this order: for each step, the sections that
/// must not be in a study of another kind, then (for the step's kinds) the step's reader.
struct KindStep {
  std::vector<std::string_view> sections;
  std::vector<StudyKind> kinds;
  void (*read)(StudyDocument doc, Study& study);
};

const std::vector<KindStep> kKindSteps = {
    {{"simulate"}, {StudyKind::kSimulate}, readSimulateStudy},
    {{"aeromap"}, {StudyKind::kAeromap}, readAeromapStudy},
    {{"trim", "continuation"}, {StudyKind::kTrim, StudyKind::kContinuation}, readTrimStudy},
    {{"calibrate"}, {StudyKind::kCalibrate}, readCalibrateStudy},
    {{"optimize"}, {StudyKind::kOptimize}, readOptimizeStudy},
};

}  // namespace

Study readStudyRoot(toml::table& root, const fs::path& study_file) {
  auto study_ctx = std::make_shared<ReadContext>();
  study_ctx->file = displayPath(study_file);

  TableReader top(root, std::string(), study_ctx,
                  {"kind", "name", "vehicle", "vehicle_source", "override", "simulate",
                   "aeromap", "trim", "sweep", "calibrate", "optimize", "sensitivity",
                   "continuation"});
  const StudyDocument doc{top, root, study_ctx};
  Study study;
  study.study_path = study_file;
  study.kind = top.requiredEnum("kind", kindChoices());
  if (study.kind == StudyKind::kSweep)  // loadStudyText sends sweeps to loadSweepStudy
    throw std::logic_error("readStudyRoot: a sweep document");
  if (study.kind == StudyKind::kSensitivity)  // ... and sensitivity studies to their loader
    throw std::logic_error("readStudyRoot: a sensitivity document");
  for (const std::string_view section : {"sensitivity", "sweep"}) {
    rejectSectionOfOtherKind(top, section, study.kind);
    top.take(section);
  }
  study.name = top.optionalString("name", runNameFromStem(study_file));
  if (!validRunName(study.name))
    throw top.valueError("name",
                         "a run name of letters, digits, '_', '-' and '.' not starting with '.'",
                         describeNode(*root.get("name")));
  readStudyVehicle(doc, study_file, study);
  for (const KindStep& step : kKindSteps) {
    for (const std::string_view section : step.sections)
      rejectSectionOfOtherKind(top, section, study.kind);
    if (isOneOf(study.kind, step.kinds)) step.read(doc, study);
  }
  top.finish();
  return study;
}

Study studyFromVehicle(const fs::path& vehicle_file, StudyKind kind) {
  Study study;
  study.kind = kind;
  study.vehicle = loadVehicleFile(vehicle_file);
  study.name = runNameFromStem(vehicle_file);
  study.vehicle_path = vehicle_file;
  study.point = study.vehicle.operating_point;
  if (kind == StudyKind::kTrim) {
    if (!study.vehicle.body.present)
      throw InputError::missingKey(displayPath(vehicle_file), 0, "body",
                                   "a [body] table: a trim needs the vehicle's mass");
    study.trim = orni::defaultTrimOptions(study.vehicle);
  }
  return study;
}

Study aeromapStudyFromVehicle(const fs::path& vehicle_file, GridAxis speed_mps, GridAxis freq_hz,
                              GridAxis theta_deg, std::optional<GridAxis> tail_angle_deg) {
  Study study = studyFromVehicle(vehicle_file);
  study.kind = StudyKind::kAeromap;
  study.name += "_aeromap";
  AeromapSettings& a = study.settings.emplace<AeromapSettings>();
  a.speed_mps = std::move(speed_mps);
  a.freq_hz = std::move(freq_hz);
  a.theta_deg = std::move(theta_deg);
  if (tail_angle_deg)
    a.tail_angle_deg = std::move(*tail_angle_deg);
  else
    a.tail_angle_deg.values = {fileUnits(study.point.tail_angle_rad, orni::kDegToRad)};
  return study;
}

std::string resolvedStudyToml(const Study& study) {
  if (study.kind == StudyKind::kSweep) return resolvedSweepToml(study);
  if (study.kind == StudyKind::kSensitivity) return resolvedSensitivityToml(study);
  TomlWriter out;
  writeResolvedOpening(study, {}, out);
  writeStudySections(study, study.kind, out);
  return out.str();
}

void writeResolvedOpening(const Study& study, const std::vector<std::string>& notes,
                          TomlWriter& out) {
  out.comment("Resolved study: every default filled in; units in the key suffixes.");
  out.comment(
      "The vehicle below includes the study's overrides; `ornithopter run` accepts this file.");
  for (const std::string& note : notes) out.comment(note);
  out.string("kind", toString(study.kind));
  out.string("name", study.name);
  if (!study.vehicle_path.empty())
    out.string("vehicle_source", study.vehicle_path.generic_string(),
               "the vehicle file as given; its resolved content is [vehicle]");
}

void checkResolvedPoints(const Study& study, const fs::path& study_file, const std::string& what,
                         const std::function<const std::vector<Study>&(const Study&)>& pointsOf,
                         const std::function<std::string(const Study&)>& pointText) {
  const std::string resolved = resolvedStudyToml(study);
  Study again;
  try {
    again = loadStudyText(resolved, study_file.parent_path() / "study.resolved.toml", false);
  } catch (const InputError& e) {
    throw std::runtime_error("the resolved form of this " + what +
                             " does not load (please report): " + std::string(e.what()));
  }
  const std::vector<Study>& p = pointsOf(study);
  const std::vector<Study>& q = pointsOf(again);
  if (q.size() != p.size())
    throw std::runtime_error("the resolved form of this " + what +
                             " has another number of points");
  for (std::size_t i = 0; i < p.size(); ++i)
    if (pointText(q[i]) != pointText(p[i]))
      throw std::runtime_error("the resolved form of this " + what + " does not reproduce point " +
                               std::to_string(i) + " (please report)");
}

void writeStudySections(const Study& study, StudyKind kind, TomlWriter& out) {
  if (kind == StudyKind::kSimulate) {
    const SimulationOptions& o = study.simulate;
    const OperatingPoint& p = study.point;
    out.header({"simulate"});
    out.string("mode", o.mode == FlightMode::kFree ? "free" : "tethered");
    out.number("speed_mps", p.speed_mps);
    out.number("freq_hz", p.freq_hz);
    out.scaled("theta_deg", p.theta_rad, orni::kDegToRad);
    out.scaled("tail_angle_deg", p.tail_angle_rad, orni::kDegToRad);
    out.integer("cycles", o.cycles);
    out.number("rel_tol", o.rel_tol);
    out.number("abs_tol", o.abs_tol);
    out.number("separation_abs_tol", o.separation_abs_tol);
    out.number("steady_tol", o.steady_tol);
    out.integer("samples_per_cycle", o.samples_per_cycle);
    out.integer("history_every", study.history_every);
    if (o.mode == FlightMode::kTethered)
      out.boolean("wing_only", study.wing_only, "true = the main wing alone (no tail, no body drag)");
    out.boolean("at_trim", study.at_trim,
                "true = at the trim point at freq_hz (speed, theta, tail: the initial guess)");
    if (o.mode == FlightMode::kFree) writeFreeFlightTable(o.free, {"simulate", "free"}, out);
  }
  if (kind == StudyKind::kAeromap) {
    const AeromapSettings& a = study.aeromap();
    out.header({"aeromap"});
    writeGridAxis(out, "speed_mps", a.speed_mps);
    writeGridAxis(out, "freq_hz", a.freq_hz);
    writeGridAxis(out, "theta_deg", a.theta_deg);
    writeGridAxis(out, "tail_angle_deg", a.tail_angle_deg);
    out.boolean("wing_only", a.wing_only, "true = the main wing alone (paper Fig. 5)");
    out.integer("cycles", a.options.cycles, "the maximum per point (each stops when steady)");
    out.number("rel_tol", a.options.rel_tol);
    out.number("abs_tol", a.options.abs_tol);
    out.number("separation_abs_tol", a.options.separation_abs_tol);
    out.number("steady_tol", a.options.steady_tol);
  }
  if (kind == StudyKind::kTrim || kind == StudyKind::kContinuation)
    writeTrimSection(study.trim, out);
  if (kind == StudyKind::kContinuation) writeContinuationSection(study.continuation(), out);
  if (kind == StudyKind::kCalibrate) writeCalibrateSection(study.calibrate(), out);
  if (kind == StudyKind::kOptimize) writeOptimizeSection(study.optimize(), out);
  writeVehicleToml(study.vehicle, out, {"vehicle"});
}

std::vector<std::string> freeFlightKeys() { return kFreeKeys; }

void readFreeFlightTable(TableReader& r, FreeFlightOptions& f) { readFreeFlight(r, f); }

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

}  // namespace orni::studies
