// Cooperative cancellation of long runs (the Python module's Ctrl-C; any embedding program's
// "stop"). A caller on another thread requests it; the long loops check it at their cancellation
// points and throw Cancelled, which unwinds to the caller like a kill, without writing anything
// more: journals keep every finished point, and no output file is left half written (they are
// written atomically at the end), so a run started again resumes.
//
// Cancellation points (each at most one short unit of work apart):
//   - every flapping cycle of a tethered or free-flight simulation (core/dynamics);
//   - every point of a point pool or aero-map stream (aero maps, sweeps, sensitivities;
//     core/grid/point_pool.cpp, trim/aero_map_stream.cpp);
//   - every design evaluation of an optimisation (optimize/optimizer.cpp);
//   - every accepted point of a continuation (the study command's callback).
// A trim's solver (Ceres) is left through its cost function, which reports the evaluation as
// failed while cancelled; the solver's caller checks again when it returns.
//
// The request is process-wide (a signal is): it stops every run in progress until cleared.
#pragma once

namespace orni {

/// Thrown at a cancellation point once cancellation is requested. Deliberately not a
/// std::exception: the handlers that turn a std::exception of one point or evaluation into a
/// failed status (and journal it) must let it pass.
struct Cancelled {
  const char* what() const noexcept { return "run cancelled"; }
};

/// Request cancellation (thread-safe, async-signal-safe: one atomic store).
void requestCancellation() noexcept;
/// Withdraw the request (after the cancelled run has returned).
void clearCancellation() noexcept;
/// True while a request stands.
bool cancellationRequested() noexcept;
/// Throws Cancelled when a request stands.
inline void throwIfCancelled() {
  if (cancellationRequested()) throw Cancelled{};
}

}  // namespace orni
