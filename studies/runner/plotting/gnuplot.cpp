#include "studies/runner/plotting/gnuplot.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "studies/runner/output/atomic_file.hpp"

#ifndef ORNI_GNUPLOT
#define ORNI_GNUPLOT "gnuplot"
#endif

namespace orni::studies {

namespace {

std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The script draws the body twice: once for PNG, once for SVG.
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

void runScript(const std::filesystem::path& dir, const std::string& stem) {
  const std::string cmd = "cd " + shellQuote(dir.string()) + " && " ORNI_GNUPLOT " " +
                          shellQuote(stem + ".gp") + " > " + shellQuote(stem + ".gnuplot.log") +
                          " 2>&1";
  const int rc = std::system(cmd.c_str());
  if (rc != 0)
    throw std::runtime_error("gnuplot failed on " + (dir / (stem + ".gp")).string() + " (see " +
                             (dir / (stem + ".gnuplot.log")).string() + ")");
  for (const char* ext : {".png", ".svg"}) {
    std::filesystem::rename(dir / (stem + ext + ".tmp"), dir / (stem + ext));
  }
  std::filesystem::remove(dir / (stem + ".gnuplot.log"));
}

}  // namespace

void drawFigure(const std::filesystem::path& dir, const std::string& stem,
                const std::string& body) {
  writeFileAtomic(dir / (stem + ".gp"), scriptFor(stem, body));
  runScript(dir, stem);
}

int redrawFigures(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir))
    throw std::runtime_error("not a run folder: " + dir.string());
  std::vector<std::string> stems;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".gp") stems.push_back(e.path().stem().string());
  std::sort(stems.begin(), stems.end());
  for (const std::string& s : stems) runScript(dir, s);
  return static_cast<int>(stems.size());
}

}  // namespace orni::studies
