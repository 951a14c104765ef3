// How a run ends when it is interrupted (docs/design.md 4.4). SIGINT and SIGTERM request the
// cooperative cancellation of core/model/cancellation.hpp (the handler does nothing else: one
// atomic store each); the run unwinds from its next cancellation point (a flapping cycle, a point,
// an evaluation; a figure being drawn: plotting/gnuplot.hpp stops gnuplot) like any exception:
// temporary files removed by their writers, journals kept, the folder lock released. On its way
// out the lock marks the folder's summary.json "interrupted" (markRunInterrupted), and main exits
// with 128 + the signal (130 for SIGINT, 143 for SIGTERM).
#pragma once

#include <filesystem>
#include <string>

namespace orni::studies {

/// Installs the SIGINT and SIGTERM handlers (the executable's main, once).
void installInterruptHandlers();
/// The signal that interrupted the run, 0 when none.
int interruptSignal() noexcept;
/// "SIGINT", "SIGTERM" or "a signal".
std::string interruptSignalName();

/// DIR/summary.json says status "interrupted" with the reason: the status and message of a
/// summary the run already wrote (the figures were being drawn) are replaced, and a folder without
/// one gets a summary of its own (kind, status, message). Never throws.
void markRunInterrupted(const std::filesystem::path& dir, const std::string& kind) noexcept;

}  // namespace orni::studies
