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
};

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

  /// One line: stable or not, the leading multiplier, its label, the margin.
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

}  // namespace orni
