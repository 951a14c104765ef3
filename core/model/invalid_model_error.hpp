// InvalidModelError: a vehicle model (or the options of an analysis of it) that the numerics
// cannot accept, found by a check in core: a free-flight vehicle lighter than its wings, a wing
// that cannot be meshed, an aerodynamic model a solver does not support. It is bad input, not a
// failed run: the command line maps it to exit status 2 (docs/design.md 3), like the file
// readers' errors. Programming errors and numerical failures keep their own types.
#pragma once

#include <stdexcept>

namespace orni {

class InvalidModelError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace orni
