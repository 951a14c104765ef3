// Grid axes of an aero map (paper Fig. 5: mean loads over speed, frequency and pitch) and of a
// sweep: the text "A:B:N" means N evenly spaced values from A to B inclusive.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace orni {

/// N evenly spaced values from `first` to `last` inclusive (descending when last < first).
struct GridSpec {
  double first = 0.0;  ///< A, any finite number (file units, e.g. deg or m/s)
  double last = 0.0;   ///< B, finite; equal to A when count == 1
  int count = 1;       ///< N, [1, kMaxGridCount]

  /// True when the fields are inside their ranges; otherwise false with the reason in *why.
  bool IsValid(std::string* why) const;
};

/// Largest N of one axis.
constexpr int kMaxGridCount = 100000;

/// What "A:B:N" means (for "expected A:B:N (...)" in messages).
inline constexpr const char* kGridSpecMeaning =
    "N evenly spaced values from A to B inclusive, N a whole number >= 1, N = 1 needs A == B";

/// Parses "A:B:N" (numbers as in C++ from_chars, no spaces: "10:20:6", "-5:5:3", "1e1:2e1:2").
/// False with a short reason ("N = 1 needs A == B") in *reason when `text` is not a valid spec.
bool tryParseGridSpec(std::string_view text, GridSpec* out, std::string* reason);

/// tryParseGridSpec that throws std::invalid_argument
/// "expected A:B:N (<kGridSpecMeaning>), got '<text>' (<reason>)".
GridSpec parseGridSpec(std::string_view text);

/// The values of the spec: v_i = (A (N-1-i) + B i) / (N-1) inside, exactly A first and B last
/// (and exact integers for integer steps, e.g. 10:20:6 -> 10, 12, ..., 20). Throws
/// std::invalid_argument for an invalid spec.
std::vector<double> gridValues(const GridSpec& spec);

/// Canonical text "A:B:N" with shortest round-trip numbers; parseGridSpec reads it back exactly.
std::string toString(const GridSpec& spec);

}  // namespace orni
