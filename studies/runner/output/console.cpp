#include "studies/runner/output/console.hpp"

#include <atomic>
#include <deque>
#include <iostream>
#include <mutex>
#include <streambuf>
#include <utility>

namespace orni::studies {

namespace {

std::atomic<bool> g_quiet{false};

/// A stream buffer that accepts everything and keeps nothing (the stream stays good, unlike a
/// stream without a buffer, so a later `<<` behaves as on a console).
class DiscardBuffer : public std::streambuf {
 protected:
  int_type overflow(int_type c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

std::atomic<bool> g_capture{false};
std::mutex g_lines_mutex;
std::deque<ConsoleLine> g_lines;  // guarded by g_lines_mutex
constexpr std::size_t kMaxLines = 10000;

void keepLine(std::string text, ConsoleLine::Kind kind) {
  const std::lock_guard<std::mutex> lock(g_lines_mutex);
  if (g_lines.size() >= kMaxLines) g_lines.pop_front();
  g_lines.push_back({kind, std::move(text)});
}

/// A stream buffer that keeps each complete line (capture on) or nothing.
class CaptureBuffer : public std::streambuf {
 public:
  explicit CaptureBuffer(bool error) : error_(error) {}

 protected:
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    put(traits_type::to_char_type(c));
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (std::streamsize i = 0; i < n; ++i) put(s[i]);
    return n;
  }

 private:
  void put(char c) {
    if (!g_capture.load()) {
      line_.clear();
      return;
    }
    if (c != '\n') {
      line_ += c;
      return;
    }
    keepLine(std::move(line_), error_ ? ConsoleLine::Kind::kNote : ConsoleLine::Kind::kResult);
    line_.clear();
  }
  bool error_;
  std::string line_;
};

std::ostream& captureStream(bool error) {
  // One per thread and stream: a partial line belongs to the thread that writes it.
  thread_local CaptureBuffer out_buffer(false);
  thread_local CaptureBuffer err_buffer(true);
  thread_local std::ostream out(&out_buffer);
  thread_local std::ostream err(&err_buffer);
  return error ? err : out;
}

std::ostream& discardStream() {
  // One per thread: a stream's state and formatting flags are not shared between threads.
  thread_local DiscardBuffer buffer;
  thread_local std::ostream stream(&buffer);
  return stream;
}

}  // namespace

std::ostream& consoleOut() {
  if (!g_quiet.load()) return std::cout;
  return g_capture.load() ? captureStream(false) : discardStream();
}

std::ostream& consoleErr() {
  if (!g_quiet.load()) return std::cerr;
  return g_capture.load() ? captureStream(true) : discardStream();
}

void setConsoleQuiet(bool quiet) noexcept { g_quiet.store(quiet); }

bool consoleQuiet() noexcept { return g_quiet.load(); }

void setConsoleCapture(bool capture) noexcept { g_capture.store(capture); }

void consoleCaptureProgress(const std::string& line) {
  if (g_quiet.load() && g_capture.load()) keepLine(line, ConsoleLine::Kind::kProgress);
}

std::vector<ConsoleLine> takeConsoleLines() {
  const std::lock_guard<std::mutex> lock(g_lines_mutex);
  std::vector<ConsoleLine> out(std::make_move_iterator(g_lines.begin()),
                               std::make_move_iterator(g_lines.end()));
  g_lines.clear();
  return out;
}

}  // namespace orni::studies
