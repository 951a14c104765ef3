// The figure of the wing's modes (gnuplot body for drawFigure, gnuplot.hpp): colour maps of the
// first modes' out-of-plane shapes over the planform, from modes_figure.dat, which
// modesFigureData writes (the mesh interpolated onto a coarse grid that follows the planform).
#pragma once

#include <string>
#include <vector>

#include "core/model/wing_geometry.hpp"
#include "core/structure/modal_wing.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// The z_W column of mode k over all nodes, signed so that its largest |w| is positive (mode
/// shapes are defined up to sign; this makes the output deterministic): the figure's and
/// mode_shapes.csv's.
std::vector<double> modeShapeW(const structure::ModalWing& wing, int k);

/// gnuplot data of the colour maps (modes_figure.dat) of the first `modes` modes.
std::string modesFigureData(const structure::ModalWing& wing, const WingModel& planform, int modes);

/// The figure (reads modes_figure.dat): one panel per mode, the members drawn on top.
std::string modesFigure(const Study& study, const structure::ModalWing& wing, int modes);

}  // namespace orni::studies
