// Where the runner's own messages go: the result line of a run ("name: ok ... -> folder"), notes,
// warnings and progress. The command line prints them (stdout for results, stderr for the rest);
// a library caller (the Python module) makes the runner quiet, so a call writes nothing on file
// descriptors 1 and 2 and the caller reads the outcome from the returned summary instead.
// Errors are not messages: they are thrown, and the caller reports them.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace orni::studies {

/// The stream for a run's result lines: std::cout, or a stream that discards when quiet.
std::ostream& consoleOut();
/// The stream for notes, warnings and progress: std::cerr, or a stream that discards when quiet.
std::ostream& consoleErr();

/// Quiet (true) or not (false, the default) from now on, for every thread.
void setConsoleQuiet(bool quiet) noexcept;
bool consoleQuiet() noexcept;

/// One message line of a quiet run, kept for the caller (the Python module hands them to
/// Python's `logging`): a result line (consoleOut), a note or warning (consoleErr), or a
/// progress or heartbeat line.
struct ConsoleLine {
  enum class Kind { kResult, kNote, kProgress };
  Kind kind = Kind::kResult;
  std::string text;
};
/// While capturing (and quiet), every complete line written to consoleOut()/consoleErr(), and
/// every progress and heartbeat line (consoleCapture), is kept until takeConsoleLines(); at
/// most 10 000 are kept (the oldest go). Off by default.
void setConsoleCapture(bool capture) noexcept;
/// Keeps `line` (no newline) as a progress line when quiet and capturing (the progress and
/// heartbeat lines, which are not written through the streams).
void consoleCaptureProgress(const std::string& line);
/// The kept lines, oldest first; the store is empty afterwards. Safe from any thread.
std::vector<ConsoleLine> takeConsoleLines();

}  // namespace orni::studies
