// The runner's message lines (result lines, notes, progress: studies/runner/output/console.hpp),
// kept while a library call runs quietly, handed to Python's logging: logger "ornithopter",
// result lines and notes at INFO, progress and heartbeat lines at DEBUG. Python's default
// logging shows neither (nothing is printed unless the caller configures logging, e.g.
// logging.basicConfig(level=logging.INFO)).
#pragma once

namespace orni::python {

/// Logs every kept line and forgets it. Needs the GIL; never throws (a failing handler is
/// logging's own business). Returns true when a signal handler raised while logging ran
/// (KeyboardInterrupt, SystemExit): that exception is then set in Python's error indicator for the
/// caller to take as an interruption, as from PyErr_CheckSignals.
[[nodiscard]] bool forwardConsoleLines() noexcept;

}  // namespace orni::python
