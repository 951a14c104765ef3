// Figures with gnuplot (PNG and SVG). Each figure is a script STEM.gp kept in the run folder, so
// `ornithopter plot RUN_DIR` can redraw it; outputs are written to temporary names and renamed.
#pragma once

#include <filesystem>
#include <string>

namespace orni::studies {

/// Write DIR/STEM.gp from `body` (plot commands; the script header sets the terminal, output and
/// CSV conventions: comma separator, two header rows to skip) and draw STEM.png and STEM.svg.
void drawFigure(const std::filesystem::path& dir, const std::string& stem,
                const std::string& body);

/// Redraw every *.gp figure script in `dir`; returns how many were drawn.
int redrawFigures(const std::filesystem::path& dir);

}  // namespace orni::studies
