// A "still working" line on stderr for runs that have no points to count (docs/design.md 4.4):
// simulations, trims, stability analyses, calibrations, a continuation (its start trim). Silent
// for the first 2 s (a short run prints nothing more than before); then "trim: working, 12.0 s
// elapsed", a full line every 5 s on a terminal and every 10 s in a log (full lines: the run's
// own report on stdout never lands in the middle of one). A thread of its own writes it, so it
// also shows a run whose solver is inside one long call; it never changes what the run computes.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace orni::studies {

class Heartbeat {
 public:
  explicit Heartbeat(std::string label, std::FILE* out = stderr);
  /// Stops the thread.
  ~Heartbeat();
  Heartbeat(const Heartbeat&) = delete;
  Heartbeat& operator=(const Heartbeat&) = delete;

  /// The text of the line (public for tests).
  static std::string text(const std::string& label, double elapsed_s);

 private:
  void loop();
  std::string label_;
  std::FILE* out_;
  bool tty_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;  // last: started when everything else is set
};

}  // namespace orni::studies
