// Where the runner's own messages go: the result line of a run ("name: ok ... -> folder"), notes,
// warnings and progress. The command line prints them (stdout for results, stderr for the rest);
// a library caller (the Python module) makes the runner quiet, so a call writes nothing on file
// descriptors 1 and 2 and the caller reads the outcome from the returned summary instead.
// Errors are not messages: they are thrown, and the caller reports them.
#pragma once

#include <ostream>

namespace orni::studies {

/// The stream for a run's result lines: std::cout, or a stream that discards when quiet.
std::ostream& consoleOut();
/// The stream for notes, warnings and progress: std::cerr, or a stream that discards when quiet.
std::ostream& consoleErr();

/// Quiet (true) or not (false, the default) from now on, for every thread.
void setConsoleQuiet(bool quiet) noexcept;
bool consoleQuiet() noexcept;

}  // namespace orni::studies
