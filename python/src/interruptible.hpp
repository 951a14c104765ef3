// Long computations called from Python, interruptible by Ctrl-C (like the CLI, docs/design.md 4.4).
//
// interruptible(work) runs `work` on a worker thread while the calling thread, with the GIL
// released, checks Python's signal handlers every 20 ms (PyErr_CheckSignals needs the GIL and
// runs handlers on the main thread only). When one raises (Ctrl-C: KeyboardInterrupt) it requests
// cancellation (core/model/cancellation.hpp), waits for the worker to stop at its next
// cancellation point (a flapping cycle, a point, an evaluation) and raises the Python exception.
// A cancelled run leaves what a killed one leaves: its journal, no half-written file; started
// again it resumes. An exception of `work` is re-thrown in the caller's thread. Meanwhile the
// run's message lines go to Python's logging (console_logging.hpp).
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <future>
#include <thread>
#include <utility>

#include "console_logging.hpp"
#include "core/model/cancellation.hpp"

namespace orni::python {

template <class Work>
auto interruptible(Work&& work) -> decltype(work()) {
  namespace py = pybind11;
  using Result = decltype(work());
  std::packaged_task<Result()> task(std::forward<Work>(work));
  std::future<Result> done = task.get_future();
  bool interrupted = false;
  // The handler's exception, taken out of the thread state until the worker has stopped: the
  // run's last lines still go to Python's logging after the loop, and calling into Python with an
  // exception pending fails there and (caught) clears it, which made an interrupted call raise
  // "error_already_set called while Python error indicator not set" now and then.
  PyObject* pending_type = nullptr;
  PyObject* pending_value = nullptr;
  PyObject* pending_traceback = nullptr;
  {
    py::gil_scoped_release release;
    std::thread worker(std::move(task));
    while (done.wait_for(std::chrono::milliseconds(20)) != std::future_status::ready) {
      if (interrupted) continue;
      py::gil_scoped_acquire gil;
      // Progress reaches Python's logging while the run goes on. Python runs signal handlers at
      // its next bytecode, often inside logging: forwardConsoleLines then returns true with the
      // handler's exception set (before, that KeyboardInterrupt was discarded as unraisable and
      // the Ctrl-C was lost: the flaky python.pytest interrupt test of 2026-12-07).
      if (forwardConsoleLines() || PyErr_CheckSignals() != 0) {  // the handler's exception is set
        PyErr_Fetch(&pending_type, &pending_value, &pending_traceback);
        interrupted = true;
        requestCancellation();
      }
    }
    worker.join();
  }
  if (forwardConsoleLines()) {  // the run's last lines (its result line); a Ctrl-C while they go
    if (interrupted) {
      PyErr_Clear();  // a second interruption: the first one is raised
    } else {
      PyErr_Fetch(&pending_type, &pending_value, &pending_traceback);
      interrupted = true;  // the work has ended (its files are written); the Ctrl-C still raises
    }
  }
  if (interrupted) {
    clearCancellation();  // the worker has stopped: the next call runs normally
    PyErr_Restore(pending_type, pending_value, pending_traceback);  // takes the references back
    throw py::error_already_set();
  }
  return done.get();
}

}  // namespace orni::python
