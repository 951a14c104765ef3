#include "studies/runner/output/heartbeat.hpp"
#include "studies/runner/output/console.hpp"

#include <unistd.h>

#include <utility>

namespace orni::studies {

namespace {

constexpr double kFirst_s = 2.0;
constexpr double kTerminalInterval_s = 5.0;
constexpr double kLogInterval_s = 10.0;

}  // namespace

Heartbeat::Heartbeat(std::string label, std::FILE* out)
    : label_(std::move(label)),
      out_(out),
      tty_(::isatty(::fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()),
      thread_([this] { loop(); }) {}

Heartbeat::~Heartbeat() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

std::string Heartbeat::text(const std::string& label, double elapsed_s) {
  char buf[64];
  std::snprintf(buf, sizeof buf, ": working, %.1f s elapsed", elapsed_s);
  return label + buf;
}

void Heartbeat::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  auto next = start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(kFirst_s));
  const auto interval = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(tty_ ? kTerminalInterval_s : kLogInterval_s));
  while (!wake_.wait_until(lock, next, [this] { return stop_; })) {
    const double elapsed_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (out_ == stderr && consoleQuiet()) {  // a library call (console.hpp): kept, not printed
      consoleCaptureProgress(text(label_, elapsed_s));
    } else {
      std::fprintf(out_, "%s\n", text(label_, elapsed_s).c_str());
      std::fflush(out_);
    }
    next += interval;
  }
}

}  // namespace orni::studies
