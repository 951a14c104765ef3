#include "studies/runner/output/html_report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "studies/runner/config/study_file.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/json_reader.hpp"
#include "studies/runner/output/output_schema.hpp"
#include "studies/runner/output/run_outputs.hpp"

namespace orni::studies {

namespace fs = std::filesystem;

namespace {

const char* const kReportName = "index.html";

// One style for every page: system fonts, a readable measure, tables with aligned numbers.
const char* const kStyle = R"css(
body { font-family: system-ui, -apple-system, "Segoe UI", "DejaVu Sans", sans-serif;
       margin: 2em auto; max-width: 78em; padding: 0 1em; color: #1a1a1a; line-height: 1.4; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; }
h2 { font-size: 1.25em; margin-top: 1.6em; border-bottom: 1px solid #ddd; }
.sub { color: #555; margin-top: 0; }
.status { display: inline-block; padding: 0.1em 0.6em; border-radius: 0.3em; font-weight: 600; }
.good { background: #d9f2dd; color: #17582a; }
.bad { background: #f8d7d7; color: #7a1a1a; }
.other { background: #fbeecb; color: #6b4d00; }
.message { background: #f6f6f6; padding: 0.6em 0.8em; border-left: 3px solid #bbb;
           white-space: pre-wrap; }
table { border-collapse: collapse; margin: 0.5em 0; }
th, td { border-bottom: 1px solid #e4e4e4; padding: 0.2em 0.8em 0.2em 0; text-align: left;
         vertical-align: top; }
td.num { font-variant-numeric: tabular-nums; text-align: right; white-space: nowrap; }
td.key { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-size: 0.92em; }
td.text { max-width: 50em; }
figure { margin: 1em 0 2em 0; }
figure img { max-width: 100%; height: auto; border: 1px solid #e4e4e4; }
figcaption { color: #444; font-size: 0.92em; }
details { margin: 0.4em 0; }
summary { cursor: pointer; font-weight: 600; }
footer { margin-top: 3em; color: #777; font-size: 0.85em; }
)css";

std::string escapeHtml(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

/// A file name as a relative URL (percent-encoding what is not safe in a path segment).
std::string hrefOf(const std::string& relative) {
  static const char* const kHex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : relative) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~' || c == '/') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

JsonValue readSummary(const fs::path& dir) {
  const fs::path file = dir / "summary.json";
  try {
    return parseJson(readText(file));
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("no report for " + dir.string() + ": " + file.string() + ": " +
                             e.what());
  }
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The unit of a summary key from its suffix (FV_N -> N, M_Nm -> N m, theta_mean_deg -> deg);
/// "" when the suffix names none.
std::string unitOf(const std::string& key) {
  static const std::vector<std::pair<std::string, std::string>> kExtra = {
      {"_j", "J"}, {"_pa", "Pa"}, {"_rad", "rad"}, {"_mm", "mm"}};
  const std::string k = lower(key);
  for (const auto& [suffix, unit] : kExtra)
    if (k.size() > suffix.size() && k.compare(k.size() - suffix.size(), suffix.size(), suffix) == 0)
      return unit;
  const std::string unit = keyUnit(k);
  return unit == "-" ? std::string() : unit;
}

/// A number for reading: 6 significant digits (the exact text stays in the title).
std::string readableNumber(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !std::isfinite(v)) return text;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string scalarCell(const JsonValue& v) {
  switch (v.type) {
    case JsonValue::Type::kNull: return "<td class=\"text\"><em>none</em></td>";
    case JsonValue::Type::kBool: return std::string("<td class=\"text\">") +
                                        (v.boolean ? "yes" : "no") + "</td>";
    case JsonValue::Type::kNumber:
      return "<td class=\"num\" title=\"" + escapeHtml(v.text) + "\">" +
             escapeHtml(readableNumber(v.text)) + "</td>";
    case JsonValue::Type::kString: return "<td class=\"text\">" + escapeHtml(v.text) + "</td>";
    default: return "<td></td>";
  }
}

/// An array in one cell: its scalars (at most 12 shown), or how many entries it has.
std::string arrayCell(const JsonValue& v) {
  constexpr std::size_t kShown = 12;
  bool scalars = true;
  for (const JsonValue& item : v.items) scalars = scalars && item.isScalar();
  if (!scalars || v.items.empty())
    return "<td class=\"text\">" + std::to_string(v.items.size()) + " entries</td>";
  std::string out = "<td class=\"text\">";
  for (std::size_t i = 0; i < v.items.size() && i < kShown; ++i) {
    const JsonValue& item = v.items[i];
    if (i) out += ", ";
    out += escapeHtml(item.type == JsonValue::Type::kNumber ? readableNumber(item.text)
                      : item.type == JsonValue::Type::kBool ? (item.boolean ? "yes" : "no")
                      : item.type == JsonValue::Type::kNull ? "none"
                                                            : item.text);
  }
  if (v.items.size() > kShown)
    out += ", ... (" + std::to_string(v.items.size()) + " entries)";
  return out + "</td>";
}

/// The unit and meaning cells of the summary value at `path` (JSON path, "[]" for an array): from
/// the output table (output_schema.hpp), or the unit the key's suffix names when the table does not
/// describe it.
std::string unitAndMeaningCells(const std::string& path, const std::string& key,
                                const JsonValue& v) {
  const OutputSpec* o =
      findOutput("summary.json", v.type == JsonValue::Type::kArray ? path + "[]" : path);
  if (o == nullptr) return "<td>" + escapeHtml(unitOf(key)) + "</td><td></td>";
  const std::string unit = o->unit == "-" ? std::string() : std::string(o->unit);
  return "<td>" + escapeHtml(unit) + "</td><td class=\"text\">" +
         escapeHtml(std::string(o->meaning)) + "</td>";
}

/// Rows "key | value | unit | meaning" for the scalars and arrays of `object` (nested objects
/// flattened with dotted keys below `prefix`, the JSON path below `json_prefix`).
void appendRows(const JsonValue& object, const std::string& prefix, const std::string& json_prefix,
                std::string& rows) {
  for (const auto& [key, v] : object.members) {
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    const std::string json_path = json_prefix.empty() ? key : json_prefix + "." + key;
    if (v.type == JsonValue::Type::kObject) {
      appendRows(v, path, json_path, rows);
      continue;
    }
    rows += "<tr><td class=\"key\">" + escapeHtml(path) + "</td>";
    rows += v.type == JsonValue::Type::kArray ? arrayCell(v) : scalarCell(v);
    rows += unitAndMeaningCells(json_path, key, v) + "</tr>\n";
  }
}

std::string table(const std::string& rows) {
  return "<table>\n<tr><th>key</th><th>value</th><th>unit</th><th>meaning</th></tr>\n" + rows +
         "</table>\n";
}

std::string statusClass(const std::string& status) {
  if (status == "ok" || status == "bounded" || status == "converged") return "good";
  if (status == "failed" || status == "diverged" || status == "unbounded") return "bad";
  return "other";
}

std::string stringMember(const JsonValue& object, std::string_view key) {
  const JsonValue* v = object.find(key);
  return v && v->type == JsonValue::Type::kString ? v->text : std::string();
}

std::string pageHead(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         escapeHtml(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
}

struct FolderFiles {
  std::vector<std::string> figures;       ///< stems with an .svg or .png, in the kind's order
  std::vector<std::string> undrawn;       ///< stems with only a .gp script
  std::vector<std::string> other;         ///< every other file (not hidden, not the report)
  std::set<std::string> names;
};

FolderFiles listFolder(const fs::path& dir, const std::string& kind) {
  FolderFiles f;
  for (const auto& e : fs::directory_iterator(dir)) {
    std::error_code ec;
    if (!e.is_regular_file(ec)) continue;
    const std::string name = e.path().filename().string();
    if (name.empty() || name[0] == '.' || name == kReportName) continue;
    f.names.insert(name);
  }
  std::set<std::string> stems;
  for (const std::string& n : f.names) {
    const fs::path p(n);
    const std::string ext = p.extension().string();
    if ((ext == ".gp" || ext == ".png" || ext == ".svg") && isFigureOfKind(kind, p.stem().string()))
      stems.insert(p.stem().string());
  }
  // The kind's own order (runOutputsByKind), then any other stem alphabetically.
  std::vector<std::string> ordered;
  for (const KindOutputs& k : runOutputsByKind())
    if (k.kind == kind)
      for (const std::string& pattern : k.figure_stems)
        for (const std::string& s : stems) {
          if (stemMatches(pattern, s) &&
              std::find(ordered.begin(), ordered.end(), s) == ordered.end())
            ordered.push_back(s);
        }
  for (const std::string& s : stems)
    if (std::find(ordered.begin(), ordered.end(), s) == ordered.end()) ordered.push_back(s);
  std::set<std::string> shown;
  for (const std::string& s : ordered) {
    if (f.names.count(s + ".svg") || f.names.count(s + ".png")) {
      f.figures.push_back(s);
      shown.insert(s + ".svg");
      shown.insert(s + ".png");
    } else {
      f.undrawn.push_back(s);
    }
    shown.insert(s + ".gp");
  }
  for (const std::string& n : f.names)
    if (!shown.count(n)) f.other.push_back(n);
  return f;
}

std::string fileSize(const fs::path& file) {
  std::error_code ec;
  const auto bytes = fs::file_size(file, ec);
  if (ec) return "";
  char buf[32];
  if (bytes < 10 * 1024) std::snprintf(buf, sizeof buf, "%ju B", static_cast<std::uintmax_t>(bytes));
  else if (bytes < 10 * 1024 * 1024) std::snprintf(buf, sizeof buf, "%.0f KB", bytes / 1024.0);
  else std::snprintf(buf, sizeof buf, "%.1f MB", bytes / (1024.0 * 1024.0));
  return buf;
}

/// What a file of a run holds, for the files table.
std::string describeFile(const std::string& name) {
  if (name == "summary.json") return "the run's results and verdict (what this page shows)";
  if (name == "study.resolved.toml")
    return "the study as run: every default filled in (`ornithopter run` accepts it)";
  const std::string ext = fs::path(name).extension().string();
  if (ext == ".csv") return "table: a names row, a units row, then the data";
  if (ext == ".toml") return "vehicle or study file";
  if (ext == ".journal") return "journal of finished points (a re-run resumes from it)";
  return "";
}

/// The `name = "..."` of DIR/study.resolved.toml (the study's run name), "" when none.
std::string resolvedStudyName(const fs::path& dir) {
  std::ifstream in(dir / "study.resolved.toml");
  std::string line;
  const std::string key = "name = \"";
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '[') break;  // the top-level keys come first
    if (line.compare(0, key.size(), key) != 0) continue;
    const std::size_t end = line.find('"', key.size());
    if (end != std::string::npos) return line.substr(key.size(), end - key.size());
  }
  return "";
}

}  // namespace

void writeRunReport(const fs::path& run_dir) {
  const JsonValue summary = readSummary(run_dir);
  if (summary.type != JsonValue::Type::kObject)
    throw std::runtime_error("no report for " + run_dir.string() + ": summary.json is not an "
                             "object");
  const std::string kind = stringMember(summary, "kind");
  const std::string status = stringMember(summary, "status");
  const std::string message = stringMember(summary, "message");
  fs::path absolute = fs::absolute(run_dir).lexically_normal();
  if (!absolute.has_filename()) absolute = absolute.parent_path();
  const std::string folder_name = absolute.filename().string();
  const std::string study_name = resolvedStudyName(run_dir);
  const std::string name = study_name.empty() ? folder_name : study_name;
  const FolderFiles files = listFolder(run_dir, kind);

  std::string page = pageHead(name + " (" + kind + ")");
  page += "<h1>" + escapeHtml(name) + "</h1>\n";
  page += "<p class=\"sub\">" + escapeHtml(kind.empty() ? std::string("run") : kind) +
          " run &middot; status <span class=\"status " + statusClass(status) + "\">" +
          escapeHtml(status.empty() ? std::string("unknown") : status) + "</span>";
  for (const char* verdict : {"converged", "bounded"}) {
    const JsonValue* v = summary.find(verdict);
    if (v && v->type == JsonValue::Type::kBool)
      page += std::string(" &middot; ") + verdict + ": <span class=\"status " +
              (v->boolean ? "good" : "bad") + "\">" + (v->boolean ? "yes" : "no") + "</span>";
  }
  page += "</p>\n";
  if (!message.empty()) page += "<p class=\"message\">" + escapeHtml(message) + "</p>\n";

  // Key numbers: the top level's values; each nested object in its own folding section.
  std::string top_rows;
  std::string sections;
  for (const auto& [key, v] : summary.members) {
    if (key == "kind" || key == "status" || key == "message") continue;
    if (v.type == JsonValue::Type::kObject) {
      std::string rows;
      appendRows(v, "", key, rows);
      sections += "<details" + std::string(sections.empty() ? " open" : "") + "><summary>" +
                  escapeHtml(key) + "</summary>\n" + (rows.empty() ? std::string() : table(rows)) +
                  "</details>\n";
      continue;
    }
    top_rows += "<tr><td class=\"key\">" + escapeHtml(key) + "</td>";
    top_rows += v.type == JsonValue::Type::kArray ? arrayCell(v) : scalarCell(v);
    top_rows += unitAndMeaningCells(key, key, v) + "</tr>\n";
  }
  page += "<h2>Results</h2>\n<p>From <a href=\"summary.json\">summary.json</a>; numbers to 6 "
          "significant digits (the exact value is in each number's tooltip).</p>\n";
  if (!top_rows.empty()) page += table(top_rows);
  page += sections;

  page += "<h2>Figures</h2>\n";
  if (files.figures.empty() && files.undrawn.empty()) page += "<p>This run draws no figure.</p>\n";
  for (const std::string& stem : files.figures) {
    // PNG first: every run draws both, but a committed results folder keeps the PNGs only.
    const bool png = files.names.count(stem + ".png") > 0;
    const std::string image = stem + (png ? ".png" : ".svg");
    page += "<figure id=\"fig-" + escapeHtml(stem) + "\"><img src=\"" + hrefOf(image) +
            "\" alt=\"figure " + escapeHtml(stem) + "\">\n<figcaption>" +
            escapeHtml(stem);
    for (const char* ext : {".png", ".svg", ".gp"})
      if (files.names.count(stem + ext))
        page += std::string(" &middot; <a href=\"") + hrefOf(stem + ext) + "\">" + (ext + 1) +
                "</a>";
    page += "</figcaption></figure>\n";
  }
  if (!files.undrawn.empty()) {
    page += "<p>Not drawn (figures were off, or gnuplot was not found); their scripts are kept "
            "and <code>ornithopter plot DIR</code> draws them:</p>\n<ul>\n";
    for (const std::string& stem : files.undrawn)
      page += "<li><a href=\"" + hrefOf(stem + ".gp") + "\">" + escapeHtml(stem) +
              ".gp</a></li>\n";
    page += "</ul>\n";
  }

  page += "<h2>Files</h2>\n<table>\n<tr><th>file</th><th>size</th><th>content</th></tr>\n";
  for (const std::string& n : files.other)
    page += "<tr><td class=\"key\"><a href=\"" + hrefOf(n) + "\">" + escapeHtml(n) +
            "</a></td><td class=\"num\">" + fileSize(run_dir / n) + "</td><td>" +
            escapeHtml(describeFile(n)) + "</td></tr>\n";
  page += "</table>\n";
  const std::string version = stringMember(summary, "version");
  page += "<footer>Written by ornithopter" +
          (version.empty() ? std::string() : " " + escapeHtml(version)) +
          " from the files of this folder; <code>ornithopter report DIR</code> writes it "
          "again.</footer>\n</body>\n</html>\n";
  writeFileAtomic(run_dir / kReportName, page);
}

void writeSetReport(const fs::path& dir, const std::vector<fs::path>& runs) {
  std::string rows;
  for (const fs::path& run : runs) {
    const std::string folder = run.lexically_relative(dir).generic_string();
    const std::string link = (folder.empty() || folder.rfind("..", 0) == 0)
                                 ? run.generic_string()
                                 : folder;
    std::string kind, status, message;
    std::error_code ec;
    if (fs::is_regular_file(run / "summary.json", ec)) {
      try {
        const JsonValue s = readSummary(run);
        kind = stringMember(s, "kind");
        status = stringMember(s, "status");
        message = stringMember(s, "message");
      } catch (const std::runtime_error& e) {
        message = e.what();
      }
    } else {
      status = "no result";
      message = "no summary.json (the run did not finish)";
    }
    constexpr std::size_t kBrief = 240;
    if (message.size() > kBrief) message = message.substr(0, kBrief) + " ...";
    const bool has_report = fs::is_regular_file(run / kReportName, ec);
    rows += "<tr><td class=\"key\">" +
            (has_report ? "<a href=\"" + hrefOf(link + "/" + kReportName) + "\">" +
                              escapeHtml(fs::path(link).filename().string()) + "</a>"
                        : escapeHtml(fs::path(link).filename().string())) +
            "</td><td>" + escapeHtml(kind) + "</td><td><span class=\"status " +
            statusClass(status) + "\">" + escapeHtml(status) + "</span></td><td class=\"text\">" +
            escapeHtml(message) + "</td></tr>\n";
  }
  std::string page = pageHead("ornithopter runs");
  page += "<h1>Runs</h1>\n<p class=\"sub\">" + std::to_string(runs.size()) +
          " run(s); each name opens its report.</p>\n<table>\n<tr><th>run</th><th>kind</th>"
          "<th>status</th><th>message</th></tr>\n" +
          rows + "</table>\n<footer>Written by ornithopter.</footer>\n</body>\n</html>\n";
  writeFileAtomic(dir / kReportName, page);
}

}  // namespace orni::studies
