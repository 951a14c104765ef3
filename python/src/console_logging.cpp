#include "console_logging.hpp"

#include <pybind11/pybind11.h>

#include <vector>

#include "studies/runner/output/console.hpp"

namespace py = pybind11;

namespace orni::python {

bool forwardConsoleLines() noexcept {
  const std::vector<studies::ConsoleLine> lines = studies::takeConsoleLines();
  if (lines.empty()) return false;
  try {
    const py::object logger = py::module_::import("logging").attr("getLogger")("ornithopter");
    for (const studies::ConsoleLine& line : lines)
      logger.attr(line.kind == studies::ConsoleLine::Kind::kProgress ? "debug" : "info")(line.text);
  } catch (py::error_already_set& e) {
    // Python runs its signal handlers at the next bytecode, which is often inside logging: a
    // Ctrl-C then raises KeyboardInterrupt here (SystemExit from a handler likewise). That is
    // the caller's interruption, not logging's failure: it goes back into the error indicator.
    if (e.matches(PyExc_KeyboardInterrupt) || e.matches(PyExc_SystemExit)) {
      e.restore();
      return true;
    }
    e.discard_as_unraisable("ornithopter: forwarding a message to logging");
  } catch (...) {
  }
  return false;
}

}  // namespace orni::python
