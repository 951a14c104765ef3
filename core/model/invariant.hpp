// Programming errors against outcomes (docs/design.md 7).
//
// A failed evaluation is an outcome where the physics or the numbers fail: a periodic run that
// diverges, a solver that does not converge (std::runtime_error), a design the model's rules
// reject (InvalidModelError, and std::invalid_argument in general: a value outside its rules).
// A programming error is not: a misspelt field name (the field table's std::logic_error), an
// index out of range (std::out_of_range), a broken invariant (ORNI_DEMAND). Where a failed
// evaluation is caught and recorded (trim points, design evaluations, aero-map, sweep and
// sensitivity points, calibrations), a programming error propagates and fails the run loudly.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>

namespace orni {

/// Throws std::logic_error "invariant violated: MESSAGE (CONDITION at FILE:LINE)".
[[noreturn]] inline void demandFailed(const char* condition, const std::string& message,
                                      const char* file, int line) {
  throw std::logic_error("invariant violated: " + message + " (" + condition + " at " + file +
                         ":" + std::to_string(line) + ")");
}

/// True for a programming error: a std::logic_error that is not a std::invalid_argument.
inline bool isProgrammingError(const std::exception& e) noexcept {
  return dynamic_cast<const std::logic_error*>(&e) != nullptr &&
         dynamic_cast<const std::invalid_argument*>(&e) == nullptr;
}

/// Inside a catch block of `e`: rethrows it when it is a programming error.
inline void rethrowIfProgrammingError(const std::exception& e) {
  if (isProgrammingError(e)) throw;
}

}  // namespace orni

/// An invariant at a module boundary, checked in every build type (Release too): when
/// `condition` is false, throws std::logic_error with `message`, the condition and the place.
#define ORNI_DEMAND(condition, message)                                            \
  do {                                                                             \
    if (!(condition)) ::orni::demandFailed(#condition, (message), __FILE__, __LINE__); \
  } while (false)
