// `ornithopter modes VEHICLE.toml [-o DIR] [--export-ccx FILE.inp]` and `kind = "modes"` studies:
// the wing's finite-element mesh and fixed-interface modes from the vehicle's [wing.fe] settings
// (docs/theory.md 2.5, 2.6, 3.4, 3.5). Writes summary.json, study.resolved.toml, modes.csv,
// mode_shapes.csv and the figure modes.png/svg (docs/design.md 4), and the CalculiX deck
// (docs/theory.md 2.7) when asked.
#pragma once

#include <filesystem>
#include <string>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// Run the modes analysis of `study.vehicle` into `out_dir`; when `export_ccx_path` is not empty,
/// also write the CalculiX deck of the same mesh there. Returns the process exit code (0 finished,
/// 1 failed: the eigen-solution did not converge). Bad input (a wing the mesher cannot mesh, an
/// element size that would give an enormous mesh, a deck name not ending in .inp) throws
/// InputError (exit 2, mapped by main).
int runModesStudy(const Study& study, const std::filesystem::path& out_dir,
                  const std::filesystem::path& export_ccx_path = {});

/// `ornithopter modes`: loads the vehicle file (InputError on bad input), then runModesStudy with
/// kind "modes" and the vehicle file stem as the run name. `export_ccx_path` "" = no deck.
int runModesCommand(const std::filesystem::path& vehicle_file,
                    const std::filesystem::path& out_dir, const std::string& export_ccx_path);

}  // namespace orni::studies
