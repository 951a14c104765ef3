#include "studies/runner/commands/keys_command.hpp"

#include <algorithm>
#include <vector>

#include "core/model/field_table.hpp"

namespace orni::studies {

namespace {

/// The type-and-range column: "[0.005, 20]", "integer in [1, 500]", "rigid | flexible", ...
std::string rangeText(const FieldSpec& f) {
  switch (f.type) {
    case FieldType::kNumber:
      return f.rangeOfAnotherKey() ? "number, in the range of the " + std::string(f.unit)
                                   : f.range.interval();
    case FieldType::kInteger: return "integer " + f.range.interval();
    case FieldType::kBoolean: return "true | false";
    case FieldType::kString: return "string";
    case FieldType::kChoice: return std::string(f.choices);
    case FieldType::kPair: return "[a, b], each " + f.range.interval();
    case FieldType::kNumberList: return "[a, ...], each " + f.range.interval();
    case FieldType::kGrid:
      return f.rangeOfAnotherKey() ? "\"A:B:N\" or numbers, in the range of the key"
                                   : "\"A:B:N\" or numbers, each " + f.range.interval();
    case FieldType::kStringList: return "array of strings";
    case FieldType::kTable: return "table";
  }
  return std::string();
}

/// The meaning column: the meaning, the rule tying the key to others, the command-line options.
std::string meaningText(const FieldSpec& f) {
  std::string s(f.meaning);
  if (!f.also.empty()) s += "; " + std::string(f.also);
  if (!f.cli.empty()) s += " (command line: " + std::string(f.cli) + ")";
  return s;
}

std::string unitText(const FieldSpec& f) {
  return f.rangeOfAnotherKey() ? "as the " + std::string(f.unit) : std::string(f.unit);
}

std::vector<std::vector<std::string>> rows(std::string_view group) {
  std::vector<std::vector<std::string>> out;
  for (const FieldSpec& f : fieldTable())
    if (f.group() == group)
      out.push_back({std::string(f.key), unitText(f), rangeText(f), std::string(f.default_text),
                     meaningText(f)});
  return out;
}

std::string escapeMarkdown(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '|') out += "\\|";
    else out += c;
  }
  return out;
}

std::string plainGroup(std::string_view group) {
  const std::vector<std::vector<std::string>> r = rows(group);
  const std::vector<std::string> head = {"key", "unit", "range", "default", "meaning"};
  std::vector<std::size_t> width(head.size());
  for (std::size_t c = 0; c < head.size(); ++c) width[c] = head[c].size();
  for (const auto& row : r)
    for (std::size_t c = 0; c + 1 < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  auto line = [&](const std::vector<std::string>& cells) {
    std::string s;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      s += cells[c];
      if (c + 1 < cells.size()) s += std::string(width[c] - cells[c].size() + 2, ' ');
    }
    return s + "\n";
  };
  std::string s = "[" + std::string(group) + "]\n" + line(head);
  for (const auto& row : r) s += line(row);
  return s;
}

std::string markdownGroup(std::string_view group) {
  std::string s = "#### " + std::string(group) + "\n\n";
  s += "| key | unit | range | default | meaning |\n| --- | --- | --- | --- | --- |\n";
  for (const auto& row : rows(group)) {
    s += "|";
    for (std::size_t c = 0; c < row.size(); ++c)
      s += " " + (c == 0 ? "`" + row[c] + "`" : escapeMarkdown(row[c])) + " |";
    s += "\n";
  }
  return s;
}

}  // namespace

std::optional<std::string> keysText(std::string_view group, bool markdown) {
  const std::vector<std::string_view>& groups = fieldGroups();
  if (!group.empty() && std::find(groups.begin(), groups.end(), group) == groups.end())
    return std::nullopt;
  std::string out;
  for (std::string_view g : groups) {
    if (!group.empty() && g != group) continue;
    if (!out.empty()) out += "\n";
    out += markdown ? markdownGroup(g) : plainGroup(g);
  }
  return out;
}

}  // namespace orni::studies
