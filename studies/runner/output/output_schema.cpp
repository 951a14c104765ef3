#include "studies/runner/output/output_schema.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/model/field_table.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/json_reader.hpp"

namespace orni::studies {

namespace {

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = s.find(sep, start);
    out.push_back(
        s.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return out;
    start = end + 1;
  }
}

bool endsWith(std::string_view s, std::string_view tail) {
  return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

/// Does pattern[pi..] match path[si..]? A "<key>" segment (with any literal suffix such as "[]")
/// takes one or more path segments that join to a field-table key; "<output>" takes one segment.
bool matchFrom(const std::vector<std::string_view>& pattern, std::size_t pi,
               const std::vector<std::string_view>& path, std::size_t si) {
  if (pi == pattern.size()) return si == path.size();
  if (si == path.size()) return false;
  const std::string_view p = pattern[pi];
  if (p.substr(0, 5) == "<key>") {
    const std::string_view suffix = p.substr(5);
    std::string joined;
    for (std::size_t sj = si; sj < path.size(); ++sj) {
      if (sj > si) joined += '.';
      joined += path[sj];
      if (!endsWith(joined, suffix)) continue;
      const std::string key = joined.substr(0, joined.size() - suffix.size());
      if (findField(key) != nullptr && matchFrom(pattern, pi + 1, path, sj + 1)) return true;
    }
    return false;
  }
  const std::size_t open = p.find('<'), close = p.find('>');
  if (open != std::string_view::npos && close != std::string_view::npos && close > open) {
    // <output>, <variable>, w_<mode>, ...: one name, with the segment's literal prefix and suffix.
    const std::string_view prefix = p.substr(0, open), suffix = p.substr(close + 1);
    const std::string_view seg = path[si];
    return seg.size() > prefix.size() + suffix.size() && seg.substr(0, prefix.size()) == prefix &&
           endsWith(seg, suffix) && matchFrom(pattern, pi + 1, path, si + 1);
  }
  return p == path[si] && matchFrom(pattern, pi + 1, path, si + 1);
}

std::string escapeMarkdown(std::string_view s) {
  std::string out;
  for (const char c : s) {
    if (c == '|') out += "\\|";
    else out += c;
  }
  return out;
}

std::vector<std::string_view> filesInOrder() {
  std::vector<std::string_view> files;
  for (const OutputSpec& o : outputTable())
    if (std::find(files.begin(), files.end(), o.file) == files.end()) files.push_back(o.file);
  return files;
}

/// The entry of a summary object or array of objects (path a proper prefix of its path) that a run
/// writes as null or [] when it does not exist for it (a failed simulation's mean, a failed
/// periodic trim's multipliers), or nullptr.
const OutputSpec* findObjectOutput(std::string_view path) {
  const std::vector<std::string_view> concrete = split(path, '.');
  for (const OutputSpec& o : outputTable()) {
    if (o.file != "summary.json") continue;
    const std::vector<std::string_view> pattern = split(o.path, '.');
    for (std::size_t n = 1; n < pattern.size(); ++n)
      if (matchFrom({pattern.begin(), pattern.begin() + static_cast<std::ptrdiff_t>(n)}, 0,
                    concrete, 0))
        return &o;
  }
  return nullptr;
}

void checkOne(OutputCheck& check, const std::string& file, const std::string& path,
              const std::string* unit, bool no_value = false) {
  const OutputSpec* o = findOutput(file, path);
  if (o == nullptr && no_value) o = findObjectOutput(path);
  if (o == nullptr) {
    check.findings.push_back(file + " " + path + ": not in the output table");
    return;
  }
  check.used.insert(o);
  if (!outputKindListed(o->kinds, check.kind))
    check.findings.push_back(file + " " + path + ": written by a " + check.kind +
                             " run, the table lists " + std::string(o->kinds));
  if (unit != nullptr && o->unit != "per key" && o->unit != "per variable" && *unit != o->unit)
    check.findings.push_back(file + " " + path + ": units row '" + *unit + "', the table '" +
                             std::string(o->unit) + "'");
}

void checkSummary(OutputCheck& check, const JsonValue& v, const std::string& path) {
  if (v.type == JsonValue::Type::kObject) {
    for (const auto& [k, m] : v.members) checkSummary(check, m, path.empty() ? k : path + "." + k);
    return;
  }
  if (v.type == JsonValue::Type::kArray) {
    bool nested = false;
    for (const JsonValue& e : v.items)
      if (!e.isScalar()) {
        nested = true;
        checkSummary(check, e, path + "[]");
      }
    if (nested) return;
    ++check.summary_values;
    checkOne(check, "summary.json", path + "[]", nullptr, v.items.empty());
    return;
  }
  ++check.summary_values;
  checkOne(check, "summary.json", path, nullptr, v.type == JsonValue::Type::kNull);
}

}  // namespace

OutputCheck checkSummaryText(const std::string& json_text) {
  const JsonValue summary = parseJson(json_text);
  const JsonValue* kind = summary.find("kind");
  if (kind == nullptr || kind->type != JsonValue::Type::kString)
    throw std::runtime_error("no \"kind\"");
  OutputCheck check;
  check.kind = kind->text;
  checkSummary(check, summary, "");
  return check;
}

OutputCheck checkRunFolder(const std::string& run_dir) {
  namespace fs = std::filesystem;
  const fs::path dir(run_dir);
  std::ifstream in(dir / "summary.json", std::ios::binary);
  if (!in) throw std::runtime_error(run_dir + ": no summary.json (not a finished run folder)");
  std::ostringstream text;
  text << in.rdbuf();
  OutputCheck check;
  try {
    check = checkSummaryText(text.str());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(run_dir + "/summary.json: " + e.what());
  }
  std::vector<fs::path> csvs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".csv") csvs.push_back(e.path());
  std::sort(csvs.begin(), csvs.end());
  for (const fs::path& csv : csvs) {
    std::ifstream f(csv);
    std::string names_line, units_line;
    std::getline(f, names_line);
    std::getline(f, units_line);
    const std::vector<std::string> names = csvLineCells(names_line),
                                   units = csvLineCells(units_line);
    const std::string file = csv.filename().string();
    for (std::size_t c = 0; c < names.size(); ++c) {
      ++check.csv_columns;
      checkOne(check, file, names[c], c < units.size() ? &units[c] : nullptr);
    }
  }
  return check;
}

const OutputSpec* findOutput(std::string_view file, std::string_view path) {
  const std::vector<std::string_view> concrete = split(path, '.');
  for (const OutputSpec& o : outputTable())
    if (o.file == file && matchFrom(split(o.path, '.'), 0, concrete, 0)) return &o;
  return nullptr;
}

std::string declaredColumnUnit(std::string_view file, std::string_view column) {
  const OutputSpec* o = findOutput(file, column);
  if (o == nullptr)
    throw std::logic_error("output table: no entry for column '" + std::string(column) + "' of " +
                           (file.empty() ? std::string("a CSV table without a file name")
                                         : std::string(file)) +
                           " (studies/runner/output/output_schema_table.cpp)");
  if (o->unit == "per key" || o->unit == "per variable")
    throw std::logic_error("output table: column '" + std::string(column) + "' of " +
                           std::string(file) + " has a unit of its own (" + std::string(o->unit) +
                           "); the writer names it");
  return std::string(o->unit);
}

void demandDeclaredColumn(std::string_view file, std::string_view column, std::string_view unit) {
  const OutputSpec* o = findOutput(file, column);
  if (o == nullptr)
    throw std::logic_error("output table: no entry for column '" + std::string(column) + "' of " +
                           std::string(file) + " (studies/runner/output/output_schema_table.cpp)");
  if (o->unit != "per key" && o->unit != "per variable" && o->unit != unit)
    throw std::logic_error("output table: column '" + std::string(column) + "' of " +
                           std::string(file) + " is declared in " + std::string(o->unit) +
                           ", written in " + std::string(unit));
}

bool outputKindListed(std::string_view kinds, std::string_view kind) {
  for (const std::string_view k : split(kinds, ','))
    if (k == kind) return true;
  return false;
}

std::vector<std::string_view> outputKinds() {
  std::vector<std::string_view> kinds;
  for (const OutputSpec& o : outputTable())
    for (const std::string_view k : split(o.kinds, ','))
      if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
  return kinds;
}

std::string outputListing(std::string_view kind, bool markdown) {
  std::string out;
  for (const std::string_view file : filesInOrder()) {
    std::vector<const OutputSpec*> rows;
    for (const OutputSpec& o : outputTable())
      if (o.file == file && (kind.empty() || outputKindListed(o.kinds, kind))) rows.push_back(&o);
    if (rows.empty()) continue;
    if (!out.empty()) out += "\n";
    if (markdown) {
      out += "#### " + std::string(file) + "\n\n";
      out += std::string("| ") + (file == "summary.json" ? "value" : "column") +
             " | unit | written by | meaning |\n| --- | --- | --- | --- |\n";
      for (const OutputSpec* o : rows)
      {
        std::string kinds;
        for (const std::string_view k : split(o->kinds, ','))
          kinds += (kinds.empty() ? "" : ", ") + std::string(k);
        out += "| `" + std::string(o->path) + "` | " + escapeMarkdown(o->unit) + " | " +
               escapeMarkdown(kinds) + " | " + escapeMarkdown(o->meaning) + " |\n";
      }
      continue;
    }
    std::size_t w_path = 6, w_unit = 4, w_kinds = 10;
    for (const OutputSpec* o : rows) {
      w_path = std::max(w_path, o->path.size());
      w_unit = std::max(w_unit, o->unit.size());
      w_kinds = std::max(w_kinds, o->kinds.size());
    }
    auto line = [&](std::string_view a, std::string_view b, std::string_view c,
                    std::string_view d) {
      return std::string(a) + std::string(w_path - a.size() + 2, ' ') + std::string(b) +
             std::string(w_unit - b.size() + 2, ' ') + std::string(c) +
             std::string(w_kinds - c.size() + 2, ' ') + std::string(d) + "\n";
    };
    out += "[" + std::string(file) + "]\n" +
           line(file == "summary.json" ? "value" : "column", "unit", "written by", "meaning");
    for (const OutputSpec* o : rows) out += line(o->path, o->unit, o->kinds, o->meaning);
  }
  return out;
}

}  // namespace orni::studies
