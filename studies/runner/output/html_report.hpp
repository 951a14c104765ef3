// The HTML report of a run: DIR/index.html, one self-contained page (inline style, no script, no
// network) with the run's status and message, the numbers of its summary.json with their units,
// every figure of its kind, and links to its tables, the resolved study and the other files. A
// set of runs (`ornithopter run A.toml B.toml -o DIR`) gets DIR/index.html linking each run's
// report. The pages are written from the files in the folder, so `ornithopter report DIR` can
// write them again for any finished run; the same files give the same bytes.
#pragma once

#include <filesystem>
#include <vector>

namespace orni::studies {

/// Writes `run_dir`/index.html from the run's files (atomic). Throws std::runtime_error when
/// `run_dir` has no readable summary.json or the page cannot be written.
void writeRunReport(const std::filesystem::path& run_dir);

/// Writes `dir`/index.html linking the reports of `runs` (folders inside `dir`, in this order),
/// each with its name, kind, status and message. Throws std::runtime_error when it cannot write.
void writeSetReport(const std::filesystem::path& dir,
                    const std::vector<std::filesystem::path>& runs);

}  // namespace orni::studies
