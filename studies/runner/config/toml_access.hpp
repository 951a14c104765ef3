// Strict, typed access to TOML tables (docs/design.md 7.11) and a small TOML writer.
//
// Private to orni_studies (it includes toml++): the rest of the program includes study_file.hpp.
//
// TableReader wraps one toml::table. Every section is read with the list of keys it allows: a key
// outside that list is rejected at once with an edit-distance suggestion ("unknown key
// 'wing.semispn_m' (did you mean 'semispan_m'?)"), and finish() rejects any key that was allowed
// but never read. Getters check the type (integers are accepted where a float is expected), reject
// nan and inf, check the valid range in FILE units and throw InputError naming file, line and key.
// Lines and files come from node.source(): for nodes merged in from another file (a study's
// [override]) they name that other file, and ReadContext::foreign_prefix is put in front of the
// key.
#pragma once

#include <toml++/toml.h>

#include <cstddef>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/model/field_table.hpp"
#include "core/model/value_range.hpp"
#include "studies/runner/config/input_error.hpp"

namespace orni::studies {

/// Parses a TOML file. A missing or unreadable file and TOML syntax errors become InputError
/// (line and description from the parser). The path is recorded as displayPath(file) in every
/// node's source().
toml::table parseTomlFile(const std::filesystem::path& file);

/// The bytes of a file; InputError when it is missing, not a regular file or unreadable.
std::string readTomlFileText(const std::filesystem::path& file);

/// Why `file` cannot be read as an input file ("no such file", "is a directory, not a file",
/// "not a regular file (a FIFO)", ...); empty for a regular file.
std::string notARegularFile(const std::filesystem::path& file);

/// Parses TOML text as if read from `file` (displayPath(file) in messages and node sources).
toml::table parseTomlText(std::string_view text, const std::filesystem::path& file);

/// The file name used in messages and node sources: the path as given, lexically normalised.
std::string displayPath(const std::filesystem::path& file);

/// Shortest decimal text that reads back as exactly `value` ("0.1", "250", "4e-05").
std::string formatNumber(double value);

/// Short description of a node for "got ..." in messages: `a string "abc"`, `an integer 5`,
/// `a float 1.5`, `a boolean true`, `a table`, `an array of 2 elements`, ...
std::string describeNode(const toml::node& node);

/// Edit distance of bytes: insertions, deletions, substitutions and adjacent transpositions.
std::size_t editDistance(std::string_view a, std::string_view b);

/// The candidate closest to `word` when it is close enough to be a likely typo, else "".
std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates);

/// Allowed interval of a number, in file units (core/model/value_range.hpp).
using Range = orni::ValueRange;

/// The text of a value node as it stands in its file ("1e308", "6e-4", "-1_000.5"), when the file
/// was parsed by parseTomlText/parseTomlFile in this process; otherwise the shortest text that
/// reads back as its value (displayNumber) or describeNode.
std::string sourceText(const toml::node& node);

/// Message context shared by the readers of one document.
struct ReadContext {
  std::string file;            ///< file named for nodes that carry no source information
  std::string foreign_file;    ///< nodes whose source is this file (a study merged in) ...
  std::string foreign_prefix;  ///< ... are named with this prefix ("override.")
};

class TableReader {
 public:
  /// Reads `table`, whose dotted key path is `path` ("" for the document root). Throws InputError
  /// for the first key of `table` that is not in `allowed`.
  TableReader(const toml::table& table, std::string path,
              std::shared_ptr<const ReadContext> context, std::vector<std::string> allowed);

  const toml::table& table() const { return *table_; }
  const std::string& path() const { return path_; }
  const std::shared_ptr<const ReadContext>& context() const { return context_; }

  /// True when the key is present (does not consume it).
  bool has(std::string_view key) const;
  /// The node of an allowed key, marked as read; nullptr when absent.
  const toml::node* take(std::string_view key);
  /// Keys present in the table, in table order.
  std::vector<std::string> presentKeys() const;

  /// `note` follows the range in messages (" (the range of tail.arm_m)").
  double requiredDouble(std::string_view key, const Range& range, std::string_view note = {});
  double optionalDouble(std::string_view key, double fallback, const Range& range);
  std::optional<double> maybeDouble(std::string_view key, const Range& range);

  int requiredInt(std::string_view key, int lo, int hi);
  int optionalInt(std::string_view key, int fallback, int lo, int hi);

  /// Numbers and integers of a field-table entry (core/model/field_table.hpp): the key is the
  /// entry's last part ("semispan_m" of "wing.semispan_m"), the range the entry's (file units);
  /// a value outside it is an InputError naming the range and the value as written.
  double requiredDouble(const orni::FieldSpec& f) { return requiredDouble(localKey(f), f.range); }
  double optionalDouble(const orni::FieldSpec& f, double fallback) {
    return optionalDouble(localKey(f), fallback, f.range);
  }
  std::optional<double> maybeDouble(const orni::FieldSpec& f) {
    return maybeDouble(localKey(f), f.range);
  }
  int requiredInt(const orni::FieldSpec& f);
  int optionalInt(const orni::FieldSpec& f, int fallback);
  /// The entry's last part, the key inside its table.
  static std::string_view localKey(const orni::FieldSpec& f);

  bool requiredBool(std::string_view key);
  bool optionalBool(std::string_view key, bool fallback);

  /// A string; empty only when allow_empty.
  std::string requiredString(std::string_view key, bool allow_empty = false);
  std::string optionalString(std::string_view key, const std::string& fallback,
                             bool allow_empty = false);

  /// One of `choices` (the file's spelling -> value); the message lists them all.
  template <typename E>
  E requiredEnum(std::string_view key, const std::vector<std::pair<std::string, E>>& choices) {
    return choices[choiceIndex(key, names(choices), true)].second;
  }
  template <typename E>
  E optionalEnum(std::string_view key, E fallback,
                 const std::vector<std::pair<std::string, E>>& choices) {
    const std::size_t i = choiceIndex(key, names(choices), false);
    return i < choices.size() ? choices[i].second : fallback;
  }

  /// Array of exactly `size` numbers (any size when 0), each inside `each`.
  std::vector<double> requiredNumberArray(std::string_view key, std::size_t size,
                                          const Range& each);
  /// The pair of a kPair entry ([a, b], each inside the entry's range).
  std::vector<double> requiredPair(const orni::FieldSpec& f) {
    return requiredNumberArray(localKey(f), 2, f.range);
  }

  TableReader requiredTable(std::string_view key, std::vector<std::string> allowed);
  std::optional<TableReader> optionalTable(std::string_view key, std::vector<std::string> allowed);
  /// Array of tables ([[key]]); empty when absent.
  std::vector<TableReader> optionalTableArray(std::string_view key,
                                              std::vector<std::string> allowed);

  /// Throws for a present key that no getter read.
  void finish() const;

  /// Dotted display name of a key of this table (with the foreign prefix when the key's node, or
  /// this table when the key is absent, comes from the foreign file).
  std::string keyPath(std::string_view key) const;
  /// File and line of the key's node, or of this table's header when the key is absent.
  std::string fileOf(std::string_view key) const;
  int lineOf(std::string_view key) const;

  /// InputError "key 'k': expected E, got G" located at the key (or the table header).
  InputError valueError(std::string_view key, const std::string& expected,
                        const std::string& got) const;
  /// InputError "missing required key 'k' (expected E)" located at the table header.
  InputError missingError(std::string_view key, const std::string& expected) const;

 private:
  template <typename E>
  static std::vector<std::string> names(const std::vector<std::pair<std::string, E>>& choices) {
    std::vector<std::string> n;
    n.reserve(choices.size());
    for (const auto& c : choices) n.push_back(c.first);
    return n;
  }
  /// Index of the string value in `names`; names.size() when absent and not required.
  std::size_t choiceIndex(std::string_view key, const std::vector<std::string>& names,
                          bool required);
  const toml::node* nodeOf(std::string_view key) const;
  const toml::node& locator(std::string_view key) const;
  std::string childPath(std::string_view key) const;
  double numberValue(std::string_view key, const toml::node& node, const Range& range,
                     std::string_view note = {}) const;
  int intValue(std::string_view key, const toml::node& node, int lo, int hi) const;

  const toml::table* table_;
  std::string path_;
  std::shared_ptr<const ReadContext> context_;
  std::vector<std::string> allowed_;
  std::vector<std::string> consumed_;
};

/// Writes a TOML document line by line with exact, readable numbers.
class TomlWriter {
 public:
  void comment(std::string_view text);
  void blank();
  /// [a.b.c]; each part is quoted when it is not a bare key.
  void header(const std::vector<std::string>& parts);
  /// [[a.b.c]]
  void arrayHeader(const std::vector<std::string>& parts);

  void string(std::string_view key, std::string_view value, std::string_view note = {});
  void integer(std::string_view key, long long value, std::string_view note = {});
  void boolean(std::string_view key, bool value, std::string_view note = {});
  /// A float written so that it reads back as exactly `value`.
  void number(std::string_view key, double value, std::string_view note = {});
  /// A float in file units: writes the shortest d with d * si_per_file_unit == si exactly (when one
  /// exists; otherwise the closest), so that loading converts it back to the same SI value.
  void scaled(std::string_view key, double si, double si_per_file_unit, std::string_view note = {});
  void numberArray(std::string_view key, const std::vector<double>& values,
                   std::string_view note = {});
  void stringArray(std::string_view key, const std::vector<std::string>& values,
                   std::string_view note = {});

  /// From now on, writes each key whose full dotted path (the current header's parts, unquoted,
  /// then the key: "trim.freq_hz", "vehicle.wing.members.diameter_m") is in `paths` as the comment
  /// "# KEY: NOTE" instead of its value (a sweep's keys that follow the swept ones).
  void leaveOut(std::vector<std::string> paths, std::string note);

  const std::string& str() const { return out_; }

  /// Helpers, public for tests: TOML text of a float, a key, a string.
  static std::string floatText(double value);
  static std::string scaledText(double si, double si_per_file_unit);
  static std::string keyText(std::string_view key);
  static std::string stringText(std::string_view value);

 private:
  void line(std::string_view key, const std::string& value, std::string_view note);
  void setHeader(const std::vector<std::string>& parts);
  std::string out_;
  std::string header_path_;  ///< the current header's parts joined by '.', unquoted
  std::vector<std::string> left_out_;
  std::string left_out_note_;
};

}  // namespace orni::studies
