// The study-file reader's internals, shared by study_file.cpp (every kind), sweep_study.cpp
// (kind "sweep", whose points are studies of another kind) and sensitivity_study.cpp (kind
// "sensitivity", whose points are trim studies). Private to orni_studies: includes
// toml++ through toml_access.hpp; the rest of the program includes study_file.hpp.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/toml_access.hpp"

namespace orni::studies {

/// Reads a study document `text` as if it were the file `study_file` (relative vehicle paths are
/// taken from its folder, messages name it). A sweep's resolved study is checked to reproduce its
/// points when `verify_resolved` (loadStudyFile). Throws InputError.
Study loadStudyText(const std::string& text, const std::filesystem::path& study_file,
                    bool verify_resolved);

/// Reads a parsed study document of any kind but "sweep". Nodes are moved out of `root`.
Study readStudyRoot(toml::table& root, const std::filesystem::path& study_file);

/// Reads a parsed sweep document (`root` parsed from `text`); every point is read from a fresh
/// parse of `text` with its axis values written in.
Study loadSweepStudy(toml::table& root, const std::string& text,
                     const std::filesystem::path& study_file, bool verify_resolved);

/// Writes the analysis section of `kind` ([simulate], [aeromap] or [trim]; nothing for other
/// kinds) and the resolved [vehicle] of `study`.
void writeStudySections(const Study& study, StudyKind kind, TomlWriter& out);

/// A grid axis at `key`: "A:B:N", an array of values or one number, every value inside `range`
/// (an [aeromap] axis, a sweep axis's values; `note` follows the range in messages). Throws
/// InputError at the value (an array's element at its own line).
GridAxis readGridAxis(TableReader& r, std::string_view key, const Range& range,
                      std::string_view note = {});

/// Writes an axis back: a spec as "A:B:N", a list as an array.
void writeGridAxis(TomlWriter& out, std::string_view key, const GridAxis& axis);

/// study.resolved.toml of a sweep (resolvedStudyToml dispatches here).
std::string resolvedSweepToml(const Study& study);

/// Reads the study of kind `run` (trim or simulate) that the document `text` (the file
/// `study_file`) becomes with `kind` set to the run, the top-level keys `drop` removed and each
/// (dotted key, value) written in: a key of the run's section ("trim.freq_hz") into that section,
/// any other key into [override] after the file's own overrides (a whole number as a TOML
/// integer). Every check of the ordinary loader applies. Throws InputError.
Study readStudyWithValues(const std::string& text, const std::filesystem::path& study_file,
                          StudyKind run, const std::vector<std::string>& drop,
                          const std::vector<std::pair<std::string, double>>& values);

/// The opening of every study.resolved.toml: what it is, the comment lines `notes`, kind, name
/// and vehicle_source (when the study names its vehicle file).
void writeResolvedOpening(const Study& study, const std::vector<std::string>& notes,
                          TomlWriter& out);

/// The contract of study.resolved.toml for a study of points (sweep, sensitivity): it loads (as
/// study.resolved.toml next to `study_file`) and its points (`pointsOf`) equal the study's,
/// compared by `pointText`. `what` names the study in messages ("sweep", "sensitivity study").
/// Throws std::runtime_error (asking for a report: a bug, not an input error).
void checkResolvedPoints(const Study& study, const std::filesystem::path& study_file,
                         const std::string& what,
                         const std::function<const std::vector<Study>&(const Study&)>& pointsOf,
                         const std::function<std::string(const Study&)>& pointText);

/// The parts of a dotted key of bare parts ("tail.arm_m" -> {"tail", "arm_m"}); empty when the
/// text is not such a key.
std::vector<std::string> dottedKeyParts(const std::string& key);

/// The message of an InputError without its "FILE:LINE: " prefix.
std::string inputErrorBody(const InputError& e);

/// The keys of [simulate.free] (also [sensitivity.free]); reads such a table into `f` (calls
/// finish()); writes one under `header` with every key.
std::vector<std::string> freeFlightKeys();
void readFreeFlightTable(TableReader& r, orni::FreeFlightOptions& f);
void writeFreeFlightTable(const orni::FreeFlightOptions& f, const std::vector<std::string>& header,
                          TomlWriter& out);

/// Reads a parsed sensitivity document (`root` parsed from `text`; config/sensitivity_study.hpp).
Study loadSensitivityStudy(toml::table& root, const std::string& text,
                           const std::filesystem::path& study_file, bool verify_resolved);

/// study.resolved.toml of a sensitivity study (resolvedStudyToml dispatches here).
std::string resolvedSensitivityToml(const Study& study);

}  // namespace orni::studies
