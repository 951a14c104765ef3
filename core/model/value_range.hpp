// ValueRange: the allowed interval of an input number, with open or closed bounds, and the text of
// numbers in messages.
//
// Every input key has one (core/model/field_table.hpp), in the key's FILE units (deg, GPa, ...);
// the readers check file values against it, core's model checks the SI value against the same
// bounds scaled to SI (ValueRange::scaled).
#pragma once

#include <limits>
#include <string>

namespace orni {

struct ValueRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  /// (a, b), [a, b], (a, b], [a, b).
  static constexpr ValueRange open(double a, double b) { return {a, b, true, true}; }
  static constexpr ValueRange closed(double a, double b) { return {a, b, false, false}; }
  static constexpr ValueRange openClosed(double a, double b) { return {a, b, true, false}; }
  static constexpr ValueRange closedOpen(double a, double b) { return {a, b, false, true}; }
  /// No bound at all: only for values whose range is checked elsewhere (never a table entry).
  static constexpr ValueRange any() { return {}; }

  /// True for a finite x inside the interval.
  bool contains(double x) const {
    if (!(x == x) || x == std::numeric_limits<double>::infinity() ||
        x == -std::numeric_limits<double>::infinity())
      return false;
    const bool lo_ok = lo_open ? x > lo : x >= lo;
    const bool hi_ok = hi_open ? x < hi : x <= hi;
    return lo_ok && hi_ok;
  }
  /// Both bounds finite.
  bool bounded() const;
  /// The same interval with both bounds multiplied by `factor` > 0 (file units -> SI).
  ValueRange scaled(double factor) const { return {lo * factor, hi * factor, lo_open, hi_open}; }
  /// "[0.005, 20]", "(0, 200]", "> 0" (one bound), "" (none).
  std::string interval() const;
  /// "a number in (0, 200]" with `noun` for "a number".
  std::string describe(const std::string& noun = "a number") const;
};

/// A number as a user writes it: whole numbers below 2^53 as integers ("250", "100000"), others
/// the shortest text that reads back exactly, with a plain exponent ("0.005", "6e-4", "1e308";
/// never "6e-04", "1e+308" or "0.000000").
std::string displayNumber(double value);

}  // namespace orni
