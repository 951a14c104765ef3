#include "studies/runner/output/progress_line.hpp"
#include "studies/runner/output/console.hpp"

#include <unistd.h>

#include <utility>

namespace orni::studies {

namespace {

constexpr double kTerminalInterval_s = 0.5;
constexpr double kLogInterval_s = 10.0;

double secondsBetween(std::chrono::steady_clock::time_point a,
                      std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

ProgressLine::ProgressLine(std::string label, std::size_t total, std::size_t already_done,
                           std::FILE* out)
    : label_(std::move(label)),
      total_(total),
      done_(already_done),
      out_(out),
      tty_(::isatty(::fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

std::string ProgressLine::text(const std::string& label, std::size_t done, std::size_t total,
                               std::size_t done_here, double elapsed_s) {
  char buf[160];
  const std::size_t left = total - done;
  if (done_here == 0 || left == 0) {
    std::snprintf(buf, sizeof buf, "%s: %zu/%zu points, %.1f s elapsed", label.c_str(), done,
                  total, elapsed_s);
  } else {
    const double eta_s = elapsed_s / static_cast<double>(done_here) * static_cast<double>(left);
    std::snprintf(buf, sizeof buf, "%s: %zu/%zu points, %.1f s elapsed, ETA %.1f s",
                  label.c_str(), done, total, elapsed_s, eta_s);
  }
  return buf;
}

void ProgressLine::pointDone() {
  ++done_;
  ++done_here_;
  const auto now = std::chrono::steady_clock::now();
  if (secondsBetween(last_draw_, now) >= (tty_ ? kTerminalInterval_s : kLogInterval_s)) {
    last_draw_ = now;
    draw(false);
  }
}

void ProgressLine::finish() { draw(true); }

void ProgressLine::draw(bool final_line) {
  const double elapsed_s = secondsBetween(start_, std::chrono::steady_clock::now());
  std::string line = text(label_, done_, total_, done_here_, elapsed_s);
  if (out_ == stderr && consoleQuiet()) {  // a library call (console.hpp): kept, not printed
    consoleCaptureProgress(line);
    return;
  }
  if (tty_) {
    const std::size_t width = line.size();
    if (width < last_width_) line.append(last_width_ - width, ' ');  // clear a longer line
    last_width_ = width;
    std::fprintf(out_, "\r%s%s", line.c_str(), final_line ? "\n" : "");
  } else {
    std::fprintf(out_, "%s\n", line.c_str());
  }
  std::fflush(out_);
}

}  // namespace orni::studies
