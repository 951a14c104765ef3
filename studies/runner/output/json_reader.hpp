// A small JSON reader for the files this program writes itself (summary.json), for the HTML
// report and `report`: objects keep their order, numbers keep the text they were written with.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace orni::studies {

struct JsonValue {
  enum class Type { kNull, kBool, kNumber, kString, kArray, kObject };
  Type type = Type::kNull;
  bool boolean = false;
  std::string text;  ///< a number as written, or a string's value (escapes resolved, UTF-8)
  std::vector<JsonValue> items;                             ///< an array's elements
  std::vector<std::pair<std::string, JsonValue>> members;  ///< an object's, in file order

  /// The member `key` of an object, nullptr when absent or not an object.
  const JsonValue* find(std::string_view key) const;
  bool isScalar() const { return type != Type::kArray && type != Type::kObject; }
};

/// Parses `text` (one JSON value, RFC 8259). Throws std::runtime_error naming the byte offset.
JsonValue parseJson(std::string_view text);

}  // namespace orni::studies
