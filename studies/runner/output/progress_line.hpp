// A progress line on stderr for long runs (aero maps, sweeps): "aeromap: 57/180 points, 3.1 s
// elapsed, ETA 6.6 s". On a terminal the line is redrawn in place at most every 0.5 s; otherwise
// (a log file) a full line is written at most every 10 s. The ETA extrapolates the points done by
// this run (resumed points cost nothing).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace orni::studies {

class ProgressLine {
 public:
  /// `label` starts the line; `total` points, of which `already_done` were done before (resumed).
  ProgressLine(std::string label, std::size_t total, std::size_t already_done,
               std::FILE* out = stderr);
  /// One more point done; redraws when the interval has passed.
  void pointDone();
  /// Final line (always written, ends with a newline).
  void finish();

  /// The text of the line for `done` of `total` points after `elapsed_s`, `done_here` of them by
  /// this run (public for tests).
  static std::string text(const std::string& label, std::size_t done, std::size_t total,
                          std::size_t done_here, double elapsed_s);

 private:
  void draw(bool final_line);
  std::string label_;
  std::size_t total_, done_, done_here_ = 0;
  std::FILE* out_;
  bool tty_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::size_t last_width_ = 0;
};

}  // namespace orni::studies
