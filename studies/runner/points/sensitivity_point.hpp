// One point of a sensitivity study (kind = "sensitivity", config/sensitivity_study.hpp): trim the
// point's vehicle, fly it freely from the trim and hold it tethered at the trim, and reduce the
// three runs to one row of sensitivity.csv: the model's predictions. No files are written here.
//
// The runs of a point, all on one FlightCoreModel:
//   trim       solveTrim with the point's [trim] options (Eq. 4 and the free-flight refinement),
//              without its own free-flight check (the free flight below is that check, with the
//              study's cycles and bounds: at the defaults it is the same run as the trim's check);
//   free       simulateFree from the trim point, [sensitivity] free_flight_cycles and
//              [sensitivity.free] (default tolerances, as the trim's check): pitch swing, the
//              altitude oscillations (core/analysis/limit_cycle.hpp) and the Eq. (5) verdict;
//   tethered   simulateTethered at the trim point with the trim's periodic-run options (rel_tol
//              1e-6, stop at the periodic steady state, at most max_cycles): the hinge and
//              aerodynamic power (cycle means) and the constrained flight test of its last cycle
//              (core/dynamics/zero_moment_point.hpp, paper Fig. 9), all at the trim point after
//              the free-flight refinement. (The trim's own mean.hinge_power_W, which `trim` reports
//              and `optimize` minimises, is at the stage-1 Eq. (4) point: hinge_power_eq4_W.)
//
// Status of a point (the worst that applies) and the cells it fills:
//   not_converged  the trim did not converge: every cell empty, the message says why; or the
//                  tethered run did not reach its periodic steady state in max_cycles: every cell
//                  filled (the last cycle, as a tethered simulate reports it);
//   diverged       the free flight diverged: trim and tethered cells filled, the free-flight cells
//                  empty but bounded = 0;
//   failed         a run failed or threw: the cells of that run empty;
//   ok             every cell filled.
// Empty cells are "" in the CSV (never NaN).
#pragma once

#include <string>
#include <vector>

#include "studies/runner/points/sweep_point.hpp"
#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// A result column of sensitivity.csv.
struct SensitivityColumn {
  std::string name;         ///< e.g. "theta_mean_deg"
  std::string unit;         ///< e.g. "deg"; "-" for none
  std::string label;        ///< what it is, for the figures
  bool prediction = false;  ///< a prediction: ranked in summary.json, drawn as a tornado
};

/// The result columns, between `status` and `message`: the predictions first, then the other
/// results of the runs (aerodynamic power, the stage-1 hinge power, bounded, theta range, climb
/// rate).
const std::vector<SensitivityColumn>& sensitivityResultColumns();

/// Runs one point (a study of kind trim) with the free-flight settings of `settings` and tabulates
/// it in the columns of sensitivityResultColumns (a row: status, cells, message; the row type of
/// sweeps, journaled with encodeSweepPoint). Exceptions become status "failed" with the reason.
/// Thread-safe: it builds its own FlightCoreModel and workspaces; flexible wings come from
/// `modal_wings` (thread-safe; null: built for the point alone).
SweepPointResult runSensitivityPoint(const Study& point, const SensitivitySettings& settings,
                                     ModalWingCache* modal_wings = nullptr);

}  // namespace orni::studies
