#include "studies/runner/commands/modes_command.hpp"
#include "studies/runner/output/console.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/model/vehicle_validation.hpp"
#include "core/model/wing_geometry.hpp"
#include "core/structure/calculix_deck.hpp"
#include "core/structure/modal_wing.hpp"
#include "core/structure/wing_mesh.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "studies/runner/output/atomic_file.hpp"
#include "studies/runner/output/csv_table.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/output/json_writer.hpp"
#include "studies/runner/output/summary_file.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "studies/runner/plotting/modes_figure.hpp"

namespace orni::studies {

namespace {

const char* p3JointName(P3Joint j) {
  switch (j) {
    case P3Joint::kUniversal: return "universal";
    case P3Joint::kSpherical: return "spherical";
    case P3Joint::kRevoluteX: return "revolute_x";
    case P3Joint::kClamped: return "clamped";
  }
  return "universal";
}

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// Modes drawn in modes.png/svg.
constexpr int kFigureModes = 6;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

std::vector<double> toVector(const Eigen::VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

CsvTable modesTable(const structure::ModalWing& wing) {
  const structure::EffectiveMassTable& e = wing.effective_mass;
  const auto k = [](std::size_t i) { return static_cast<Eigen::Index>(i); };
  return RowTable("modes.csv", rowIndices(static_cast<std::size_t>(wing.modeCount())))
      .number("mode", [](std::size_t i) { return i + 1; })
      .number("frequency", [&](std::size_t i) { return wing.frequencies_hz[k(i)]; })
      .number("damping_ratio", [&](std::size_t i) { return wing.damping_ratios[k(i)]; })
      .number("flap_effective_mass", [&](std::size_t i) { return e.flap_fraction[k(i)]; })
      .number("heave_effective_mass", [&](std::size_t i) { return e.heave_fraction[k(i)]; })
      .number("flap_effective_mass_cumulative",
              [&](std::size_t i) { return e.flap_cumulative[k(i)]; })
      .number("heave_effective_mass_cumulative",
              [&](std::size_t i) { return e.heave_cumulative[k(i)]; })
      .table();
}

CsvTable modeShapeTable(const structure::ModalWing& wing) {
  const std::vector<Vec3>& nodes = wing.mesh.nodes_W_m;
  CsvTable t = RowTable("mode_shapes.csv", rowIndices(nodes.size()))
                   .number("node", [](std::size_t p) { return p; })
                   .number("x_W", [&](std::size_t p) { return nodes[p].x(); })
                   .number("y_W", [&](std::size_t p) { return nodes[p].y(); })
                   .table();
  for (int k = 0; k < wing.modeCount(); ++k)
    t.addColumn("w_" + std::to_string(k + 1), "m/sqrt(kg)", modeShapeW(wing, k));
  return t;
}

void writeFailedSummary(const fs::path& out_dir, const std::string& message, double wall_s) {
  JsonObject summary = summaryHeader("modes", "failed", message, wall_s);
  writeSummary(out_dir, summary);
}

}  // namespace

int runModesStudy(const Study& study, const fs::path& out_dir, const fs::path& export_ccx_path) {
  const auto t0 = Clock::now();
  if (!export_ccx_path.empty() && export_ccx_path.extension() != ".inp")
    throw InputError("command line", 0, "--export-ccx",
                     "option --export-ccx: expected a file name ending in .inp (CalculiX runs it "
                     "as `ccx -i JOB`), got '" + export_ccx_path.string() + "'");
  const VehicleModel& vehicle = study.vehicle;
  const WingFeSettings& fe = vehicle.wing.fe;

  // Mesh size guard (bad input, exit 2), the limit of a flexible wing's mesh
  // (core/model/vehicle_validation.hpp; the reader checks it only for flexible wings, this command
  // meshes rigid ones too).
  const double estimated_nodes = estimatedMeshNodes(vehicle.wing);
  if (!(estimated_nodes <= kMaxWingMeshNodes))
    throw vehicleKeyError(study, "wing.fe.element_size_m",
                           "an element size giving at most " + displayNumber(kMaxWingMeshNodes) +
                               " mesh nodes",
                           displayNumber(fe.element_size_m) + " (about " +
                               displayNumber(std::round(estimated_nodes)) + " mesh nodes)");

  structure::WingMesh mesh;
  try {
    mesh = structure::buildWingMesh(vehicle, fe.element_size_m);
  } catch (const std::invalid_argument& e) {
    throw InputError(inputFileOf(study), 0, "wing",
                     std::string("the wing cannot be meshed: ") + e.what());
  }
  const double mesh_s = seconds(t0);

  const structure::ModalWingOptions options = structure::modalWingOptionsOf(fe);

  fs::create_directories(out_dir);
  Study resolved = study;
  resolved.kind = StudyKind::kModes;
  writeFileAtomic(out_dir / "study.resolved.toml", resolvedStudyToml(resolved));

  // The deck first: it is useful even when our own eigen-solution fails.
  if (!export_ccx_path.empty()) {
    structure::CalculixDeckOptions deck_options;
    deck_options.mode_count = fe.max_modes;
    deck_options.p3_cross_axis_normal = fe.p3_cross_axis_normal;
    deck_options.p3_joint = fe.p3_joint;
    deck_options.root_edge_pinned = fe.root_edge_pinned;
    deck_options.heading = "Ornithopter wing " + vehicle.name + " (" + study.name +
                           "), fixed-interface modes";
    const std::string deck = structure::calculixDeck(vehicle, mesh, deck_options);
    try {
      writeFileAtomic(export_ccx_path, deck);
    } catch (const std::exception& e) {  // an output-path problem: bad input that names the option
      throw OutputPathError(export_ccx_path.string() + ": option --export-ccx: cannot write the "
                            "CalculiX deck: " + e.what());
    }
  }

  const auto t1 = Clock::now();
  structure::ModalWing wing;
  try {
    wing = structure::buildModalWing(vehicle, mesh, options);
  } catch (const std::invalid_argument& e) {
    throw InputError(inputFileOf(study), 0, "wing", std::string("bad wing model: ") + e.what());
  } catch (const std::runtime_error& e) {
    writeFailedSummary(out_dir, e.what(), seconds(t0));
    consoleErr() << "ornithopter: modes failed: " << e.what() << "\n";
    return 1;
  }
  const double modal_s = seconds(t1);

  const int m = wing.modeCount();
  const int figure_modes = std::min(kFigureModes, m);
  writeFileAtomic(out_dir / "modes.csv", modesTable(wing).toString());
  writeFileAtomic(out_dir / "mode_shapes.csv", modeShapeTable(wing).toString());
  writeFileAtomic(out_dir / "modes_figure.dat", modesFigureData(wing, vehicle.wing, figure_modes));

  const structure::EffectiveMassTable& e = wing.effective_mass;
  const double flap_total = m > 0 ? e.flap_cumulative(m - 1) : 0.0;
  const double heave_total = m > 0 ? e.heave_cumulative(m - 1) : 0.0;
  const std::string message = wing.selection.BriefReport();
  const int triangles = static_cast<int>(mesh.triangles.size());
  const int beams = static_cast<int>(mesh.beams.size());

  JsonObject summary = summaryHeader("modes", "ok", message, seconds(t0));
  summary.set("frequencies_hz", toVector(wing.frequencies_hz))
      .set("damping_ratios", toVector(wing.damping_ratios))
      .set("wing_mass_kg", wing.wing_mass_kg)
      .set("member_mass_kg", wing.member_mass_kg)
      .set("skin_mass_kg", wing.skin_mass_kg)
      .set("elements", triangles + beams)
      .set("modes", m)
      .set("static_shapes", wing.static_shape_count)
      .set("effective_mass",
           JsonObject()
               .set("flap_fraction", flap_total)
               .set("heave_fraction", heave_total)
               .set("flap_cumulative", toVector(e.flap_cumulative))
               .set("heave_cumulative", toVector(e.heave_cumulative))
               .set("flap_reference_kgm2", e.flap_reference_kgm2)
               .set("heave_reference_kg", e.heave_reference_kg))
      .set("mesh", JsonObject()
                       .set("element_size_m", fe.element_size_m)
                       .set("nodes", mesh.nodeCount())
                       .set("triangles", triangles)
                       .set("beams", beams)
                       .set("p2_node", mesh.p2_node)
                       .set("p3_node", mesh.p3_node))
      .set("settings", JsonObject()
                           .set("modes_requested", fe.max_modes)
                           .set("cutoff_hz", fe.cutoff_hz)
                           .set("damping_ratio", fe.damping_ratio)
                           .set("p3_cross_axis", fe.p3_cross_axis_normal ? "normal" : "span")
                           .set("p3_joint", p3JointName(fe.p3_joint))
                           .set("root_edge", fe.root_edge_pinned ? "pinned" : "free")
                           .set("static_shapes_pa", fe.static_shapes_pa)
                           .set("mass_matrix", "consistent"))
      .set("selection", JsonObject()
                            .set("cutoff_reached", wing.selection.cutoff_reached)
                            .set("effective_mass_met", wing.selection.effective_mass_met))
      .set("build_time_s", JsonObject().set("mesh", mesh_s).set("modal", modal_s));
  if (!export_ccx_path.empty()) summary.set("calculix_deck", export_ccx_path.string());
  writeSummary(out_dir, summary);
  if (figure_modes > 0) drawFigure(out_dir, "modes", modesFigure(study, wing, figure_modes));

  std::ostringstream brief;
  brief.precision(4);
  for (int k = 0; k < std::min(m, 6); ++k) brief << (k ? ", " : "") << wing.frequencies_hz(k);
  char mass_text[96];
  std::snprintf(mass_text, sizeof mass_text, "flap/heave effective mass %.1f / %.1f %%",
                100.0 * flap_total, 100.0 * heave_total);
  consoleOut() << study.name << ": " << m << " modes, f = " << brief.str() << (m > 6 ? ", ..." : "")
            << " Hz; " << mass_text << "\n  -> " << out_dir.string() << "\n";
  if (!export_ccx_path.empty())
    consoleOut() << "  CalculiX deck: " << export_ccx_path.string() << " (run: ccx -i "
              << (export_ccx_path.parent_path() / export_ccx_path.stem()).string() << ")\n";
  return 0;
}

int runModesCommand(const fs::path& vehicle_file, const fs::path& out_dir,
                    const std::string& export_ccx_path) {
  Study study = studyFromVehicle(vehicle_file, StudyKind::kModes);
  return runModesStudy(study, out_dir, fs::path(export_ccx_path));
}

}  // namespace orni::studies
