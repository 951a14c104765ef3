// What every subcommand's wiring shares (studies/runner/cli/): the exit codes, command-line
// errors, option values checked against the field table (core/model/field_table.hpp: the same
// ranges as in the files) and the output folder. The executable's only: includes CLI11.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies::cli {

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitBadInput = 2;

/// A bad command-line value: reported like a file error, with "command line" as the file.
struct CliError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The value of a command-line option `flag` that sets the field-table key `key` (file units):
/// the whole text a number (kNumber) or an integer (kInteger) inside the key's range. Messages
/// quote the text as given: "command line: option --freq: expected E (key simulate.freq_hz), got
/// G". Throws CliError.
double optionValue(const std::string& flag, std::string_view key, const std::string& text);

/// A grid axis from a command-line spec "A:B:N" for the [aeromap] key `key`, every value inside
/// its range. Throws CliError.
GridAxis axisOption(const std::string& flag, std::string_view key, const std::string& text);

/// -j N: the "jobs" entry of the field table; 1 when not given.
int jobsOption(const std::optional<std::string>& text);

/// A logic_error unless the field-table entry of `key` names this option of `sub` in its
/// FieldSpec::cli ("simulate --speed", "run/aeromap/optimize -j"): the table, `ornithopter keys`
/// and docs/keys.md say which option sets which key, and the wiring must agree.
void requireCliEntry(const CLI::App& sub, const std::string& names, std::string_view key);

/// `sub`'s option `names` ("--speed", "-j,--jobs") that sets the field-table key `key`, its text
/// into `text` (checked later with optionValue or axisOption, against the same key).
template <class T>
CLI::Option* addFieldOption(CLI::App* sub, const std::string& names, std::string_view key, T& text,
                            const std::string& help) {
  requireCliEntry(*sub, names, key);
  return sub->add_option(names, text, help);
}

/// --help of --fresh (run, aeromap, optimize).
inline constexpr const char* kFreshHelp =
    "Discard any journal in the output folder and start afresh (without it a journal of another "
    "study, grid or version is refused, never deleted)";

/// -o, --export-ccx and RUN_DIR: a name, never "" (which would silently mean the default).
const CLI::Validator& nonEmptyPath();

/// results/<study name> without -o; with -o its folder, or DIR/<study name> for `several` studies.
std::filesystem::path outputFolder(const std::optional<std::string>& out_opt, const Study& study,
                                   bool several);

/// A vehicle without [body] cannot fly free: bad input (InputError), before any work.
void requireBodyForFreeFlight(const Study& study);

}  // namespace orni::studies::cli
