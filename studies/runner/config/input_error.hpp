// InputError: the exception for bad input files (docs/design.md 7.6 and 3.2).
//
// Thrown by the study and vehicle file loaders for anything wrong with a file: TOML syntax, unknown
// or missing keys, wrong types, values outside their valid range, broken cross-references. `main`
// maps it to exit status 2 and prints what(). Messages always start with "FILE:LINE: " (or
// "FILE: " when no line applies) and take one of these forms:
//
//   FILE:LINE: key 'a.b.c': expected <what>, got <what was found>
//   FILE:LINE: missing required key 'a.b.c' (expected <what>)
//   FILE:LINE: unknown key 'a.b.c' (did you mean 'x'?)
//   FILE:LINE: TOML syntax error: <parser description>
//
// For a missing key, LINE is the line of the enclosing table header (1 for the top level).
#pragma once

#include <stdexcept>
#include <string>

namespace orni::studies {

class InputError : public std::runtime_error {
 public:
  /// General form: what() = "FILE:LINE: " + body (", LINE" left out when line <= 0).
  InputError(std::string file, int line, std::string key, const std::string& body);

  /// "FILE:LINE: key 'KEY': expected EXPECTED, got GOT".
  static InputError wrongValue(const std::string& file, int line, const std::string& key,
                               const std::string& expected, const std::string& got);
  /// "FILE:LINE: missing required key 'KEY' (expected EXPECTED)".
  static InputError missingKey(const std::string& file, int line, const std::string& key,
                               const std::string& expected);
  /// "FILE:LINE: unknown key 'KEY'" followed by " (HINT)" when a hint is given.
  static InputError unknownKey(const std::string& file, int line, const std::string& key,
                               const std::string& hint);
  /// "FILE:LINE: TOML syntax error: DESCRIPTION" (key() is empty).
  static InputError syntax(const std::string& file, int line, const std::string& description);

  const std::string& file() const noexcept { return file_; }
  /// 1-based line number, 0 when the error concerns the file as a whole.
  int line() const noexcept { return line_; }
  /// Dotted key path ("wing.members[2].diameter_m"); empty for syntax and file errors.
  const std::string& key() const noexcept { return key_; }
  /// What the key expects ("a number in [0.01, 1] m"), for wrongValue and missingKey; empty for
  /// the other forms.
  const std::string& expected() const noexcept { return expected_; }

 private:
  std::string file_;
  int line_ = 0;
  std::string key_;
  std::string expected_;
};

}  // namespace orni::studies
