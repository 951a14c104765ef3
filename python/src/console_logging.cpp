#include "console_logging.hpp"

#include <pybind11/pybind11.h>

#include <vector>

#include "studies/runner/output/console.hpp"

namespace py = pybind11;

namespace orni::python {

void forwardConsoleLines() noexcept {
  const std::vector<studies::ConsoleLine> lines = studies::takeConsoleLines();
  if (lines.empty()) return;
  try {
    const py::object logger = py::module_::import("logging").attr("getLogger")("ornithopter");
    for (const studies::ConsoleLine& line : lines)
      logger.attr(line.kind == studies::ConsoleLine::Kind::kProgress ? "debug" : "info")(line.text);
  } catch (py::error_already_set& e) {
    e.discard_as_unraisable("ornithopter: forwarding a message to logging");
  } catch (...) {
  }
}

}  // namespace orni::python
