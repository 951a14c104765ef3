#include "studies/runner/config/input_error.hpp"

#include <utility>

namespace orni::studies {

namespace {

std::string location(const std::string& file, int line) {
  std::string s = file.empty() ? std::string("<input>") : file;
  if (line > 0) s += ":" + std::to_string(line);
  return s;
}

}  // namespace

InputError::InputError(std::string file, int line, std::string key, const std::string& body)
    : std::runtime_error(location(file, line) + ": " + body),
      file_(std::move(file)),
      line_(line),
      key_(std::move(key)) {}

InputError InputError::wrongValue(const std::string& file, int line, const std::string& key,
                                  const std::string& expected, const std::string& got) {
  InputError e(file, line, key, "key '" + key + "': expected " + expected + ", got " + got);
  e.expected_ = expected;
  return e;
}

InputError InputError::missingKey(const std::string& file, int line, const std::string& key,
                                  const std::string& expected) {
  InputError e(file, line, key, "missing required key '" + key + "' (expected " + expected + ")");
  e.expected_ = expected;
  return e;
}

InputError InputError::unknownKey(const std::string& file, int line, const std::string& key,
                                  const std::string& hint) {
  std::string body = "unknown key '" + key + "'";
  if (!hint.empty()) body += " (" + hint + ")";
  return InputError(file, line, key, body);
}

InputError InputError::syntax(const std::string& file, int line, const std::string& description) {
  return InputError(file, line, std::string(), "TOML syntax error: " + description);
}

}  // namespace orni::studies
