#include "studies/runner/output/run_outputs.hpp"

#include <fstream>
#include <mutex>
#include <regex>
#include <set>
#include <system_error>

namespace orni::studies {

namespace fs = std::filesystem;

namespace {

/// Every run writes these besides its own (index.html: output/html_report.hpp).
const std::vector<std::string> kCommonFiles = {"summary.json", "study.resolved.toml",
                                               "index.html"};
const std::vector<std::string> kFigureExtensions = {".gp", ".png", ".svg"};

/// `dir` as one spelling (absolute, normal, no trailing separator).
fs::path folderKey(const fs::path& dir) {
  fs::path p = fs::absolute(dir.empty() ? fs::path(".") : dir).lexically_normal();
  if (!p.has_filename() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  return p;
}

std::mutex g_mutex;
std::set<fs::path> g_expected;  // folders locked for a run, not yet claimed

}  // namespace

bool stemMatches(const std::string& pattern, const std::string& stem) {
  if (!pattern.empty() && pattern.back() == '*')
    return stem.compare(0, pattern.size() - 1, pattern, 0, pattern.size() - 1) == 0;
  return pattern == stem;
}

const std::vector<KindOutputs>& runOutputsByKind() {
  static const std::vector<KindOutputs> kinds = {
      {"simulate",
       {"histories.csv", "cycles.csv", "zmp.csv", "spectra.csv"},
       {"loads", "zmp", "flight", "cycle", "phase"}},
      {"aeromap", {"aeromap.csv"}, {"aeromap_FV", "aeromap_FH", "aeromap_M", "aeromap_power"}},
      {"trim",
       {"trim_iterations.csv", "trim_progress.csv", "periodic_iterations.csv", "floquet.csv",
        "periodic_orbit.csv"},
       {"trim_convergence", "periodic_orbit", "floquet_multipliers"}},
      {"stability",
       {"periodic_iterations.csv", "floquet.csv", "periodic_orbit.csv"},
       {"periodic_orbit", "floquet_multipliers"}},
      {"modes", {"modes.csv", "mode_shapes.csv", "modes_figure.dat"}, {"modes"}},
      {"calibrate", {"calibration.csv", "calibrated_vehicle.toml"}, {}},
      {"sweep", {"sweep.csv"}, {"sweep"}},
      {"continuation", {"continuation.csv"}, {"continuation"}},
      {"sensitivity",
       {"sensitivity.csv", "tornado.csv"},
       {"sensitivity_overview", "tornado_*"}},
      {"optimize", {"history.csv", "best_vehicle.toml"}, {"optimize_convergence"}},
  };
  return kinds;
}

bool isFigureOfKind(const std::string& kind, const std::string& stem) {
  for (const KindOutputs& k : runOutputsByKind()) {
    if (k.kind != kind) continue;
    for (const std::string& pattern : k.figure_stems)
      if (stemMatches(pattern, stem)) return true;
    return false;
  }
  return true;  // a kind this version does not know: every figure
}

std::string summaryKind(const fs::path& dir) {
  std::ifstream in(dir / "summary.json", std::ios::binary);
  std::string line;
  static const std::regex kKind(R"re(^\s*"kind":\s*"([^"]*)")re");
  std::smatch m;
  while (std::getline(in, line))
    if (std::regex_search(line, m, kKind)) return m[1].str();
  return "";
}

int removeEarlierRunOutputs(const fs::path& dir) {
  std::set<std::string> names(kCommonFiles.begin(), kCommonFiles.end());
  std::vector<std::string> stems;
  for (const KindOutputs& k : runOutputsByKind()) {
    names.insert(k.files.begin(), k.files.end());
    stems.insert(stems.end(), k.figure_stems.begin(), k.figure_stems.end());
  }
  std::vector<fs::path> stale;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (!e.is_regular_file(ec) || e.is_symlink(ec)) continue;
    const fs::path name = e.path().filename();
    bool ours = names.count(name.string()) > 0;
    for (const std::string& ext : kFigureExtensions)
      if (!ours && name.extension() == ext)
        for (const std::string& pattern : stems)
          ours = ours || stemMatches(pattern, name.stem().string());
    if (ours) stale.push_back(e.path());
  }
  int removed = 0;
  for (const fs::path& p : stale) removed += fs::remove(p, ec) ? 1 : 0;
  return removed;
}

void expectRunFolder(const fs::path& dir) {
  const std::lock_guard<std::mutex> lock(g_mutex);
  g_expected.insert(folderKey(dir));
}

void forgetRunFolder(const fs::path& dir) {
  const std::lock_guard<std::mutex> lock(g_mutex);
  g_expected.erase(folderKey(dir));
}

void claimRunFolder(const fs::path& path) {
  const std::lock_guard<std::mutex> lock(g_mutex);
  if (g_expected.empty()) return;
  const fs::path dir = folderKey(path.parent_path());
  if (g_expected.erase(dir) == 0) return;
  removeEarlierRunOutputs(dir);
}

}  // namespace orni::studies
