// The study-file reader's internals, shared by study_file.cpp (every kind) and sweep_study.cpp
// (kind "sweep", whose points are studies of another kind). Private to orni_studies: includes
// toml++ through toml_access.hpp; the rest of the program includes study_file.hpp.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

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
/// (an [aeromap] axis, a sweep axis's values). Throws InputError.
GridAxis readGridAxis(TableReader& r, std::string_view key, const Range& range);

/// Writes an axis back: a spec as "A:B:N", a list as an array.
void writeGridAxis(TomlWriter& out, std::string_view key, const GridAxis& axis);

/// study.resolved.toml of a sweep (resolvedStudyToml dispatches here).
std::string resolvedSweepToml(const Study& study);

}  // namespace orni::studies
