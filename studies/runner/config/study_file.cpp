// Study files: the kinds' names, the run name, the top-level flow of the reader (readStudyRoot:
// the sections' readers are study_sections.hpp's), the kind accessors of Study and the resolved
// study's opening and sections.
#include "studies/runner/config/study_file.hpp"

#include <array>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "studies/runner/config/calibrate_section.hpp"
#include "studies/runner/config/continuation_section.hpp"
#include "studies/runner/config/optimize_section.hpp"
#include "studies/runner/config/study_reader.hpp"
#include "studies/runner/config/study_sections.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "studies/runner/config/trim_section.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni::studies {

namespace fs = std::filesystem;

namespace {

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

/// The alternative T of study.settings, or a logic_error naming the accessor and the kind.
template <class T, class S>
T& kindSettings(S& study, std::string_view accessor) {
  if (auto* t = std::get_if<std::remove_const_t<T>>(&study.settings)) return *t;
  throw std::logic_error("Study::" + std::string(accessor) + "(): this study is kind \"" +
                         std::string(toString(study.kind)) + "\", it has no [" +
                         std::string(accessor) + "] settings");
}

}  // namespace

// Study::NAME() const and non-const: the alternative TYPE of `settings` (kindSettings).
#define ORNI_STUDY_KIND_ACCESSORS(TYPE, NAME)                                        \
  const TYPE& Study::NAME() const { return kindSettings<const TYPE>(*this, #NAME); } \
  TYPE& Study::NAME() { return kindSettings<TYPE>(*this, #NAME); }

ORNI_STUDY_KIND_ACCESSORS(SimulateSettings, simulate)
ORNI_STUDY_KIND_ACCESSORS(AeromapSettings, aeromap)
ORNI_STUDY_KIND_ACCESSORS(orni::CalibrationOptions, calibrate)
ORNI_STUDY_KIND_ACCESSORS(SweepSettings, sweep)
ORNI_STUDY_KIND_ACCESSORS(OptimizeSettings, optimize)
ORNI_STUDY_KIND_ACCESSORS(SensitivitySettings, sensitivity)
ORNI_STUDY_KIND_ACCESSORS(orni::TrimContinuationOptions, continuation)

#undef ORNI_STUDY_KIND_ACCESSORS

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

Study readStudyRoot(toml::table& root, const fs::path& study_file) {
  auto study_ctx = std::make_shared<ReadContext>();
  study_ctx->file = displayPath(study_file);

  TableReader top(root, std::string(), study_ctx,
                  {"kind", "name", "vehicle", "vehicle_source", "override", "simulate",
                   "aeromap", "trim", "sweep", "calibrate", "optimize", "sensitivity",
                   "continuation", "output"});
  const StudyDocument doc{top, root, study_ctx};
  Study study;
  study.study_path = study_file;
  study.kind = top.requiredEnum("kind", kindChoices());
  if (study.kind == StudyKind::kSweep)  // loadStudyText sends sweeps to loadSweepStudy
    throw std::logic_error("readStudyRoot: a sweep document");
  if (study.kind == StudyKind::kSensitivity)  // ... and sensitivity studies to their loader
    throw std::logic_error("readStudyRoot: a sensitivity document");
  for (const std::string section : {"sensitivity", "sweep"}) {
    rejectSectionsOfOtherKinds(top, {section}, study.kind);
    top.take(section);
  }
  study.name = top.optionalString("name", runNameFromStem(study_file));
  if (!validRunName(study.name))
    throw top.valueError("name",
                         "a run name of letters, digits, '_', '-' and '.' not starting with '.'",
                         describeNode(*root.get("name")));
  if (std::optional<TableReader> output = top.optionalTable("output", {"figures"})) {
    study.figures = output->optionalBool("figures", true);
    output->finish();
  }
  readStudyVehicle(doc, study_file, study);
  readKindSections(doc, study);
  top.finish();
  return study;
}

Study studyFromVehicle(const fs::path& vehicle_file, StudyKind kind) {
  Study study;
  study.kind = kind;
  orni::VehicleDefinition definition = loadVehicleFile(vehicle_file);
  study.vehicle = std::move(definition.model);
  study.design_point = definition.design_point;
  study.name = runNameFromStem(vehicle_file);
  study.vehicle_path = vehicle_file;
  study.point = study.design_point;
  if (kind == StudyKind::kSimulate) study.settings.emplace<SimulateSettings>();
  if (kind == StudyKind::kTrim) {
    if (!study.vehicle.body.present)
      throw InputError::missingKey(displayPath(vehicle_file), 0, "body",
                                   "a [body] table: a trim needs the vehicle's mass");
    study.trim = orni::defaultTrimOptions(study.design_point);
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
  a.tail_angle_deg =
      tail_angle_deg ? std::move(*tail_angle_deg) : defaultTailAngleAxis(study.point);
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
  if (kind == StudyKind::kSimulate)  // a simulate sweep writes its base's [simulate]
    writeSimulateSection(
        study.kind == StudyKind::kSweep ? study.sweep().base_simulate : study.simulate(),
        study.point, out);
  if (kind == StudyKind::kAeromap) writeAeromapSection(study.aeromap(), out);
  if (kind == StudyKind::kTrim || kind == StudyKind::kContinuation)
    writeTrimSection(study.trim, out);
  if (kind == StudyKind::kContinuation) writeContinuationSection(study.continuation(), out);
  if (kind == StudyKind::kCalibrate) writeCalibrateSection(study.calibrate(), out);
  if (kind == StudyKind::kOptimize) writeOptimizeSection(study.optimize(), out);
  if (!study.figures) {  // written when not the default: it changes no result, only the files
    out.header({"output"});
    out.boolean("figures", false, "figure scripts only");
  }
  writeVehicleToml({study.vehicle, study.design_point}, out, {"vehicle"});
}

}  // namespace orni::studies
