#include "studies/runner/cli/cli_options.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "core/grid/grid_spec.hpp"
#include "core/model/field_table.hpp"
#include "core/model/value_range.hpp"
#include "studies/runner/commands/run_study.hpp"
#include "studies/runner/config/input_error.hpp"

namespace orni::studies::cli {

namespace {

CliError optionError(const std::string& flag, std::string_view key, const std::string& expected,
                     const std::string& got) {
  return CliError("command line: option " + flag + ": expected " + expected + " (key " +
                  std::string(key) + "), got " + got);
}

}  // namespace

double optionValue(const std::string& flag, std::string_view key, const std::string& text) {
  const FieldSpec& f = field(key);
  const std::string got = "'" + text + "'";
  if (f.type == FieldType::kInteger) {
    long long v = 0;
    const char* end = text.data() + text.size();
    const auto res = std::from_chars(text.data(), end, v);
    if (text.empty() || res.ec != std::errc() || res.ptr != end)
      throw optionError(flag, key, f.expected(), got);
    if (!f.range.contains(static_cast<double>(v))) throw optionError(flag, key, f.expected(), got);
    return static_cast<double>(v);
  }
  char* end = nullptr;
  const double v = text.empty() || std::isspace(static_cast<unsigned char>(text[0]))
                       ? std::nan("")
                       : std::strtod(text.c_str(), &end);
  if (end == nullptr || *end != '\0') throw optionError(flag, key, f.expected(), got);
  if (!f.range.contains(v)) throw optionError(flag, key, f.expected(), got);
  return v;
}

GridAxis axisOption(const std::string& flag, std::string_view key, const std::string& text) {
  const FieldSpec& f = field(key);
  const std::string expected =
      std::string("A:B:N (") + kGridSpecMeaning + "), " + f.range.describe("each value");
  GridSpec spec;
  std::string reason;
  if (!tryParseGridSpec(text, &spec, &reason))
    throw optionError(flag, key, expected, "'" + text + "' (" + reason + ")");
  GridAxis axis = gridAxis(spec);
  for (const double v : axis.values)
    if (!f.range.contains(v))
      throw optionError(flag, key, expected, "'" + text + "' (value " + displayNumber(v) + ")");
  return axis;
}

void requireCliEntry(const CLI::App& sub, const std::string& names, std::string_view key) {
  const std::string_view cli = field(key).cli;
  bool named = false;
  std::stringstream list(names);
  for (std::string name; std::getline(list, name, ',');)
    named = named || cli.find(name) != std::string_view::npos;
  if (!named || cli.find(sub.get_name()) == std::string_view::npos)
    throw std::logic_error("the field table's entry of " + std::string(key) + " (cli \"" +
                           std::string(cli) + "\") does not name the option " + names + " of " +
                           sub.get_name());
}

int jobsOption(const std::optional<std::string>& text) {
  return text ? static_cast<int>(optionValue("-j", "jobs", *text)) : 1;
}

const CLI::Validator& nonEmptyPath() {
  static const CLI::Validator validator(
      [](std::string& text) {
        return text.empty() ? std::string("expected a path, got an empty string") : std::string();
      },
      "PATH", "NonEmptyPath");
  return validator;
}

std::filesystem::path outputFolder(const std::optional<std::string>& out_opt, const Study& study,
                                   bool several) {
  if (!out_opt) return std::filesystem::path("results") / study.name;
  return several ? std::filesystem::path(*out_opt) / study.name : std::filesystem::path(*out_opt);
}

void requireBodyForFreeFlight(const Study& study) {
  if (study.simulate().options.mode == FlightMode::kFree && !study.vehicle.body.present)
    throw InputError::missingKey(inputFileOf(study), 0, "body",
                                 "a [body] table: free flight needs the vehicle's mass and pitch "
                                 "inertia");
}

}  // namespace orni::studies::cli
