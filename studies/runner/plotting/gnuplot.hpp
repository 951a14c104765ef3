// Figures with gnuplot (PNG and SVG). Each figure is a script STEM.gp kept in the run folder, so
// `ornithopter plot RUN_DIR` can redraw it. A figure is complete or absent: gnuplot draws into a
// private folder DIR/.plot-STEM-PID.N, each output is checked (PNG signature and end chunk, SVG
// closing tag: gnuplot exits 0 even when the disk is full) and renamed into place, and the folder
// is removed whatever happens. The environment variable ORNI_GNUPLOT names another gnuplot
// program (tests use a stand-in).
//
// gnuplot runs as a child process in the caller's process group (a terminal's Ctrl-C reaches it
// too). While it runs the caller polls the cancellation request (core/model/cancellation.hpp, set
// by the CLI's SIGINT/SIGTERM handler): a request stops gnuplot (SIGTERM, then SIGKILL) and
// throws Cancelled; a gnuplot that died while a request stands is an interrupt too, never
// "gnuplot failed".
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace orni::studies {

/// Whether drawFigure draws figures (true, the default) or writes only their scripts (false: a
/// study's `[output] figures = false`, `--no-figures`, a library call without figures), for
/// every thread from now on. `ornithopter plot DIR` draws the kept scripts later.
void setFiguresWanted(bool wanted) noexcept;
bool figuresWanted() noexcept;

/// Figures wanted while it lives when `wanted` and they were wanted before (a study's
/// `[output] figures = false` inside a run without --no-figures); the earlier choice afterwards.
class FiguresScope {
 public:
  explicit FiguresScope(bool wanted) noexcept;
  ~FiguresScope();
  FiguresScope(const FiguresScope&) = delete;
  FiguresScope& operator=(const FiguresScope&) = delete;

 private:
  bool previous_;
};

/// True when the gnuplot program (ORNI_GNUPLOT, else the one found at build time, else `gnuplot`
/// on PATH) can be started: an executable file at its path, or on PATH.
bool gnuplotAvailable();

/// Write DIR/STEM.gp from `body` (plot commands; the script header sets the terminal, output and
/// CSV conventions: comma separator, two header rows to skip) and draw STEM.png and STEM.svg when
/// figures are wanted. Without gnuplot the figure is skipped with one notice per process on the
/// console (console.hpp), not an error. Throws std::runtime_error (with the end of gnuplot's log)
/// when a figure cannot be drawn.
void drawFigure(const std::filesystem::path& dir, const std::string& stem,
                const std::string& body);

/// Redraw every *.gp figure script in `dir` (an existing folder) whose stem `include` takes (every
/// one when it is empty); returns how many were drawn. Throws std::runtime_error when one cannot
/// be drawn.
int redrawFigures(const std::filesystem::path& dir,
                  const std::function<bool(const std::string& stem)>& include = {});

}  // namespace orni::studies
