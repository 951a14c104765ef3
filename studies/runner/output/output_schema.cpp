#include "studies/runner/output/output_schema.hpp"

#include <algorithm>

#include "core/model/field_table.hpp"

namespace orni::studies {

namespace {

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = s.find(sep, start);
    out.push_back(s.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
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
  for (const std::string_view ph : {std::string_view("<key>"), std::string_view("<output>")}) {
    if (p.substr(0, ph.size()) != ph) continue;
    const std::string_view suffix = p.substr(ph.size());
    if (ph == "<output>") {
      const std::string_view seg = path[si];
      return endsWith(seg, suffix) && seg.size() > suffix.size() &&
             matchFrom(pattern, pi + 1, path, si + 1);
    }
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

}  // namespace

const OutputSpec* findOutput(std::string_view file, std::string_view path) {
  const std::vector<std::string_view> concrete = split(path, '.');
  for (const OutputSpec& o : outputTable())
    if (o.file == file && matchFrom(split(o.path, '.'), 0, concrete, 0)) return &o;
  return nullptr;
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
