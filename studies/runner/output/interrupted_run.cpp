#include "studies/runner/output/interrupted_run.hpp"

#include <signal.h>

#include <atomic>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/model/cancellation.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/json_writer.hpp"

namespace orni::studies {

namespace {

std::atomic<int> g_signal{0};

extern "C" void onInterrupt(int sig) {
  g_signal.store(sig);
  requestCancellation();
}

}  // namespace

void installInterruptHandlers() {
  struct sigaction sa {};
  sa.sa_handler = onInterrupt;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  for (const int sig : {SIGINT, SIGTERM}) {
    // A signal the parent set to be ignored stays ignored (a shell's background job ignores
    // SIGINT: a Ctrl-C meant for the foreground job must not stop it).
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    sigaction(sig, &sa, nullptr);
  }
}

int interruptSignal() noexcept { return g_signal.load(); }

std::string interruptSignalName() {
  switch (interruptSignal()) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
  }
  return "a signal";
}

void markRunInterrupted(const std::filesystem::path& dir, const std::string& kind) noexcept {
  try {
    const std::string message =
        "interrupted by " + interruptSignalName() +
        " before the run finished; a resumable run (aero map, sweep, sensitivity study, "
        "continuation, optimisation) keeps its journal here and the same command resumes it";
    const std::filesystem::path file = dir / "summary.json";
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    if (in) text << in.rdbuf();
    std::string summary = text.str();
    static const std::regex kStatus(R"re("status": "(?:[^"\\]|\\.)*")re");
    static const std::regex kMessage(R"re("message": "(?:[^"\\]|\\.)*")re");
    if (std::regex_search(summary, kStatus)) {
      summary = std::regex_replace(summary, kStatus, "\"status\": \"interrupted\"",
                                   std::regex_constants::format_first_only);
      if (std::regex_search(summary, kMessage))
        summary = std::regex_replace(summary, kMessage,
                                     "\"message\": " + jsonEscape(message),
                                     std::regex_constants::format_first_only);
    } else {
      JsonObject o;
      if (!kind.empty()) o.set("kind", kind);
      o.set("status", "interrupted").set("message", message);
      summary = o.toString() + "\n";
    }
    writeFileAtomic(file, summary);
  } catch (...) {
    // The interrupt is reported by the exit status whatever happens here.
  }
}

}  // namespace orni::studies
