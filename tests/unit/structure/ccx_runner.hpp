// Running CalculiX (`ccx`, Debian calculix-ccx) from a test: write a deck into a scratch folder,
// run it, read the displacement tables of JOB.dat (core/structure/calculix_results.hpp). Tests
// that need ccx skip (GTEST_SKIP) when it is not on PATH.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/structure/calculix_deck.hpp"
#include "core/structure/calculix_results.hpp"
#include "core/structure/fe_assembly.hpp"

namespace orni::structure::fe_test {

inline bool ccxAvailable() { return std::system("command -v ccx >/dev/null 2>&1") == 0; }

/// A deck of static steps only, held as `support` holds the wing (P3's joint and cross axis, the
/// root edge), as our static solves are.
inline CalculixDeckOptions staticDeckFor(const WingSupport& support) {
  CalculixDeckOptions o;
  o.frequency_step = false;
  o.p3_joint = support.p3_joint;
  o.p3_cross_axis_normal = support.p3_cross_axis == UniversalJointCrossAxis::kZW;
  o.root_edge_pinned = support.root_edge_pinned;
  return o;
}

inline constexpr const char* kNoCcxMessage =
    "ccx (CalculiX, Debian package calculix-ccx) is not on PATH: cross-code check skipped";

struct CcxRun {
  bool ran = false;          ///< ccx exited with status 0
  std::string message;       ///< the log's tail when not
  double seconds = 0.0;      ///< wall time of ccx
  std::vector<CalculixDisplacementTable> tables;
};

/// Writes `deck` to <tmp>/orni_ccx_<pid>_<job>/<job>.inp, runs ccx there (OMP_NUM_THREADS as set,
/// else 2; at most 10 minutes) and reads <job>.dat. The folder is removed afterwards unless
/// ORNI_KEEP_CCX is set (then its path is in the message).
inline CcxRun runCcx(const std::string& deck, const std::string& job) {
  namespace fs = std::filesystem;
  CcxRun run;
  const fs::path dir =
      fs::temp_directory_path() / ("orni_ccx_" + std::to_string(::getpid()) + "_" + job);
  fs::remove_all(dir);
  fs::create_directories(dir);
  { std::ofstream(dir / (job + ".inp")) << deck; }
  const std::string command = "cd '" + dir.string() +
                              "' && OMP_NUM_THREADS=${OMP_NUM_THREADS:-2} timeout 600 ccx -i " +
                              job + " > " + job + ".log 2>&1";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.ran = status == 0;
  if (!run.ran) {
    std::ifstream log(dir / (job + ".log"));
    std::vector<std::string> lines;
    for (std::string l; std::getline(log, l);) lines.push_back(l);
    run.message = "ccx exited with status " + std::to_string(status) + ":";
    for (std::size_t i = lines.size() > 8 ? lines.size() - 8 : 0; i < lines.size(); ++i)
      run.message += "\n  " + lines[i];
  }
  if (fs::exists(dir / (job + ".dat")))
    run.tables = readCalculixDisplacementFile((dir / (job + ".dat")).string());
  if (std::getenv("ORNI_KEEP_CCX") != nullptr)
    run.message += "\n(ccx files kept in " + dir.string() + ")";
  else
    fs::remove_all(dir);
  return run;
}

}  // namespace orni::structure::fe_test
