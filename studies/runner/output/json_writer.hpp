// A small ordered JSON builder for summary.json (deterministic key order and number text).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace orni::studies {

class JsonObject {
 public:
  JsonObject& set(const std::string& key, double value);
  JsonObject& set(const std::string& key, int value);
  JsonObject& set(const std::string& key, long value);
  JsonObject& set(const std::string& key, bool value);
  JsonObject& set(const std::string& key, const std::string& value);
  JsonObject& set(const std::string& key, const char* value);
  JsonObject& set(const std::string& key, const JsonObject& value);
  JsonObject& set(const std::string& key, const std::vector<double>& values);
  /// An array of objects.
  JsonObject& setObjects(const std::string& key, const std::vector<JsonObject>& values);
  /// An array of strings.
  JsonObject& setStrings(const std::string& key, const std::vector<std::string>& values);
  /// null (a value that does not exist for this run).
  JsonObject& setNull(const std::string& key);
  /// Pretty text with two-space indentation. Non-finite numbers are written as null (never NaN).
  std::string toString(int indent = 0) const;

 private:
  std::vector<std::pair<std::string, std::string>> items_;  // key, already-encoded value
};

std::string jsonEscape(const std::string& s);

}  // namespace orni::studies
