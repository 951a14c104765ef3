#include "studies/runner/plotting/gnuplot.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "core/model/cancellation.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/console.hpp"

#ifndef ORNI_GNUPLOT
#define ORNI_GNUPLOT "gnuplot"
#endif


namespace orni::studies {

namespace fs = std::filesystem;

namespace {

/// Runs `argv` (argv[0] looked up in PATH) in `cwd` with stdout and stderr to `log`, in this
/// process group, and waits for it: its exit status (0 = success), or -1 when it could not be
/// started or died of a signal. A cancellation request while it runs (or when it died) stops it
/// and throws Cancelled.
int runGnuplot(const fs::path& cwd, const fs::path& log, const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int err = ::posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) {
    std::ofstream(log) << "cannot start " << argv[0] << ": " << std::strerror(err) << "\n";
    return -1;
  }
  int status = 0;
  for (int polls = 0;; ++polls) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) return -1;
    if (cancellationRequested()) {
      // Stop it (a second later for good), reap it, and leave as the interrupt.
      ::kill(pid, SIGTERM);
      for (int i = 0; i < 100 && ::waitpid(pid, &status, WNOHANG) == 0; ++i) ::usleep(10000);
      if (::waitpid(pid, &status, WNOHANG) == 0) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
      }
      throw Cancelled{};
    }
    ::usleep(polls < 50 ? 2000 : 20000);  // quick figures return fast; then 50 polls a second
  }
  // Ctrl-C reached gnuplot and us alike: our handler may still be running on another thread
  // when gnuplot's death is seen, so an interrupt signal gets a moment to be noted.
  if (WIFSIGNALED(status) && (WTERMSIG(status) == SIGINT || WTERMSIG(status) == SIGTERM))
    for (int i = 0; i < 50 && !cancellationRequested(); ++i) ::usleep(2000);
  if (cancellationRequested()) throw Cancelled{};
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return -1;
}

/// A gnuplot single-quoted string ('' stands for one quote inside).
std::string gnuplotQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("''") : std::string(1, c);
  return out + "'";
}

// The script draws the body twice: once for PNG, once for SVG. The output names are relative:
// gnuplot runs in a private scratch folder (see drawInScratch), so the script stays the same
// bytes for every run and redraw.
std::string scriptFor(const std::string& stem, const std::string& body) {
  std::ostringstream s;
  s << "# Figure '" << stem << "' written by ornithopter; redraw with `ornithopter plot DIR`.\n"
    << "set datafile separator ','\n"
    << "set grid lc rgb '#dddddd'\n"
    << "set key top right box opaque\n"
    << "set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'\n"
    << "set output '" << stem << ".png.tmp'\n"
    << body << "\n"
    << "unset output\n"
    << "set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'\n"
    << "set output '" << stem << ".svg.tmp'\n"
    << body << "\n"
    << "unset output\n";
  return s.str();
}

std::string gnuplotProgram() {
  const char* override_path = std::getenv("ORNI_GNUPLOT");
  return override_path && *override_path ? std::string(override_path) : std::string(ORNI_GNUPLOT);
}

std::string readFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The last lines of gnuplot's log (at most ~600 characters), for the error message.
std::string logTail(const fs::path& log) {
  std::string text = readFile(log);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  constexpr std::size_t kMax = 600;
  if (text.size() > kMax) text = "..." + text.substr(text.size() - kMax);
  return text.empty() ? std::string("nothing") : text;
}

/// Why `file` is not a complete PNG (empty when it is): the 8-byte signature first, the IEND
/// chunk (length 0, type, CRC) last, as a truncated write would not leave it.
std::string pngProblem(const std::string& bytes) {
  static const std::string kSignature("\x89PNG\r\n\x1a\n", 8);
  static const std::string kIend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  if (bytes.empty()) return "empty";
  if (bytes.compare(0, kSignature.size(), kSignature) != 0) return "not a PNG: no signature";
  if (bytes.size() < kSignature.size() + kIend.size() ||
      bytes.compare(bytes.size() - kIend.size(), kIend.size(), kIend) != 0)
    return "truncated: no IEND chunk at its end";
  return "";
}

/// Why `file` is not a complete SVG (empty when it is): it must end with the closing </svg>.
std::string svgProblem(const std::string& bytes) {
  if (bytes.empty()) return "empty";
  const std::size_t end = bytes.find_last_not_of(" \t\r\n");
  const std::string closing = "</svg>";
  if (end == std::string::npos || end + 1 < closing.size() ||
      bytes.compare(end + 1 - closing.size(), closing.size(), closing) != 0)
    return "truncated: no closing </svg>";
  return "";
}

/// Flushes `file` to disk (a renamed figure must not be a hole after a power loss).
void syncFile(const fs::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot open " + file.string() + " to flush it");
  const bool ok = ::fsync(fd) == 0;
  ::close(fd);
  if (!ok) throw std::runtime_error("cannot flush " + file.string() + " to disk");
}

/// A folder DIR/.plot-STEM-PID.N for one drawing, removed with everything in it at scope exit.
class ScratchFolder {
 public:
  ScratchFolder(const fs::path& dir, const std::string& stem)
      : path_(dir / (".plot-" + stem + "-" + uniqueTempTag())) {
    std::error_code ec;
    fs::create_directory(path_, ec);
    if (ec)
      throw std::runtime_error("cannot create the drawing folder " + path_.string() + ": " +
                               ec.message());
  }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

/// Runs DIR/STEM.gp and puts DIR/STEM.png and DIR/STEM.svg in place, or throws and leaves
/// neither a temporary file nor a partial figure. gnuplot runs in a private scratch folder inside
/// DIR (unique name: two drawings never share a file) and finds the run's data files through its
/// loadpath; it exits 0 even when it could not write (a full disk), so each output is checked
/// (PNG signature and end chunk, SVG closing tag) before it is renamed into place.
void drawInScratch(const fs::path& dir, const std::string& stem) {
  const fs::path run_dir = fs::absolute(dir);
  const ScratchFolder scratch(run_dir, stem);
  const fs::path log = scratch.path() / "gnuplot.log";
  const fs::path script = dir / (stem + ".gp");
  const int rc = runGnuplot(scratch.path(), log,
                            {gnuplotProgram(), "-e",
                             "set loadpath " + gnuplotQuote(run_dir.string()),
                             (run_dir / (stem + ".gp")).string()});
  if (rc != 0)
    throw std::runtime_error("gnuplot failed on " + script.string() + "; gnuplot said: " +
                             logTail(log));
  const std::array<std::pair<const char*, std::string (*)(const std::string&)>, 2> outputs = {
      {{".png", &pngProblem}, {".svg", &svgProblem}}};
  for (const auto& [ext, problem] : outputs) {
    const fs::path tmp = scratch.path() / (stem + ext + ".tmp");
    std::error_code ec;
    if (!fs::is_regular_file(tmp, ec))
      throw std::runtime_error("gnuplot wrote no " + stem + ext + " from " + script.string() +
                               "; gnuplot said: " + logTail(log));
    const std::string why = problem(readFile(tmp));
    if (!why.empty())
      throw std::runtime_error("gnuplot left an incomplete " + stem + ext + " (" + why +
                               "; is the disk full?) from " + script.string() +
                               "; gnuplot said: " + logTail(log));
    syncFile(tmp);
  }
  for (const auto& output : outputs) {
    const std::string ext = output.first;
    std::error_code ec;
    fs::rename(scratch.path() / (stem + ext + ".tmp"), dir / (stem + ext), ec);
    if (ec)
      throw std::runtime_error("cannot rename the figure into " + (dir / (stem + ext)).string() +
                               ": " + ec.message());
  }
}

std::atomic<bool> g_figures_wanted{true};
std::atomic<bool> g_missing_gnuplot_noted{false};

/// `program` is an executable file (a path with '/'), or one is found on PATH.
bool canStart(const std::string& program) {
  if (program.empty()) return false;
  if (program.find('/') != std::string::npos) return ::access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t begin = 0;
  while (begin <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', begin), dirs.size());
    const std::string d = dirs.substr(begin, end - begin);
    const std::string candidate = (d.empty() ? std::string(".") : d) + "/" + program;
    if (::access(candidate.c_str(), X_OK) == 0) return true;
    begin = end + 1;
  }
  return false;
}

}  // namespace

void setFiguresWanted(bool wanted) noexcept { g_figures_wanted.store(wanted); }

bool figuresWanted() noexcept { return g_figures_wanted.load(); }

FiguresScope::FiguresScope(bool wanted) noexcept : previous_(figuresWanted()) {
  setFiguresWanted(previous_ && wanted);
}

FiguresScope::~FiguresScope() { setFiguresWanted(previous_); }

bool gnuplotAvailable() { return canStart(gnuplotProgram()); }

void drawFigure(const fs::path& dir, const std::string& stem, const std::string& body) {
  writeFileAtomic(dir / (stem + ".gp"), scriptFor(stem, body));
  if (!figuresWanted()) return;
  if (!gnuplotAvailable()) {
    if (!g_missing_gnuplot_noted.exchange(true))
      consoleErr() << "ornithopter: note: figures skipped: gnuplot (" << gnuplotProgram()
                   << ") not found; the figure scripts (*.gp) are kept: install gnuplot "
                      "(apt-get install gnuplot-nox), then `ornithopter plot DIR` draws them\n";
    return;
  }
  drawInScratch(dir, stem);
}

int redrawFigures(const fs::path& dir, const std::function<bool(const std::string&)>& include) {
  std::vector<std::string> stems;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".gp" && e.is_regular_file() &&
        (!include || include(e.path().stem().string())))
      stems.push_back(e.path().stem().string());
  std::sort(stems.begin(), stems.end());
  for (const std::string& s : stems) drawInScratch(dir, s);
  return static_cast<int>(stems.size());
}

}  // namespace orni::studies
