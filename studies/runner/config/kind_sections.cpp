// Which top-level section a study of each kind may have, and the readers of the kinds' sections
// in the order readStudyRoot calls them (study_sections.hpp).
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "studies/runner/config/calibrate_section.hpp"
#include "studies/runner/config/continuation_section.hpp"
#include "studies/runner/config/optimize_section.hpp"
#include "studies/runner/config/study_sections.hpp"
#include "studies/runner/config/trim_section.hpp"

namespace orni::studies {

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

const std::vector<StudyKind>& kindsOf(std::string_view section) {
  for (const SectionKinds& s : kSectionKinds)
    if (s.section == section) return s.kinds;
  throw std::logic_error("kind_sections: no kinds for [" + std::string(section) + "]");
}

bool isOneOf(StudyKind kind, const std::vector<StudyKind>& kinds) {
  return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
}

/// "[trim] is only allowed in a study of kind "trim" or "continuation", this one is kind ..."
/// at `section` when the study has it but its kind may not.
void rejectSectionOfOtherKind(const TableReader& top, std::string_view section, StudyKind kind) {
  const std::string key(section);
  const std::vector<StudyKind>& kinds = kindsOf(section);
  if (!top.has(key) || isOneOf(kind, kinds)) return;
  std::string allowed;
  for (std::size_t i = 0; i < kinds.size(); ++i)
    allowed += std::string(i ? " or " : "") + "\"" + std::string(toString(kinds[i])) + "\"";
  throw InputError::unknownKey(top.fileOf(key), top.lineOf(key), key,
                               "[" + key + "] is only allowed in a study of kind " + allowed +
                                   ", this one is kind \"" + std::string(toString(kind)) + "\"");
}

/// An error at 'vehicle' unless the study's vehicle has a [body]; `why` says what needs it.
void requireBody(const TableReader& top, const Study& study, const std::string& why) {
  if (!study.vehicle.body.present)
    throw top.valueError("vehicle", "a vehicle with a [body] section (" + why + ")",
                         "a vehicle without [body]");
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
    study.trim = readTrimSection(*trim, study.design_point);
  } else {
    // No [trim]: the defaults, validated like an empty section.
    toml::table empty;
    TableReader none(empty, "trim", doc.context, trimSectionKeys());
    study.trim = readTrimSection(none, study.design_point);
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
  checkContinuationEnd(c, options, study.trim);
}

/// [calibrate] (required; kind calibrate).
void readCalibrateStudy(StudyDocument doc, Study& study) {
  requireBody(doc.top, study, "a calibration flies it");
  TableReader c = doc.top.requiredTable("calibrate", calibrateSectionKeys());
  study.settings = readCalibrateSection(c, study.vehicle, study.design_point);
}

/// [optimize] (required; kind optimize).
void readOptimizeStudy(StudyDocument doc, Study& study) {
  requireBody(doc.top, study, "its mass is the weight to trim");
  TableReader opt = doc.top.requiredTable("optimize", optimizeSectionKeys());
  study.settings = readOptimizeSection(opt, study.vehicle, study.design_point);
}

/// What readKindSections reads, in this order: for each step, the sections that must not be in a
/// study of another kind, then the step's reader when the kind may have the first of them.
struct KindStep {
  std::vector<std::string> sections;
  void (*read)(StudyDocument doc, Study& study);
};

const std::vector<KindStep> kKindSteps = {
    {{"simulate"}, readSimulateSection},       {{"aeromap"}, readAeromapSection},
    {{"trim", "continuation"}, readTrimStudy}, {{"calibrate"}, readCalibrateStudy},
    {{"optimize"}, readOptimizeStudy},
};

}  // namespace

void rejectSectionsOfOtherKinds(const TableReader& top, const std::vector<std::string>& sections,
                                StudyKind kind) {
  for (const std::string& section : sections) rejectSectionOfOtherKind(top, section, kind);
}

void readKindSections(StudyDocument doc, Study& study) {
  for (const KindStep& step : kKindSteps) {
    rejectSectionsOfOtherKinds(doc.top, step.sections, study.kind);
    if (isOneOf(study.kind, kindsOf(step.sections.front()))) step.read(doc, study);
  }
}

}  // namespace orni::studies
