// The field table: one description of every input key, with its unit, default and valid range
// (docs/design.md 7.11).
//
// Each entry names a key as it is written in a vehicle or study file (dotted path; "[]" for any
// element of an array of tables, "*" for any name of a named table), its unit, its type, its valid
// range in FILE units with both bounds (open or closed), its default and a one-line meaning. The
// same entry is checked wherever the key can be set: the vehicle reader, a study's sections and
// [override], sweep axes, sensitivity parameters, design and calibration variables, the command
// line (FieldSpec::cli) and core's model checks (core/model/vehicle_validation.hpp, in SI:
// range.scaled(si_per_unit)). `ornithopter keys` prints the table; the key reference docs/keys.md is
// generated from it (tests/regression/readme_keys.sh fails when they drift).
//
// Keys that set the same quantity (the speed of the operating point, of [simulate], of a trim's
// initial guess and bounds, of an aero-map axis) share one range constant in field_table.cpp, so
// a range is written once.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/model/value_range.hpp"

namespace orni {

enum class FieldType {
  kNumber,      ///< a float (integers accepted) inside `range`
  kInteger,     ///< an integer inside `range` (whole-number bounds)
  kBoolean,     ///< true or false
  kString,      ///< a string (a name, a path)
  kChoice,      ///< one of the strings listed in `choices`
  kPair,        ///< an array of two numbers, each inside `range`
  kNumberList,  ///< an array of numbers (possibly empty), each inside `range`
  kGrid,        ///< a grid axis: "A:B:N", an array of numbers or one number, each inside `range`
  kStringList,  ///< an array of strings
  kTable,       ///< a table or an array of tables (its keys have their own entries)
};

/// "number", "integer", "boolean", ...
const char* toString(FieldType type);

struct FieldSpec {
  std::string_view key;      ///< "wing.semispan_m", "materials.*.density_kgpm3", "jobs" (CLI only)
  std::string_view unit;     ///< unit of the file value: "m", "deg", "kg/m^3", "-" (none)
  double si_per_unit = 1.0;  ///< SI value = file value * si_per_unit (deg -> rad, GPa -> Pa)
  FieldType type = FieldType::kNumber;
  ValueRange range;                ///< numbers, integers, pairs, grids: file units, both bounds
  std::string_view choices;        ///< kChoice: the allowed strings, "a | b | c"
  std::string_view default_text;   ///< "0.005", "required", "the operating point's", ...
  std::string_view meaning;        ///< one line
  std::string_view cli;            ///< command-line options that set this key ("simulate --speed")
  /// Keys whose values are further limited by other keys (e.g. element_size_m <= semispan_m):
  /// the rule in words, checked by core's model checks or the section reader.
  std::string_view also;

  /// The section group of the key for `ornithopter keys GROUP`: "vehicle", "study", "simulate",
  /// "aeromap", "trim", "optimize", "calibrate", "sweep", "sensitivity", "continuation" or "cli"
  /// (command line only).
  std::string_view group() const;
  /// "a number in [0.005, 20]", "an integer in [1, 500]", "one of \"a\", \"b\"", ...
  std::string expected() const;
  /// The range in SI units (range.scaled(si_per_unit)).
  ValueRange siRange() const { return range.scaled(si_per_unit); }
  /// True for the bounds of a variable or axis whose range is that of the key it sets (unit
  /// "key" or "field"): checked against that key's entry, not its own.
  bool rangeOfAnotherKey() const { return unit == "key" || unit == "field"; }
};

/// Every entry, in the order of the files (vehicle keys first, then the study's sections, then
/// options of the command line only).
const std::vector<FieldSpec>& fieldTable();

/// The entry of a key, nullptr when there is none. Array indices and table names are normalised:
/// "wing.members[3].diameter_m" -> "wing.members[].diameter_m",
/// "materials.LE1.density_kgpm3" -> "materials.*.density_kgpm3".
const FieldSpec* findField(std::string_view key);
/// The entry of a key that must have one; throws std::logic_error otherwise (a programming error).
const FieldSpec& field(std::string_view key);

/// The groups of `ornithopter keys GROUP`, in print order.
const std::vector<std::string_view>& fieldGroups();

}  // namespace orni
