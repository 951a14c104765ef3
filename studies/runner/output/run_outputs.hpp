// A run owns its output folder (docs/design.md 4.4): the files every kind of run writes there, by
// the "kind" its summary.json names, so that
//   - a run removes the outputs an earlier run left in its folder before it writes its first file
//     (tethered then free flight must not leave cycles.csv, zmp.csv and loads.*; an aero map then
//     a simulation must not leave aeromap.*). Only this program's output names are removed (a
//     user's notes stay), never a journal (an interrupted run's finished points: journal_file.hpp
//     refuses another study's) and never anything in a subfolder;
//   - `plot` redraws only the figures of the kind the folder's summary.json names.
// The removal happens at the first file the run writes into the folder (claimRunFolder, called
// by AtomicFileWriter), not when the folder is locked: a run refused before it writes (another
// study's journal, bad input found late) leaves the folder as it was.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace orni::studies {

/// The files of one kind of run: fixed names and figure stems (STEM.gp, .png, .svg); a stem
/// ending in '*' is a prefix (the sensitivity study's tornado_<prediction>).
struct KindOutputs {
  std::string kind;  ///< summary.json's "kind"
  std::vector<std::string> files;
  std::vector<std::string> figure_stems;
};

/// True when figure stem `stem` is named by `pattern` (a KindOutputs figure stem, '*' at its end
/// a prefix).
bool stemMatches(const std::string& pattern, const std::string& stem);

/// Every kind's outputs.
const std::vector<KindOutputs>& runOutputsByKind();

/// True when `stem` is a figure of `kind`; true for any stem when the kind is unknown ("" or a
/// kind of a newer version).
bool isFigureOfKind(const std::string& kind, const std::string& stem);

/// The "kind" of DIR/summary.json, "" when there is none.
std::string summaryKind(const std::filesystem::path& dir);

/// Removes from `dir` every file that some run of this program writes there (any kind), except
/// journals. Returns how many were removed.
int removeEarlierRunOutputs(const std::filesystem::path& dir);

/// The folder a run is about to write into: its earlier outputs are removed at the first file
/// written into it (claimRunFolder). Called by OutputFolderLock for a run (not for `plot`).
void expectRunFolder(const std::filesystem::path& dir);
/// Forget the folder (the lock is released).
void forgetRunFolder(const std::filesystem::path& dir);
/// Called before a file is created at `path`: when its folder is an expected run folder not yet
/// claimed, removes the earlier run's outputs there first.
void claimRunFolder(const std::filesystem::path& path);

}  // namespace orni::studies
