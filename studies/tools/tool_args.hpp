// Command-line parsing shared by the investigation tools (orni_flapping_reference,
// orni_film_static): whole-text numbers and lists, and the usage exit.
#pragma once

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace orni::tools {

/// Prints "TOOL: WHY" and "usage: SYNOPSIS" to stderr and exits with status 2 (bad arguments).
[[noreturn]] inline void exitWithUsage(const std::string& tool, const std::string& synopsis,
                                       const std::string& why) {
  std::cerr << tool << ": " << why << "\nusage: " << synopsis << "\n";
  std::exit(2);
}

/// The whole of `text` as a finite number, or nothing.
inline std::optional<double> parseNumber(const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

/// The whole of `text` as an integer, or nothing.
inline std::optional<int> parseInt(const std::string& text) {
  try {
    std::size_t used = 0;
    const int v = std::stoi(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

/// Comma-separated numbers (empty items skipped); nothing if an item is not a number. May be
/// empty.
inline std::optional<std::vector<double>> parseNumberList(const std::string& text) {
  std::vector<double> values;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    const std::optional<double> v = parseNumber(item);
    if (!v) return std::nullopt;
    values.push_back(*v);
  }
  return values;
}

/// A command line's non-option argument: the vehicle file, once. Returns why it is refused (an
/// unknown option, a second file), or an empty string when it was taken.
inline std::string takeVehicleArgument(const std::string& arg, std::string* vehicle) {
  if (!arg.empty() && arg[0] == '-') return "unknown option " + arg;
  if (!vehicle->empty()) return "one vehicle file";
  *vehicle = arg;
  return {};
}

}  // namespace orni::tools
