// Floquet analysis of a periodic orbit: the eigenvalues (multipliers) of the monodromy matrix, the
// Jacobian of the period map at the orbit (periodic_shooting.hpp).
//
// A deviation along eigenvector v is multiplied by mu every period. Per multiplier: modulus and
// argument; the equivalent continuous eigenvalue lambda = ln(mu) / T on the principal branch
// (Re lambda, the decay rate, is exact; Im lambda is only known modulo 2 pi / T: a motion faster
// than f/2 appears at its alias, as in any stroboscopic sampling); for a complex multiplier (and a
// negative real one, a period-doubling motion) the damping ratio -Re lambda / |lambda| and the
// period 2 pi / |Im lambda|; the states that dominate v, with v in scaled states (each state over
// its scale), named, and a label from the group that carries most of |v|^2: "phugoid-like: U,
// theta" or "short-period-like: W, Q" (body states; phugoid when U and theta carry more than W and
// Q), "wing mode k" (q_k and its rate); "aero lag" (the strips' circulation-lag and separation
// states) only when the body and the modes carry less than 1 % of |v|^2, because the lag states
// follow whatever motion drives them.
//
// Accuracy: the multipliers are those of the period map as discretised. A motion that the step
// grid does not resolve (the grid is chosen on the orbit, where a stiff wing mode far above the
// flapping frequency only follows the forcing quasi-statically) gets a less accurate multiplier
// (tests/unit/analysis: a 300 Hz mode forced at 12 Hz is off by 8e-5 on the grid of its orbit at
// rel_tol 1e-9, by < 1e-6 with the step limited to T/2000); on the magpie such multipliers are
// below 0.07 and do not decide the verdict.
//
// Stable: every multiplier strictly inside the unit circle; the margin is 1 - max |mu|. A system
// with ignorable states (a vehicle's position and altitude, which nothing depends on) has a
// multiplier 1 for each of them: they are left out of the state (their gains are conditions of
// the period map), so that `stable` is about the motions that matter.
#pragma once

#include <complex>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/analysis/monodromy.hpp"

namespace orni {

/// How a state is named and grouped in the labels.
enum class FloquetStateKind { kBodyU, kBodyW, kBodyTheta, kBodyQ, kModal, kAeroLag, kOther };

struct FloquetStateInfo {
  std::string name;                            ///< e.g. "U", "q3", "q3_dot", "lag_strip12"
  FloquetStateKind kind = FloquetStateKind::kOther;
  int mode = 0;                                ///< wing mode number (1-based) of a modal state
};

struct FloquetMultiplier {
  std::complex<double> mu;          ///< the multiplier
  double modulus = 0.0;             ///< |mu|
  double argument_rad = 0.0;        ///< arg(mu) in (-pi, pi]
  std::complex<double> exponent_per_s;  ///< ln(mu) / T, principal branch (|mu| floored at 1e-300)
  bool oscillatory = false;         ///< complex or negative real: damping ratio and period apply
  double damping_ratio = 0.0;       ///< -Re lambda / |lambda| (oscillatory), else sign(-Re lambda)
  double period_s = 0.0;            ///< 2 pi / |Im lambda| (oscillatory), else 0
  std::string label;                ///< "phugoid-like: U, theta", "wing mode 1", "aero lag", ...
  std::vector<std::pair<std::string, double>> dominant_states;  ///< name, share of |v|^2 (top 3)
  Eigen::VectorXcd eigenvector;     ///< scaled states, unit 2-norm
  /// |mu - mu_r|, mu_r the multiplier paired with this one in a second analysis on a finer
  /// discretisation (compareWithRefined): an estimate of this multiplier's error. NaN when not
  /// checked.
  double refinement_change = std::numeric_limits<double>::quiet_NaN();
  /// Checked and resolved: |mu| >= kResolvedModulusFloor and refinement_change <=
  /// kResolvedChangeFraction |mu|, so that the argument (the period) is good to about 3 deg and
  /// ln|mu| (the damping) to about 0.05. An unchecked multiplier is not resolved.
  bool resolved() const;
};

/// A multiplier is resolved when a finer discretisation moves it by at most this fraction of its
/// modulus: its argument then moves by at most asin(0.05) = 2.9 deg and ln|mu| by at most 0.05.
constexpr double kResolvedChangeFraction = 0.05;
/// Below this modulus (a motion more than 99.5 % gone within one period) no multiplier is called
/// resolved: on the magpie the aero-lag multipliers of 1e-3 and below agreed to 1e-8 between the
/// default grid and the 10 times finer one, yet differ by up to 60 % of |mu| from a 100 times
/// finer reference (tests/unit/trim/test_periodic_trim.cpp); 0.005 is five times the largest of
/// them. Such a motion matters to no flight-dynamics or stability question.
constexpr double kResolvedModulusFloor = 0.005;

struct FloquetAnalysis {
  double period_s = 0.0;
  std::vector<FloquetMultiplier> multipliers;  ///< by modulus, largest first (pairs adjacent,
                                               ///< positive argument first)
  int state_count = 0;        ///< n: how many multipliers the orbit has
  bool complete = false;      ///< all n listed (full monodromy), else the leading ones (Arnoldi)
  std::string method;         ///< how the multipliers were found (MonodromyEigen::message)
  double max_modulus = 0.0;
  bool stable = false;        ///< max_modulus < 1
  double margin = 0.0;        ///< 1 - max_modulus (< 0: unstable)
  /// The multipliers were compared with a finer discretisation's (compareWithRefined): how.
  bool checked = false;
  std::string check_method;

  /// One line: stable or not, the leading multiplier, its label, the margin; when checked, how
  /// many are resolved.
  std::string BriefReport() const;
};

/// Multipliers of `monodromy` (n x n, in the scaled states described by `states`, n entries) of an
/// orbit of period `period_s`. Throws std::invalid_argument on a size mismatch or non-finite input.
FloquetAnalysis analyseFloquet(const Eigen::MatrixXd& monodromy, double period_s,
                               const std::vector<FloquetStateInfo>& states);

/// The same from eigenpairs already found (monodromy.hpp: all, or the leading ones by Arnoldi;
/// `eigen.ok` required). Throws std::invalid_argument on a size mismatch or eigen.ok false.
FloquetAnalysis analyseFloquet(const MonodromyEigen& eigen, double period_s,
                               const std::vector<FloquetStateInfo>& states);

/// Pairs each multiplier of `analysis` with one of `refined` (the same orbit's multipliers on a
/// finer discretisation; all of them or the leading ones), leading multipliers first, each with
/// the nearest one not yet paired, and sets its refinement_change (the distance; infinity when
/// `refined` has none left); `how` is kept as check_method. The change estimates the error, it
/// does not bound it: a multiplier can be paired with another's partner that happens to lie
/// nearer than its own (in a cluster), and two grids can share an error (the modulus floor). How
/// far the flag can be trusted is measured against a tight reference on the magpie
/// (tests/unit/trim/test_periodic_trim.cpp). Throws std::invalid_argument when refined.ok is
/// false.
void compareWithRefined(FloquetAnalysis* analysis, const MonodromyEigen& refined,
                        const std::string& how);

}  // namespace orni
