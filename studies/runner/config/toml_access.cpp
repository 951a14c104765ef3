#include "studies/runner/config/toml_access.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace orni::studies {

namespace fs = std::filesystem;

// ------------------------------------------------------------------------------------------------
// Files

std::string displayPath(const fs::path& file) { return file.lexically_normal().string(); }

std::string notARegularFile(const fs::path& file) {
  std::error_code ec;
  const fs::file_status st = fs::status(file, ec);
  switch (st.type()) {
    case fs::file_type::regular: return std::string();
    case fs::file_type::not_found: return "no such file";
    case fs::file_type::directory: return "is a directory, not a file";
    case fs::file_type::fifo: return "not a regular file (a FIFO)";
    case fs::file_type::character: return "not a regular file (a character device)";
    case fs::file_type::block: return "not a regular file (a block device)";
    case fs::file_type::socket: return "not a regular file (a socket)";
    default:
      return ec ? ec.message() : std::string("not a regular file");
  }
}

std::string readTomlFileText(const fs::path& file) {
  std::string name = displayPath(file);
  const std::string why = notARegularFile(file);
  if (!why.empty()) throw InputError(name, 0, std::string(), "cannot open file: " + why);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(name, 0, std::string(), "cannot open file for reading");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  std::string text(size > 0 ? static_cast<std::size_t>(size) : 0, '\0');
  if (size > 0 && !in.read(text.data(), size))
    throw InputError(name, 0, std::string(), "cannot read file");
  return text;
}

namespace {

/// The texts of the documents parsed in this process, by display path (the latest of each), for
/// sourceText. Read only to write an error message.
struct SourceTexts {
  std::mutex mutex;
  std::map<std::string, std::string> texts;
};

SourceTexts& sourceTexts() {
  static SourceTexts registry;
  return registry;
}

}  // namespace

std::string sourceText(const toml::node& node) {
  const toml::source_region& src = node.source();
  std::string line_text;
  if (src.path && src.begin.line > 0 && src.begin.line == src.end.line &&
      src.end.column > src.begin.column) {
    SourceTexts& registry = sourceTexts();
    const std::lock_guard<std::mutex> lock(registry.mutex);
    const auto it = registry.texts.find(*src.path);
    if (it != registry.texts.end()) {
      std::size_t start = 0;
      for (toml::source_index l = 1; l < src.begin.line && start != std::string::npos; ++l) {
        start = it->second.find('\n', start);
        if (start != std::string::npos) ++start;
      }
      if (start != std::string::npos) {
        const std::size_t end = it->second.find('\n', start);
        line_text = it->second.substr(start, end == std::string::npos ? end : end - start);
      }
    }
  }
  const std::size_t from = src.begin.column - 1, count = src.end.column - src.begin.column;
  if (from + count <= line_text.size()) {
    const std::string text = line_text.substr(from, count);
    // Only a value that reads back as this node's value (the line may have changed since).
    if (const auto* f = node.as_floating_point()) {
      std::string plain;
      for (const char c : text)
        if (c != '_') plain += c;
      try {
        const toml::table t = toml::parse("v = " + plain);
        const auto v = t.get("v") ? t.get("v")->value<double>() : std::nullopt;
        if (v && (*v == f->get() || (std::isnan(*v) && std::isnan(f->get())))) return text;
      } catch (const toml::parse_error&) {
      }
    } else if (const auto* i = node.as_integer()) {
      std::string plain;
      for (const char c : text)
        if (c != '_' && c != '+') plain += c;
      if (plain == std::to_string(i->get())) return text;
      if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'o' || text[1] == 'b'))
        return text + " (" + std::to_string(i->get()) + ")";
    }
  }
  if (const auto* f = node.as_floating_point()) return orni::displayNumber(f->get());
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  return describeNode(node);
}

toml::table parseTomlText(std::string_view text, const fs::path& file) {
  const std::string name = displayPath(file);
  {
    SourceTexts& registry = sourceTexts();
    const std::lock_guard<std::mutex> lock(registry.mutex);
    registry.texts[name] = std::string(text);
  }
  try {
    return toml::parse(text, std::string(name));
  } catch (const toml::parse_error& e) {
    throw InputError::syntax(name, static_cast<int>(e.source().begin.line),
                             std::string(e.description()));
  }
}

toml::table parseTomlFile(const fs::path& file) {
  const std::string text = readTomlFileText(file);
  return parseTomlText(text, file);
}

// ------------------------------------------------------------------------------------------------
// Text helpers

std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof(buf), value);
  return std::string(buf, res.ptr);
}

std::string TomlWriter::floatText(double value) {
  std::string s = formatNumber(value);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string TomlWriter::scaledText(double si, double si_per_file_unit) {
  if (si_per_file_unit == 1.0 || !std::isfinite(si)) return floatText(si);
  const double guess = si / si_per_file_unit;
  char buf[64];
  for (int precision = 1; precision <= 17; ++precision) {
    const auto res =
        std::to_chars(buf, buf + sizeof(buf), guess, std::chars_format::general, precision);
    double d = 0.0;
    std::from_chars(buf, res.ptr, d);
    if (d * si_per_file_unit == si) return floatText(d);
  }
  double up = guess, down = guess;
  for (int i = 0; i < 8; ++i) {
    up = std::nextafter(up, std::numeric_limits<double>::infinity());
    down = std::nextafter(down, -std::numeric_limits<double>::infinity());
    if (up * si_per_file_unit == si) return floatText(up);
    if (down * si_per_file_unit == si) return floatText(down);
  }
  return floatText(guess);  // no exact file value exists; the closest one
}

std::string TomlWriter::stringText(std::string_view value) {
  std::string s = "\"";
  for (const char ch : value) {
    const unsigned char c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '"':
        s += "\\\"";
        break;
      case '\\':
        s += "\\\\";
        break;
      case '\b':
        s += "\\b";
        break;
      case '\t':
        s += "\\t";
        break;
      case '\n':
        s += "\\n";
        break;
      case '\f':
        s += "\\f";
        break;
      case '\r':
        s += "\\r";
        break;
      default:
        if (c < 0x20 || c == 0x7f) {
          char esc[8];
          std::snprintf(esc, sizeof(esc), "\\u%04X", static_cast<unsigned>(c));
          s += esc;
        } else {
          s += ch;
        }
    }
  }
  s += '"';
  return s;
}

std::string TomlWriter::keyText(std::string_view key) {
  const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
  return bare ? std::string(key) : stringText(key);
}

std::string describeNode(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: {
      std::string v = node.as_string()->get();
      if (v.size() > 100) v = v.substr(0, 97) + "...";
      return "a string " + TomlWriter::stringText(v);
    }
    case toml::node_type::integer:
      return "an integer " + std::to_string(node.as_integer()->get());
    case toml::node_type::floating_point:
      return "a float " + TomlWriter::floatText(node.as_floating_point()->get());
    case toml::node_type::boolean:
      return std::string("a boolean ") + (node.as_boolean()->get() ? "true" : "false");
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array: {
      const toml::array& a = *node.as_array();
      if (a.empty()) return "an empty array";
      if (a.is_array_of_tables()) return "an array of tables";
      return "an array of " + std::to_string(a.size()) + (a.size() == 1 ? " element" : " elements");
    }
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

std::size_t editDistance(std::string_view a, std::string_view b) {
  // Optimal string alignment: Levenshtein plus transpositions of adjacent characters.
  const std::size_t n = b.size();
  std::vector<std::size_t> prev2(n + 1), prev(n + 1), row(n + 1);
  for (std::size_t j = 0; j <= n; ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= n; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({prev[j] + 1, row[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        row[j] = std::min(row[j], prev2[j - 2] + 1);
    }
    prev2.swap(prev);
    prev.swap(row);
  }
  return prev[n];
}

std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates) {
  auto lower = [](std::string_view s) {
    std::string r(s);
    for (char& c : r)
      if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return r;
  };
  const std::string w = lower(word);
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const std::string& c : candidates) {
    const std::size_t d = editDistance(w, lower(c));
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  // A likely typo: one edit for short words, up to a third of the length for longer ones.
  const std::size_t len = std::max(word.size(), best.size());
  const std::size_t limit = len <= 4 ? 1 : std::max<std::size_t>(2, len / 3);
  return best_d <= limit ? best : std::string();
}

// ------------------------------------------------------------------------------------------------
// Range

// ------------------------------------------------------------------------------------------------
// TableReader

namespace {

const std::string* sourcePath(const toml::node& node) {
  const auto& p = node.source().path;
  return (p && !p->empty()) ? p.get() : nullptr;
}

std::string joinQuoted(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i) s += (i + 1 == names.size()) ? " or " : ", ";
    s += TomlWriter::stringText(names[i]);
  }
  return s;
}

}  // namespace

TableReader::TableReader(const toml::table& table, std::string path,
                         std::shared_ptr<const ReadContext> context,
                         std::vector<std::string> allowed)
    : table_(&table),
      path_(std::move(path)),
      context_(std::move(context)),
      allowed_(std::move(allowed)) {
  if (!context_) context_ = std::make_shared<ReadContext>();
  for (const auto& kv : *table_) {
    const std::string key(kv.first.str());
    if (std::find(allowed_.begin(), allowed_.end(), key) != allowed_.end()) continue;
    std::string hint;
    const std::string near = closestMatch(key, allowed_);
    if (!near.empty()) {
      hint = "did you mean '" + near + "'?";
    } else if (allowed_.empty()) {
      hint = "no keys are allowed here";
    } else {
      hint = "allowed keys: ";
      for (std::size_t i = 0; i < allowed_.size(); ++i) hint += (i ? ", " : "") + allowed_[i];
    }
    throw InputError::unknownKey(fileOf(key), lineOf(key), keyPath(key), hint);
  }
}

bool TableReader::has(std::string_view key) const { return nodeOf(key) != nullptr; }

const toml::node* TableReader::nodeOf(std::string_view key) const { return table_->get(key); }

const toml::node& TableReader::locator(std::string_view key) const {
  const toml::node* n = nodeOf(key);
  return n ? *n : *table_;
}

std::string TableReader::childPath(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

std::string TableReader::keyPath(std::string_view key) const {
  const std::string* src = sourcePath(locator(key));
  if (src && !context_->foreign_file.empty() && *src == context_->foreign_file)
    return context_->foreign_prefix + childPath(key);
  return childPath(key);
}

std::string TableReader::fileOf(std::string_view key) const {
  const std::string* src = sourcePath(locator(key));
  return src ? *src : context_->file;
}

int TableReader::lineOf(std::string_view key) const {
  const int line = static_cast<int>(locator(key).source().begin.line);
  return line > 0 ? line : 1;
}

InputError TableReader::valueError(std::string_view key, const std::string& expected,
                                   const std::string& got) const {
  return InputError::wrongValue(fileOf(key), lineOf(key), keyPath(key), expected, got);
}

InputError TableReader::missingError(std::string_view key, const std::string& expected) const {
  return InputError::missingKey(fileOf(key), lineOf(key), keyPath(key), expected);
}

const toml::node* TableReader::take(std::string_view key) {
  if (std::find(allowed_.begin(), allowed_.end(), key) == allowed_.end())
    throw std::logic_error("TableReader: key '" + childPath(key) + "' read but not allowed");
  if (std::find(consumed_.begin(), consumed_.end(), key) == consumed_.end())
    consumed_.emplace_back(key);
  return nodeOf(key);
}

std::vector<std::string> TableReader::presentKeys() const {
  std::vector<std::string> keys;
  for (const auto& kv : *table_) keys.emplace_back(kv.first.str());
  return keys;
}

void TableReader::finish() const {
  for (const auto& kv : *table_) {
    const std::string key(kv.first.str());
    if (std::find(consumed_.begin(), consumed_.end(), key) == consumed_.end())
      throw InputError::unknownKey(fileOf(key), lineOf(key), keyPath(key),
                                   "not used in this section");
  }
}

double TableReader::numberValue(std::string_view key, const toml::node& node, const Range& range,
                                std::string_view note) const {
  const std::string n(note);
  double v = 0.0;
  if (const auto* i = node.as_integer()) {
    v = static_cast<double>(i->get());
  } else if (const auto* f = node.as_floating_point()) {
    v = f->get();
  } else {
    throw valueError(key, range.describe() + n, describeNode(node));
  }
  if (!std::isfinite(v))
    throw valueError(key, range.describe("a finite number") + n, sourceText(node));
  if (!range.contains(v)) throw valueError(key, range.describe() + n, sourceText(node));
  return v;
}

double TableReader::requiredDouble(std::string_view key, const Range& range,
                                   std::string_view note) {
  const toml::node* n = take(key);
  if (!n) throw missingError(key, range.describe() + std::string(note));
  return numberValue(key, *n, range, note);
}

double TableReader::optionalDouble(std::string_view key, double fallback, const Range& range) {
  const toml::node* n = take(key);
  return n ? numberValue(key, *n, range) : fallback;
}

std::optional<double> TableReader::maybeDouble(std::string_view key, const Range& range) {
  const toml::node* n = take(key);
  if (!n) return std::nullopt;
  return numberValue(key, *n, range);
}

int TableReader::intValue(std::string_view key, const toml::node& node, int lo, int hi) const {
  const std::string expected =
      "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  const auto* i = node.as_integer();
  if (!i) throw valueError(key, expected, describeNode(node));
  const std::int64_t v = i->get();
  if (v < lo || v > hi) throw valueError(key, expected, sourceText(node));
  return static_cast<int>(v);
}

std::string_view TableReader::localKey(const orni::FieldSpec& f) {
  const std::size_t dot = f.key.rfind('.');
  return dot == std::string_view::npos ? f.key : f.key.substr(dot + 1);
}

int TableReader::requiredInt(const orni::FieldSpec& f) {
  return requiredInt(localKey(f), static_cast<int>(f.range.lo), static_cast<int>(f.range.hi));
}

int TableReader::optionalInt(const orni::FieldSpec& f, int fallback) {
  return optionalInt(localKey(f), fallback, static_cast<int>(f.range.lo),
                     static_cast<int>(f.range.hi));
}

int TableReader::requiredInt(std::string_view key, int lo, int hi) {
  const toml::node* n = take(key);
  if (!n)
    throw missingError(key,
                       "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return intValue(key, *n, lo, hi);
}

int TableReader::optionalInt(std::string_view key, int fallback, int lo, int hi) {
  const toml::node* n = take(key);
  return n ? intValue(key, *n, lo, hi) : fallback;
}

bool TableReader::requiredBool(std::string_view key) {
  const toml::node* n = take(key);
  if (!n) throw missingError(key, "a boolean (true or false)");
  const auto* b = n->as_boolean();
  if (!b) throw valueError(key, "a boolean (true or false)", describeNode(*n));
  return b->get();
}

bool TableReader::optionalBool(std::string_view key, bool fallback) {
  if (has(key)) return requiredBool(key);
  take(key);
  return fallback;
}

std::string TableReader::requiredString(std::string_view key, bool allow_empty) {
  const std::string expected = allow_empty ? "a string" : "a non-empty string";
  const toml::node* n = take(key);
  if (!n) throw missingError(key, expected);
  const auto* s = n->as_string();
  if (!s || (!allow_empty && s->get().empty())) throw valueError(key, expected, describeNode(*n));
  return s->get();
}

std::string TableReader::optionalString(std::string_view key, const std::string& fallback,
                                        bool allow_empty) {
  if (has(key)) return requiredString(key, allow_empty);
  take(key);
  return fallback;
}

std::size_t TableReader::choiceIndex(std::string_view key, const std::vector<std::string>& names,
                                     bool required) {
  const std::string expected = "one of " + joinQuoted(names);
  const toml::node* n = take(key);
  if (!n) {
    if (required) throw missingError(key, expected);
    return names.size();
  }
  const auto* s = n->as_string();
  if (!s) throw valueError(key, expected, describeNode(*n));
  const auto it = std::find(names.begin(), names.end(), s->get());
  if (it == names.end()) {
    std::string got = describeNode(*n);
    const std::string near = closestMatch(s->get(), names);
    if (!near.empty()) got += " (did you mean " + TomlWriter::stringText(near) + "?)";
    throw valueError(key, expected, got);
  }
  return static_cast<std::size_t>(it - names.begin());
}

std::vector<double> TableReader::requiredNumberArray(std::string_view key, std::size_t size,
                                                     const Range& each) {
  const std::string expected =
      (size ? "an array of " + std::to_string(size) + " numbers"
            : std::string("an array of numbers")) +
      (std::isfinite(each.lo) || std::isfinite(each.hi) ? " (each " + each.describe() + ")"
                                                        : std::string());
  const toml::node* n = take(key);
  if (!n) throw missingError(key, expected);
  const auto* a = n->as_array();
  if (!a || (size && a->size() != size)) throw valueError(key, expected, describeNode(*n));
  std::vector<double> values;
  values.reserve(a->size());
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    double v = 0.0;
    if (const auto* iv = e.as_integer()) {
      v = static_cast<double>(iv->get());
    } else if (const auto* fv = e.as_floating_point()) {
      v = fv->get();
    } else {
      throw valueError(key, expected, describeNode(e) + " at index " + std::to_string(i));
    }
    if (!std::isfinite(v) || !each.contains(v))
      throw valueError(key, expected, sourceText(e) + " at index " + std::to_string(i));
    values.push_back(v);
  }
  return values;
}

TableReader TableReader::requiredTable(std::string_view key, std::vector<std::string> allowed) {
  const toml::node* n = take(key);
  if (!n) throw missingError(key, "a table [" + childPath(key) + "]");
  const auto* t = n->as_table();
  if (!t) throw valueError(key, "a table [" + childPath(key) + "]", describeNode(*n));
  return TableReader(*t, childPath(key), context_, std::move(allowed));
}

std::optional<TableReader> TableReader::optionalTable(std::string_view key,
                                                      std::vector<std::string> allowed) {
  if (!has(key)) {
    take(key);
    return std::nullopt;
  }
  return requiredTable(key, std::move(allowed));
}

std::vector<TableReader> TableReader::optionalTableArray(std::string_view key,
                                                         std::vector<std::string> allowed) {
  const toml::node* n = take(key);
  std::vector<TableReader> readers;
  if (!n) return readers;
  const std::string expected = "an array of tables [[" + childPath(key) + "]]";
  const auto* a = n->as_array();
  if (!a) throw valueError(key, expected, describeNode(*n));
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    const auto* t = e.as_table();
    if (!t) throw valueError(key, expected, describeNode(e) + " at index " + std::to_string(i));
    readers.emplace_back(*t, childPath(key) + "[" + std::to_string(i) + "]", context_, allowed);
  }
  return readers;
}

// ------------------------------------------------------------------------------------------------
// TomlWriter

namespace {

std::string headerText(const std::vector<std::string>& parts) {
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i)
    s += (i ? "." : "") + TomlWriter::keyText(parts[i]);
  return s;
}

}  // namespace

void TomlWriter::comment(std::string_view text) {
  std::istringstream in{std::string(text)};
  std::string l;
  while (std::getline(in, l)) out_ += l.empty() ? "#\n" : "# " + l + "\n";
}

void TomlWriter::blank() { out_ += "\n"; }

void TomlWriter::header(const std::vector<std::string>& parts) {
  if (!out_.empty() && out_.back() == '\n' && out_.size() > 1 && out_[out_.size() - 2] != '\n')
    blank();
  out_ += "[" + headerText(parts) + "]\n";
  setHeader(parts);
}

void TomlWriter::arrayHeader(const std::vector<std::string>& parts) {
  if (!out_.empty() && out_.back() == '\n' && out_.size() > 1 && out_[out_.size() - 2] != '\n')
    blank();
  out_ += "[[" + headerText(parts) + "]]\n";
  setHeader(parts);
}

void TomlWriter::setHeader(const std::vector<std::string>& parts) {
  header_path_.clear();
  for (std::size_t i = 0; i < parts.size(); ++i) header_path_ += (i ? "." : "") + parts[i];
}

void TomlWriter::leaveOut(std::vector<std::string> paths, std::string note) {
  left_out_ = std::move(paths);
  left_out_note_ = std::move(note);
}

void TomlWriter::line(std::string_view key, const std::string& value, std::string_view note) {
  if (!left_out_.empty()) {
    const std::string path =
        header_path_.empty() ? std::string(key) : header_path_ + "." + std::string(key);
    if (std::find(left_out_.begin(), left_out_.end(), path) != left_out_.end()) {
      out_ += "# " + std::string(key) + ": " + left_out_note_ + "\n";
      return;
    }
  }
  out_ += keyText(key) + " = " + value;
  if (!note.empty()) out_ += "  # " + std::string(note);
  out_ += "\n";
}

void TomlWriter::string(std::string_view key, std::string_view value, std::string_view note) {
  line(key, stringText(value), note);
}

void TomlWriter::integer(std::string_view key, long long value, std::string_view note) {
  line(key, std::to_string(value), note);
}

void TomlWriter::boolean(std::string_view key, bool value, std::string_view note) {
  line(key, value ? "true" : "false", note);
}

void TomlWriter::number(std::string_view key, double value, std::string_view note) {
  line(key, floatText(value), note);
}

void TomlWriter::scaled(std::string_view key, double si, double si_per_file_unit,
                        std::string_view note) {
  line(key, scaledText(si, si_per_file_unit), note);
}

void TomlWriter::numberArray(std::string_view key, const std::vector<double>& values,
                             std::string_view note) {
  std::string s = "[";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + floatText(values[i]);
  s += "]";
  line(key, s, note);
}

void TomlWriter::stringArray(std::string_view key, const std::vector<std::string>& values,
                             std::string_view note) {
  std::string s = "[";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + stringText(values[i]);
  s += "]";
  line(key, s, note);
}

}  // namespace orni::studies
