#include "studies/runner/output/json_writer.hpp"

#include <cmath>
#include <cstdio>

#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

namespace {
std::string number(double v) { return std::isfinite(v) ? formatShortest(v) : "null"; }
}  // namespace

std::string jsonEscape(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(ch));
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

JsonObject& JsonObject::set(const std::string& key, double value) {
  items_.emplace_back(key, number(value));
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, int value) {
  items_.emplace_back(key, std::to_string(value));
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, long value) {
  items_.emplace_back(key, std::to_string(value));
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, bool value) {
  items_.emplace_back(key, value ? "true" : "false");
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, const std::string& value) {
  items_.emplace_back(key, jsonEscape(value));
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, const char* value) {
  return set(key, std::string(value));
}
JsonObject& JsonObject::set(const std::string& key, const JsonObject& value) {
  items_.emplace_back(key, "\x01" + value.toString(0));  // marker: nested object, re-indented
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, const std::vector<double>& values) {
  std::string s = "[";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + number(values[i]);
  items_.emplace_back(key, s + "]");
  return *this;
}
JsonObject& JsonObject::setObjects(const std::string& key, const std::vector<JsonObject>& values) {
  if (values.empty()) {
    items_.emplace_back(key, "[]");
    return *this;
  }
  std::string s = "[\n";
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string o = values[i].toString(0);
    std::string shifted = "  ";
    for (std::size_t p = 0; p < o.size(); ++p) {
      shifted += o[p];
      if (o[p] == '\n') shifted += "  ";
    }
    s += shifted + (i + 1 < values.size() ? ",\n" : "\n");
  }
  items_.emplace_back(key, "\x01" + s + "]");  // marker: re-indented like a nested object
  return *this;
}
JsonObject& JsonObject::setStrings(const std::string& key, const std::vector<std::string>& values) {
  std::string s = "[";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + jsonEscape(values[i]);
  items_.emplace_back(key, s + "]");
  return *this;
}
JsonObject& JsonObject::setNull(const std::string& key) {
  items_.emplace_back(key, "null");
  return *this;
}

std::string JsonObject::toString(int indent) const {
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  std::string out = "{\n";
  for (std::size_t i = 0; i < items_.size(); ++i) {
    out += pad + jsonEscape(items_[i].first) + ": ";
    const std::string& v = items_[i].second;
    if (!v.empty() && v[0] == '\x01') {
      // Re-indent the nested object's lines.
      std::string nested = v.substr(1);
      std::string shifted;
      for (std::size_t p = 0; p < nested.size(); ++p) {
        shifted += nested[p];
        if (nested[p] == '\n' && p + 1 < nested.size()) shifted += pad;
      }
      out += shifted;
    } else {
      out += v;
    }
    out += (i + 1 < items_.size()) ? ",\n" : "\n";
  }
  out += std::string(static_cast<std::size_t>(indent), ' ') + "}";
  return indent == 0 ? out + "" : out;
}

}  // namespace orni::studies
