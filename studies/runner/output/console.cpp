#include "studies/runner/output/console.hpp"

#include <atomic>
#include <iostream>
#include <streambuf>

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

std::ostream& discardStream() {
  // One per thread: a stream's state and formatting flags are not shared between threads.
  thread_local DiscardBuffer buffer;
  thread_local std::ostream stream(&buffer);
  return stream;
}

}  // namespace

std::ostream& consoleOut() { return g_quiet.load() ? discardStream() : std::cout; }

std::ostream& consoleErr() { return g_quiet.load() ? discardStream() : std::cerr; }

void setConsoleQuiet(bool quiet) noexcept { g_quiet.store(quiet); }

bool consoleQuiet() noexcept { return g_quiet.load(); }

}  // namespace orni::studies
