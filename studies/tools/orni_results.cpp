// orni_results: two small jobs on finished run folders, no physics and no dependencies.
//
//   orni_results compare BASE_DIR NEW_DIR [--rel R] [--abs-scale A] [--report N] [--quiet]
//       Compare every summary.json value and every numeric CSV cell of every run folder under
//       BASE_DIR (a folder holding summary.json, at any depth) with the same file under NEW_DIR.
//       A number passes when |a - b| <= R |b| + A range(column) + floor(unit) (CSV, the unit
//       from the units row) or R |b| + floor(unit) (summary.json, the unit from the key's
//       suffix); see unitFloor. A NaN/null or
//       empty cell where the baseline has a number, a missing file, row or column, a changed
//       status/kind/mode word or boolean fail. Run metadata (wall_time_s, version, ...) and free
//       text (message, report columns and keys) are not compared. Exit 0 = match, 1 = mismatch,
//       2 = bad usage. Prints the worst cells (by |a-b| / tolerance).
//
//   orni_results fill TEMPLATE RESULTS_DIR
//       Write TEMPLATE to stdout with every {{ ... }} replaced by a number computed from the files
//       under RESULTS_DIR (see evalExpression for the little RPN language). A missing file, key or
//       column is an error (exit 2): the generated page never shows a number that is not in a
//       committed file.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw Failure("cannot read " + p.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// ---------------------------------------------------------------- JSON (flattened leaves)
struct JsonLeaf {
  enum Type { kNumber, kString, kBool, kNull } type = kNull;
  double number = 0.0;
  std::string text;  // string value, or "true"/"false"
};
using FlatJson = std::vector<std::pair<std::string, JsonLeaf>>;  // in file order

class JsonParser {
 public:
  explicit JsonParser(const std::string& s) : s_(s) {}
  FlatJson parse() {
    FlatJson out;
    value("", &out);
    ws();
    if (p_ != s_.size()) fail("trailing characters");
    return out;
  }

 private:
  const std::string& s_;
  std::size_t p_ = 0;
  [[noreturn]] void fail(const std::string& why) {
    throw Failure("JSON: " + why + " at offset " + std::to_string(p_));
  }
  void ws() {
    while (p_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[p_]))) ++p_;
  }
  std::string str() {
    if (s_[p_] != '"') fail("expected a string");
    ++p_;
    std::string r;
    while (p_ < s_.size() && s_[p_] != '"') {
      if (s_[p_] == '\\' && p_ + 1 < s_.size()) {
        const char e = s_[++p_];
        if (e == 'n') r += '\n';
        else if (e == 't') r += '\t';
        else if (e == 'u') { r += '?'; p_ += 4; }
        else r += e;
      } else {
        r += s_[p_];
      }
      ++p_;
    }
    if (p_ >= s_.size()) fail("unterminated string");
    ++p_;
    return r;
  }
  void value(const std::string& path, FlatJson* out) {
    ws();
    if (p_ >= s_.size()) fail("unexpected end");
    const char c = s_[p_];
    if (c == '{') {
      ++p_;
      ws();
      if (s_[p_] == '}') { ++p_; return; }
      while (true) {
        ws();
        const std::string k = str();
        ws();
        if (s_[p_] != ':') fail("expected ':'");
        ++p_;
        value(path.empty() ? k : path + "." + k, out);
        ws();
        if (s_[p_] == ',') { ++p_; continue; }
        if (s_[p_] == '}') { ++p_; return; }
        fail("expected ',' or '}'");
      }
    }
    if (c == '[') {
      ++p_;
      ws();
      if (s_[p_] == ']') { ++p_; return; }
      for (int i = 0;; ++i) {
        value(path + "[" + std::to_string(i) + "]", out);
        ws();
        if (s_[p_] == ',') { ++p_; continue; }
        if (s_[p_] == ']') { ++p_; return; }
        fail("expected ',' or ']'");
      }
    }
    JsonLeaf leaf;
    if (c == '"') {
      leaf.type = JsonLeaf::kString;
      leaf.text = str();
    } else if (s_.compare(p_, 4, "true") == 0) {
      leaf.type = JsonLeaf::kBool, leaf.text = "true", p_ += 4;
    } else if (s_.compare(p_, 5, "false") == 0) {
      leaf.type = JsonLeaf::kBool, leaf.text = "false", p_ += 5;
    } else if (s_.compare(p_, 4, "null") == 0) {
      leaf.type = JsonLeaf::kNull, p_ += 4;
    } else {
      char* end = nullptr;
      leaf.number = std::strtod(s_.c_str() + p_, &end);
      if (end == s_.c_str() + p_) fail("bad value");
      leaf.type = JsonLeaf::kNumber;
      p_ = static_cast<std::size_t>(end - s_.c_str());
    }
    out->emplace_back(path, leaf);
  }
};

FlatJson readJson(const fs::path& p) { return JsonParser(readFile(p)).parse(); }

// ---------------------------------------------------------------- CSV (names row, units row)
struct Csv {
  std::vector<std::string> names, units;
  std::vector<std::vector<std::string>> rows;
  int column(const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return static_cast<int>(i);
    return -1;
  }
};

std::vector<std::vector<std::string>> csvRecords(const std::string& s) {
  std::vector<std::vector<std::string>> recs;
  std::vector<std::string> rec;
  std::string cell;
  bool quoted = false, any = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (quoted) {
      if (c == '"' && i + 1 < s.size() && s[i + 1] == '"') cell += '"', ++i;
      else if (c == '"') quoted = false;
      else cell += c;
    } else if (c == '"') {
      quoted = true, any = true;
    } else if (c == ',') {
      rec.push_back(cell), cell.clear(), any = true;
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < s.size() && s[i + 1] == '\n') ++i;
      if (any || !cell.empty()) rec.push_back(cell);
      if (!rec.empty()) recs.push_back(rec);
      rec.clear(), cell.clear(), any = false;
    } else {
      cell += c, any = true;
    }
  }
  if (any || !cell.empty()) rec.push_back(cell);
  if (!rec.empty()) recs.push_back(rec);
  return recs;
}

Csv readCsv(const fs::path& p) {
  auto recs = csvRecords(readFile(p));
  if (recs.size() < 2) throw Failure(p.string() + ": no names and units rows");
  Csv c;
  c.names = recs[0];
  c.units = recs[1];
  c.rows.assign(recs.begin() + 2, recs.end());
  return c;
}

bool parseNumber(const std::string& t, double* v) {
  if (t.empty()) return false;
  char* end = nullptr;
  *v = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

// ---------------------------------------------------------------- compare
std::string lastComponent(const std::string& key) {
  const auto dot = key.find_last_of('.');
  std::string k = dot == std::string::npos ? key : key.substr(dot + 1);
  const auto br = k.find('[');
  return br == std::string::npos ? k : k.substr(0, br);
}

bool contains(const std::string& s, const char* what) { return s.find(what) != std::string::npos; }

// Run metadata: differs from run to run by design.
bool isMetadata(const std::string& key) {
  const std::string k = lastComponent(key);
  return k == "wall_time_s" || k == "version" || contains(k, "wall_time") || k == "timestamp" ||
         k == "threads" || k == "jobs" || k == "elapsed_s" ||
         // solver work counters: the adaptive step sequence differs between builds (SIMD or not)
         // by a few steps without changing a result beyond the tolerances
         k == "steps" || k == "rhs_evaluations";
}
// Free text (may quote numbers in words); not compared.
bool isFreeText(const std::string& key) {
  const std::string k = lastComponent(key);
  return contains(k, "message") || contains(k, "report") || contains(k, "reason") ||
         k == "residual_source" || k == "note" || k == "path" || contains(k, "file");
}

// summary.json: the absolute floor of a number from its key's unit suffix, the resolution of
// interest for this vehicle (weight 1.16 N, chord 0.05 m): 1e-4 of the weight for forces, etc.
double unitFloor(const std::string& key) {
  const std::string k = lastComponent(key);
  auto ends = [&](const char* suf) {
    const std::string s(suf);
    return k.size() >= s.size() && k.compare(k.size() - s.size(), s.size(), s) == 0;
  };
  // convergence measure of the periodic steady state: anything below the default steady_tol
  if (k == "last_cycle_change") return 1e-3;
  if (ends("_Nm")) return 1e-5;
  if (ends("_N")) return 1e-4;
  if (ends("_W")) return 1e-3;
  if (ends("_deg")) return 1e-3;
  if (ends("_degps")) return 1e-2;
  if (ends("_rad")) return 2e-5;
  if (ends("_mps")) return 1e-4;
  if (ends("_m")) return 1e-5;
  if (ends("_m2")) return 1e-7;
  if (ends("_hz")) return 1e-3;
  if (ends("_kg")) return 1e-6;
  if (ends("_s")) return 1e-4;
  // scaled (dimensionless) residuals and coefficients: 1e-4 (the trim tolerance is 1e-4)
  return 1e-4;
}

// CSV: the same floor from a column's unit (units row); 0 for dimensionless or unknown units.
double csvUnitFloor(const std::string& unit) {
  static const std::pair<const char*, const char*> kSuffix[] = {
      {"N", "_N"},    {"N m", "_Nm"}, {"W", "_W"},   {"deg", "_deg"}, {"deg/s", "_degps"},
      {"rad", "_rad"}, {"m/s", "_mps"}, {"m", "_m"}, {"m^2", "_m2"},  {"Hz", "_hz"},
      {"kg", "_kg"},  {"s", "_s"}};
  for (const auto& [u, suffix] : kSuffix)
    if (unit == u) return unitFloor(std::string("x") + suffix);
  return 0.0;
}

struct Cell {
  std::string where;  // file : key or file : row, column
  std::string base, now;
  double ratio = 0.0;  // |a-b| / tolerance; inf = structural failure
};

struct Comparison {
  double rel = 1e-2, abs_scale = 2e-3;
  long compared = 0, failed = 0;
  std::vector<Cell> cells;  // every value that differs at all
  std::vector<std::string> structural;
  void note(Cell c) {
    if (c.ratio > 1.0) ++failed;
    if (c.ratio > 0.0) cells.push_back(std::move(c));  // any difference: the report shows the worst
  }
  void fail(const std::string& what) {
    ++failed;
    structural.push_back(what);
  }
};

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

void compareJson(const fs::path& bf, const fs::path& nf, const std::string& label, Comparison* c) {
  const FlatJson b = readJson(bf), n = readJson(nf);
  std::map<std::string, JsonLeaf> nm(n.begin(), n.end());
  for (const auto& [key, bl] : b) {
    if (isMetadata(key)) continue;
    const auto it = nm.find(key);
    if (it == nm.end()) {
      c->fail(label + ": key '" + key + "' missing");
      continue;
    }
    const JsonLeaf& nl = it->second;
    if (bl.type == JsonLeaf::kString) {
      if (isFreeText(key)) continue;
      ++c->compared;
      if (nl.type != JsonLeaf::kString || nl.text != bl.text)
        c->fail(label + ": '" + key + "' was \"" + bl.text + "\", now \"" +
                (nl.type == JsonLeaf::kString ? nl.text : std::string("(not a string)")) + "\"");
      continue;
    }
    ++c->compared;
    if (bl.type == JsonLeaf::kBool || bl.type == JsonLeaf::kNull) {
      if (nl.type != bl.type || nl.text != bl.text)
        c->fail(label + ": '" + key + "' was " + (bl.type == JsonLeaf::kNull ? "null" : bl.text) +
                ", now " + (nl.type == JsonLeaf::kNumber ? fmt(nl.number) :
                            nl.type == JsonLeaf::kNull ? "null" : nl.text));
      continue;
    }
    if (nl.type != JsonLeaf::kNumber || !std::isfinite(nl.number)) {
      c->fail(label + ": '" + key + "' was " + fmt(bl.number) + ", now " +
              (nl.type == JsonLeaf::kNull ? "null (NaN)" : "not a number"));
      continue;
    }
    const double tol = c->rel * std::fabs(bl.number) + unitFloor(key);
    c->note({label + ": " + key, fmt(bl.number), fmt(nl.number),
             std::fabs(nl.number - bl.number) / tol});
  }
}

void compareCsv(const fs::path& bf, const fs::path& nf, const std::string& label, Comparison* c) {
  const Csv b = readCsv(bf), n = readCsv(nf);
  if (b.rows.size() != n.rows.size())
    c->fail(label + ": " + std::to_string(b.rows.size()) + " rows in the baseline, " +
            std::to_string(n.rows.size()) + " now");
  const std::size_t rows = std::min(b.rows.size(), n.rows.size());
  for (std::size_t j = 0; j < b.names.size(); ++j) {
    const std::string& name = b.names[j];
    if (isMetadata(name)) continue;
    const int nj = n.column(name);
    if (nj < 0) {
      c->fail(label + ": column '" + name + "' missing");
      continue;
    }
    // Column range of the baseline's numbers.
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const auto& r : b.rows) {
      double v = 0.0;
      if (j < r.size() && parseNumber(r[j], &v) && std::isfinite(v))
        lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const double range = hi >= lo ? hi - lo : 0.0;
    const double floor = j < b.units.size() ? csvUnitFloor(b.units[j]) : 0.0;
    int structural_in_column = 0;
    for (std::size_t i = 0; i < rows; ++i) {
      const std::string bt = j < b.rows[i].size() ? b.rows[i][j] : "";
      const std::string nt =
          static_cast<std::size_t>(nj) < n.rows[i].size() ? n.rows[i][static_cast<std::size_t>(nj)] : "";
      double bv = 0.0, nv = 0.0;
      const bool bnum = parseNumber(bt, &bv), nnum = parseNumber(nt, &nv);
      const std::string where =
          label + ": row " + std::to_string(i + 1) + ", " + name;
      if (bnum && std::isfinite(bv)) {
        ++c->compared;
        if (!nnum || !std::isfinite(nv)) {
          if (structural_in_column++ < 3)
            c->fail(where + ": was " + bt + ", now '" + nt + "'");
          else
            ++c->failed;
          continue;
        }
        const double tol = c->rel * std::fabs(bv) + c->abs_scale * range + floor;
        const double d = std::fabs(nv - bv);
        c->note({where, bt, nt, tol > 0 ? d / tol : (d > 0 ? HUGE_VAL : 0.0)});
      } else {
        if (isFreeText(name)) continue;
        ++c->compared;
        if (bt != nt) {
          if (structural_in_column++ < 3)
            c->fail(where + ": was '" + bt + "', now '" + nt + "'");
          else
            ++c->failed;
        }
      }
    }
  }
}

int compareCommand(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: orni_results compare BASE_DIR NEW_DIR [--rel R] [--abs-scale A] "
                 "[--report N] [--quiet]\n";
    return 2;
  }
  Comparison c;
  int report = 15;
  bool quiet = false;
  for (int i = 4; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--rel" && i + 1 < argc) c.rel = std::atof(argv[++i]);
    else if (a == "--abs-scale" && i + 1 < argc) c.abs_scale = std::atof(argv[++i]);
    else if (a == "--report" && i + 1 < argc) report = std::atoi(argv[++i]);
    else if (a == "--quiet") quiet = true;
    else {
      std::cerr << "orni_results compare: unknown option " << a << "\n";
      return 2;
    }
  }
  const fs::path base = argv[2], now = argv[3];
  std::vector<fs::path> runs;
  if (!fs::is_directory(base)) {
    std::cerr << "orni_results compare: " << base << " is not a folder\n";
    return 2;
  }
  for (const auto& e : fs::recursive_directory_iterator(base))
    if (e.is_regular_file() && e.path().filename() == "summary.json")
      runs.push_back(e.path().parent_path());
  std::sort(runs.begin(), runs.end());
  if (runs.empty()) {
    std::cerr << "orni_results compare: no summary.json under " << base << "\n";
    return 2;
  }
  int files = 0;
  for (const fs::path& run : runs) {
    const fs::path rel = fs::relative(run, base);
    std::vector<fs::path> targets;
    for (const auto& e : fs::directory_iterator(run)) {
      const auto ext = e.path().extension();
      if (e.is_regular_file() && (ext == ".csv" || e.path().filename() == "summary.json"))
        targets.push_back(e.path().filename());
    }
    std::sort(targets.begin(), targets.end());
    for (const fs::path& f : targets) {
      const std::string label = (rel / f).string();
      const fs::path nf = now / rel / f;
      if (!fs::exists(nf)) {
        c.fail(label + ": missing in " + now.string());
        continue;
      }
      ++files;
      try {
        if (f.extension() == ".json") compareJson(run / f, nf, label, &c);
        else compareCsv(run / f, nf, label, &c);
      } catch (const Failure& e) {
        c.fail(label + ": " + e.what());
      }
    }
  }
  std::sort(c.cells.begin(), c.cells.end(),
            [](const Cell& x, const Cell& y) { return x.ratio > y.ratio; });
  std::cout << "orni_results compare: " << runs.size() << " runs, " << files << " files, "
            << c.compared << " values (rel " << c.rel << ", abs " << c.abs_scale
            << " x column range; summary.json: rel + unit floor): " << c.failed << " failed\n";
  for (const std::string& s : c.structural) std::cout << "  FAIL " << s << "\n";
  if (!quiet || c.failed) {
    int shown = 0;
    if (!c.cells.empty()) std::cout << "  worst cells (|a-b| / tolerance; > 1 fails):\n";
    for (const Cell& cell : c.cells) {
      if (shown++ >= report) break;
      std::printf("  %s %8.3g  %s: baseline %s, now %s\n", cell.ratio > 1 ? "FAIL" : "ok  ",
                  cell.ratio, cell.where.c_str(), cell.base.c_str(), cell.now.c_str());
    }
  }
  return c.failed ? 1 : 0;
}

// ---------------------------------------------------------------- fill
// An expression is RPN, tokens separated by spaces, the last token optionally a printf format
// (%.2f, %.3g, ...; default %.4g):
//   j:FILE:KEY             number at KEY (dotted path, arrays as [i]) of the JSON file FILE
//   c:FILE:COL:AGG         aggregate of a CSV column: min max mean range first last count absmax
//   cw:FILE:COL:AGG:WCOL=V  the same over the rows where column WCOL equals V (numerically, or
//                          as text when V is not a number); WCOL>=V and WCOL<=V select at
//                          least / at most V; join with &
//   at:FILE:COL:BYCOL:max|min   COL in the row where BYCOL is largest / smallest
//   fit:FILE:Y:X1,X2,..:Xk  least-squares coefficient of Xk in Y = a + sum b_i X_i (rows with
//                          numbers); fit:FILE:Y:X1,..:r2 gives the coefficient of determination
//   s:FILE:KEY             a JSON string (the whole expression must be just this)
//   numbers; + - * / abs neg min2 max2
std::string g_root;

std::string resolveFile(const std::string& f) { return (fs::path(g_root) / f).string(); }

std::map<std::string, FlatJson> g_json;
std::map<std::string, Csv> g_csv;
const FlatJson& json(const std::string& f) {
  auto it = g_json.find(f);
  if (it == g_json.end()) it = g_json.emplace(f, readJson(resolveFile(f))).first;
  return it->second;
}
const Csv& csv(const std::string& f) {
  auto it = g_csv.find(f);
  if (it == g_csv.end()) it = g_csv.emplace(f, readCsv(resolveFile(f))).first;
  return it->second;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> r;
  std::string cur;
  for (char ch : s) {
    if (ch == sep) r.push_back(cur), cur.clear();
    else cur += ch;
  }
  r.push_back(cur);
  return r;
}

const JsonLeaf& jsonLeaf(const std::string& f, const std::string& key) {
  for (const auto& [k, v] : json(f))
    if (k == key) return v;
  throw Failure(f + ": no key '" + key + "'");
}

std::vector<double> columnValues(const Csv& t, const std::string& f, const std::string& col,
                                 const std::string& where = "") {
  const int j = t.column(col);
  if (j < 0) throw Failure(f + ": no column '" + col + "'");
  // Conditions "COL=V", "COL>=V", "COL<=V", joined by '&'.
  struct Cond {
    int col = -1;
    char op = '=';
    double value = 0.0;
    bool numeric = true;  ///< false: '=' compares the cell's text with `text`
    std::string text;
  };
  std::vector<Cond> conds;
  if (!where.empty()) {
    for (const std::string& w : split(where, '&')) {
      const auto eq = w.find('=');
      if (eq == std::string::npos || eq == 0) throw Failure("bad condition '" + w + "'");
      Cond c;
      std::size_t name_end = eq;
      if (w[eq - 1] == '>' || w[eq - 1] == '<') c.op = w[eq - 1], name_end = eq - 1;
      c.col = t.column(w.substr(0, name_end));
      if (c.col < 0) throw Failure(f + ": no column '" + w.substr(0, name_end) + "'");
      c.text = w.substr(eq + 1);
      c.numeric = parseNumber(c.text, &c.value);
      if (!c.numeric && c.op != '=') throw Failure("bad condition '" + w + "': >= and <= need a number");
      conds.push_back(c);
    }
  }
  auto keep = [&](const std::vector<std::string>& r) {
    for (const Cond& c : conds) {
      double w = 0.0;
      if (!c.numeric) {
        if (static_cast<std::size_t>(c.col) >= r.size() ||
            r[static_cast<std::size_t>(c.col)] != c.text)
          return false;
        continue;
      }
      if (static_cast<std::size_t>(c.col) >= r.size() ||
          !parseNumber(r[static_cast<std::size_t>(c.col)], &w))
        return false;
      const double eps = 1e-9 * std::max(1.0, std::fabs(c.value));
      const bool ok = c.op == '>' ? w >= c.value - eps
                      : c.op == '<' ? w <= c.value + eps
                                    : std::fabs(w - c.value) <= eps;
      if (!ok) return false;
    }
    return true;
  };
  std::vector<double> v;
  for (const auto& r : t.rows) {
    double x = 0.0;
    if (!keep(r)) continue;
    if (static_cast<std::size_t>(j) < r.size() && parseNumber(r[static_cast<std::size_t>(j)], &x) &&
        std::isfinite(x))
      v.push_back(x);
  }
  if (v.empty()) throw Failure(f + ": column '" + col + "' has no numbers" +
                               (where.empty() ? "" : " where " + where));
  return v;
}

double aggregate(const std::vector<double>& v, const std::string& agg) {
  if (agg == "min") return *std::min_element(v.begin(), v.end());
  if (agg == "max") return *std::max_element(v.begin(), v.end());
  if (agg == "range")
    return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  if (agg == "first") return v.front();
  if (agg == "last") return v.back();
  if (agg == "count") return static_cast<double>(v.size());
  if (agg == "absmax") {
    double m = 0;
    for (double x : v) m = std::max(m, std::fabs(x));
    return m;
  }
  if (agg == "sum") {
    double s = 0;
    for (double x : v) s += x;
    return s;
  }
  if (agg == "mean") {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
  }
  throw Failure("unknown aggregate '" + agg + "'");
}

// Least squares by normal equations (few regressors, well scaled grids).
double fitTerm(const std::string& f, const std::string& y, const std::string& xs,
               const std::string& term) {
  const Csv& t = csv(f);
  const std::vector<std::string> xn = split(xs, ',');
  const std::size_t p = xn.size() + 1;
  std::vector<int> cols;
  for (const auto& x : xn) {
    const int j = t.column(x);
    if (j < 0) throw Failure(f + ": no column '" + x + "'");
    cols.push_back(j);
  }
  const int yj = t.column(y);
  if (yj < 0) throw Failure(f + ": no column '" + y + "'");
  std::vector<std::vector<double>> X;
  std::vector<double> Y;
  for (const auto& r : t.rows) {
    std::vector<double> row{1.0};
    double v = 0.0;
    bool ok = static_cast<std::size_t>(yj) < r.size() && parseNumber(r[static_cast<std::size_t>(yj)], &v);
    const double yv = v;
    for (int j : cols)
      if (ok && static_cast<std::size_t>(j) < r.size() && parseNumber(r[static_cast<std::size_t>(j)], &v))
        row.push_back(v);
      else
        ok = false;
    if (ok) X.push_back(row), Y.push_back(yv);
  }
  if (X.size() < p + 1) throw Failure(f + ": too few rows to fit " + y);
  std::vector<std::vector<double>> A(p, std::vector<double>(p + 1, 0.0));
  for (std::size_t k = 0; k < X.size(); ++k)
    for (std::size_t a = 0; a < p; ++a) {
      for (std::size_t b = 0; b < p; ++b) A[a][b] += X[k][a] * X[k][b];
      A[a][p] += X[k][a] * Y[k];
    }
  for (std::size_t i = 0; i < p; ++i) {  // Gauss-Jordan with partial pivoting
    std::size_t piv = i;
    for (std::size_t r = i + 1; r < p; ++r)
      if (std::fabs(A[r][i]) > std::fabs(A[piv][i])) piv = r;
    std::swap(A[i], A[piv]);
    if (std::fabs(A[i][i]) < 1e-300) throw Failure(f + ": singular fit of " + y);
    for (std::size_t r = 0; r < p; ++r) {
      if (r == i) continue;
      const double m = A[r][i] / A[i][i];
      for (std::size_t cc = i; cc <= p; ++cc) A[r][cc] -= m * A[i][cc];
    }
  }
  std::vector<double> beta(p);
  for (std::size_t i = 0; i < p; ++i) beta[i] = A[i][p] / A[i][i];
  if (term == "r2") {
    double mean = 0;
    for (double v : Y) mean += v;
    mean /= static_cast<double>(Y.size());
    double ss_res = 0, ss_tot = 0;
    for (std::size_t k = 0; k < X.size(); ++k) {
      double yhat = 0;
      for (std::size_t a = 0; a < p; ++a) yhat += beta[a] * X[k][a];
      ss_res += (Y[k] - yhat) * (Y[k] - yhat);
      ss_tot += (Y[k] - mean) * (Y[k] - mean);
    }
    return ss_tot > 0 ? 1.0 - ss_res / ss_tot : 1.0;
  }
  if (term == "const") return beta[0];
  for (std::size_t i = 0; i < xn.size(); ++i)
    if (xn[i] == term) return beta[i + 1];
  throw Failure("fit term '" + term + "' is not a regressor");
}

std::string evalExpression(const std::string& expr) {
  std::istringstream in(expr);
  std::vector<std::string> tok;
  for (std::string t; in >> t;) tok.push_back(t);
  if (tok.empty()) throw Failure("empty expression");
  std::string format = "%.4g";
  if (tok.back()[0] == '%') format = tok.back(), tok.pop_back();
  if (tok.size() == 1 && tok[0].rfind("s:", 0) == 0) {
    const auto parts = split(tok[0], ':');
    if (parts.size() != 3) throw Failure("bad token '" + tok[0] + "'");
    const JsonLeaf& l = jsonLeaf(parts[1], parts[2]);
    if (l.type == JsonLeaf::kNull) return "null";
    return l.type == JsonLeaf::kNumber ? fmt(l.number) : l.text;
  }
  std::vector<double> st;
  auto pop = [&]() {
    if (st.empty()) throw Failure("stack underflow in '" + expr + "'");
    const double v = st.back();
    st.pop_back();
    return v;
  };
  for (const std::string& t : tok) {
    const auto parts = split(t, ':');
    double v = 0.0;
    if (parts[0] == "j" && parts.size() == 3) {
      const JsonLeaf& l = jsonLeaf(parts[1], parts[2]);
      if (l.type == JsonLeaf::kBool) st.push_back(l.text == "true" ? 1.0 : 0.0);
      else if (l.type != JsonLeaf::kNumber) throw Failure(parts[1] + ": '" + parts[2] + "' is not a number");
      else st.push_back(l.number);
    } else if (parts[0] == "c" && parts.size() == 4) {
      st.push_back(aggregate(columnValues(csv(parts[1]), parts[1], parts[2]), parts[3]));
    } else if (parts[0] == "cw" && parts.size() == 5) {
      st.push_back(aggregate(columnValues(csv(parts[1]), parts[1], parts[2], parts[4]), parts[3]));
    } else if (parts[0] == "at" && parts.size() == 5) {
      const Csv& c = csv(parts[1]);
      const int j = c.column(parts[2]), bj = c.column(parts[3]);
      if (j < 0 || bj < 0) throw Failure(parts[1] + ": no column in '" + t + "'");
      bool found = false;
      double best = 0, val = 0;
      for (const auto& r : c.rows) {
        double b = 0.0, x = 0.0;
        if (static_cast<std::size_t>(std::max(j, bj)) >= r.size()) continue;
        if (!parseNumber(r[static_cast<std::size_t>(bj)], &b) ||
            !parseNumber(r[static_cast<std::size_t>(j)], &x))
          continue;
        if (!found || (parts[4] == "max" ? b > best : b < best)) best = b, val = x, found = true;
      }
      if (!found) throw Failure(parts[1] + ": no rows for '" + t + "'");
      st.push_back(val);
    } else if (parts[0] == "fit" && parts.size() == 5) {
      st.push_back(fitTerm(parts[1], parts[2], parts[3], parts[4]));
    } else if (t == "+" || t == "-" || t == "*" || t == "/" || t == "min2" || t == "max2") {
      const double b = pop(), a = pop();
      st.push_back(t == "+" ? a + b : t == "-" ? a - b : t == "*" ? a * b : t == "/" ? a / b
                   : t == "min2" ? std::min(a, b) : std::max(a, b));
    } else if (t == "abs") {
      st.push_back(std::fabs(pop()));
    } else if (t == "neg") {
      st.push_back(-pop());
    } else if (parseNumber(t, &v)) {
      st.push_back(v);
    } else {
      throw Failure("bad token '" + t + "' in '" + expr + "'");
    }
  }
  if (st.size() != 1) throw Failure("expression '" + expr + "' leaves " +
                                    std::to_string(st.size()) + " values");
  if (!std::isfinite(st[0])) throw Failure("expression '" + expr + "' is not finite");
  char buf[64];
  std::snprintf(buf, sizeof buf, format.c_str(), st[0]);
  std::string out = buf;
  if (out == "-0" || out.find_first_not_of("-0.") == std::string::npos) {
    // "-0.00" -> "0.00"
    if (!out.empty() && out[0] == '-') out.erase(0, 1);
  }
  return out;
}

int fillCommand(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: orni_results fill TEMPLATE RESULTS_DIR\n";
    return 2;
  }
  g_root = argv[3];
  const std::string t = readFile(argv[2]);
  std::string out;
  std::size_t p = 0;
  int line = 1;
  while (true) {
    const std::size_t a = t.find("{{", p);
    if (a == std::string::npos) {
      out += t.substr(p);
      break;
    }
    line += static_cast<int>(std::count(t.begin() + static_cast<long>(p), t.begin() + static_cast<long>(a), '\n'));
    const std::size_t b = t.find("}}", a);
    if (b == std::string::npos) throw Failure(std::string(argv[2]) + ":" + std::to_string(line) + ": unclosed {{");
    out += t.substr(p, a - p);
    try {
      out += evalExpression(t.substr(a + 2, b - a - 2));
    } catch (const Failure& e) {
      throw Failure(std::string(argv[2]) + ":" + std::to_string(line) + ": " + e.what());
    }
    line += static_cast<int>(std::count(t.begin() + static_cast<long>(a), t.begin() + static_cast<long>(b), '\n'));
    p = b + 2;
  }
  std::cout << out;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string cmd = argc > 1 ? argv[1] : "";
    if (cmd == "compare") return compareCommand(argc, argv);
    if (cmd == "fill") return fillCommand(argc, argv);
    std::cerr << "usage: orni_results compare BASE_DIR NEW_DIR [options] | fill TEMPLATE DIR\n";
    return 2;
  } catch (const Failure& e) {
    std::cerr << "orni_results: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "orni_results: " << e.what() << "\n";
    return 2;
  }
}
