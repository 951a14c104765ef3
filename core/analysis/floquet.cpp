#include "core/analysis/floquet.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/model/frames.hpp"

namespace orni {

namespace {


bool isBody(FloquetStateKind k) {
  return k == FloquetStateKind::kBodyU || k == FloquetStateKind::kBodyW ||
         k == FloquetStateKind::kBodyTheta || k == FloquetStateKind::kBodyQ;
}

// Label and dominant states of an eigenvector (shares of |v|^2).
void describe(const std::vector<FloquetStateInfo>& states, FloquetMultiplier* m) {
  const Eigen::Index n = m->eigenvector.size();
  std::vector<double> share(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) share[static_cast<std::size_t>(i)] = std::norm(m->eigenvector[i]);
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return share[static_cast<std::size_t>(a)] > share[static_cast<std::size_t>(b)];
  });
  for (std::size_t k = 0; k < std::min<std::size_t>(3, order.size()); ++k)
    m->dominant_states.emplace_back(states[static_cast<std::size_t>(order[k])].name,
                                    share[static_cast<std::size_t>(order[k])]);

  // Group weights: the body, each wing mode, the aerodynamic states, anything else per state.
  double body = 0.0, aero = 0.0, body_UT = 0.0, body_WQ = 0.0;
  std::vector<double> mode_share;
  for (Eigen::Index i = 0; i < n; ++i) {
    const FloquetStateInfo& s = states[static_cast<std::size_t>(i)];
    const double w = share[static_cast<std::size_t>(i)];
    if (isBody(s.kind)) {
      body += w;
      (s.kind == FloquetStateKind::kBodyU || s.kind == FloquetStateKind::kBodyTheta ? body_UT
                                                                                     : body_WQ) += w;
    } else if (s.kind == FloquetStateKind::kModal && s.mode >= 1) {
      if (static_cast<int>(mode_share.size()) < s.mode)
        mode_share.resize(static_cast<std::size_t>(s.mode), 0.0);
      mode_share[static_cast<std::size_t>(s.mode - 1)] += w;
    } else if (s.kind == FloquetStateKind::kAeroLag) {
      aero += w;
    }
  }
  int best_mode = 0;
  double mode_max = 0.0;
  for (std::size_t k = 0; k < mode_share.size(); ++k)
    if (mode_share[k] > mode_max) {
      mode_max = mode_share[k];
      best_mode = static_cast<int>(k) + 1;
    }
  // The aerodynamic lag states follow the motion that drives them (a short-period pair moves
  // every strip's lag state with the angle of attack: 65 % of |v|^2 in the steady glide), so they
  // name a multiplier only when the body and the wing modes together carry less than 1 %.
  double modal = 0.0;
  for (double w : mode_share) modal += w;
  constexpr double kSlavedShare = 0.01;
  if (body + modal < kSlavedShare) {
    m->label = aero > 0.0 ? "aero lag"
                          : (m->dominant_states.empty() ? "" : m->dominant_states.front().first);
    return;
  }
  const double top = std::max(body, mode_max);
  if (top == body) {
    // The two body states with the largest shares, in order.
    std::string names;
    int count = 0;
    for (Eigen::Index i : order) {
      if (!isBody(states[static_cast<std::size_t>(i)].kind)) continue;
      names += (count ? ", " : "") + states[static_cast<std::size_t>(i)].name;
      if (++count == 2) break;
    }
    m->label = std::string(body_UT >= body_WQ ? "phugoid-like: " : "short-period-like: ") + names;
  } else {
    m->label = "wing mode " + std::to_string(best_mode);
  }
}

}  // namespace

std::string FloquetAnalysis::BriefReport() const {
  char buf[320];
  if (multipliers.empty()) return "no multipliers";
  const FloquetMultiplier& m = multipliers.front();
  std::snprintf(buf, sizeof buf,
                "%s: max |mu| = %.6f (%s, arg %.2f deg), margin %.4f; %s%zu of %d multipliers",
                stable ? "stable" : "unstable", max_modulus, m.label.c_str(),
                m.argument_rad * 180.0 / kPi, margin, complete ? "" : "leading ",
                multipliers.size(), state_count);
  std::string out = buf;
  if (checked) {
    const auto resolved = std::count_if(multipliers.begin(), multipliers.end(),
                                        [](const FloquetMultiplier& x) { return x.resolved(); });
    std::snprintf(buf, sizeof buf, ", %td resolved (a finer grid moves them by <= %.0f %%)",
                  resolved, 100.0 * kResolvedChangeFraction);
    out += buf;
  }
  return out;
}

FloquetAnalysis analyseFloquet(const Eigen::MatrixXd& monodromy, double period_s,
                               const std::vector<FloquetStateInfo>& states) {
  const Eigen::Index n = monodromy.rows();
  if (n < 1 || monodromy.cols() != n || static_cast<Eigen::Index>(states.size()) != n)
    throw std::invalid_argument("analyseFloquet: a square monodromy matrix with one name per state");
  if (!monodromy.allFinite() || !(period_s > 0.0))
    throw std::invalid_argument("analyseFloquet: non-finite monodromy or period <= 0");
  const MonodromyEigen eigen = eigenOfMonodromy(monodromy);
  if (!eigen.ok) throw std::runtime_error("analyseFloquet: " + eigen.message);
  return analyseFloquet(eigen, period_s, states);
}

FloquetAnalysis analyseFloquet(const MonodromyEigen& eigen, double period_s,
                               const std::vector<FloquetStateInfo>& states) {
  const Eigen::Index n = eigen.state_count;
  const Eigen::Index count = eigen.multipliers.size();
  if (!eigen.ok || count < 1 || count > n || eigen.vectors.rows() != n ||
      eigen.vectors.cols() != count || static_cast<Eigen::Index>(states.size()) != n)
    throw std::invalid_argument("analyseFloquet: valid eigenpairs with one name per state");
  if (!(period_s > 0.0)) throw std::invalid_argument("analyseFloquet: period <= 0");
  FloquetAnalysis a;
  a.period_s = period_s;
  a.state_count = static_cast<int>(n);
  a.complete = eigen.complete || count == n;
  a.method = eigen.message;
  for (Eigen::Index k = 0; k < count; ++k) {
    FloquetMultiplier m;
    m.mu = eigen.multipliers[k];
    m.modulus = std::abs(m.mu);
    m.argument_rad = std::arg(m.mu);
    const double log_mod = std::log(std::max(m.modulus, 1e-300));
    m.exponent_per_s = std::complex<double>(log_mod, m.argument_rad) / period_s;
    m.oscillatory = m.argument_rad != 0.0;
    const double lambda_abs = std::abs(m.exponent_per_s);
    if (m.oscillatory) {
      m.damping_ratio = lambda_abs > 0.0 ? -m.exponent_per_s.real() / lambda_abs : 0.0;
      m.period_s = 2.0 * kPi / std::abs(m.exponent_per_s.imag());
    } else {
      m.damping_ratio = m.exponent_per_s.real() < 0.0 ? 1.0 : -1.0;
      m.period_s = 0.0;
    }
    m.eigenvector = eigen.vectors.col(k);
    const double norm = m.eigenvector.norm();
    if (norm > 0.0) m.eigenvector /= norm;
    describe(states, &m);
    a.multipliers.push_back(std::move(m));
  }
  // Largest modulus first; within a conjugate pair the positive argument first. Moduli equal to
  // rounding count as equal so the pair order does not depend on the last bit.
  std::stable_sort(a.multipliers.begin(), a.multipliers.end(),
                   [](const FloquetMultiplier& x, const FloquetMultiplier& y) {
                     const double tol = 1e-12 * std::max(1.0, std::max(x.modulus, y.modulus));
                     if (std::abs(x.modulus - y.modulus) > tol) return x.modulus > y.modulus;
                     return x.argument_rad > y.argument_rad;
                   });
  a.max_modulus = a.multipliers.front().modulus;
  a.stable = a.max_modulus < 1.0;
  a.margin = 1.0 - a.max_modulus;
  return a;
}

bool FloquetMultiplier::resolved() const {
  return modulus >= kResolvedModulusFloor &&
         refinement_change <= kResolvedChangeFraction * modulus;  // false for NaN
}

void compareWithRefined(FloquetAnalysis* analysis, const MonodromyEigen& refined,
                        const std::string& how) {
  if (!refined.ok) throw std::invalid_argument("compareWithRefined: the refined analysis failed");
  std::vector<bool> used(static_cast<std::size_t>(refined.multipliers.size()), false);
  for (FloquetMultiplier& m : analysis->multipliers) {  // largest first
    double best = std::numeric_limits<double>::infinity();
    Eigen::Index at = -1;
    for (Eigen::Index k = 0; k < refined.multipliers.size(); ++k) {
      const double d = std::abs(m.mu - refined.multipliers(k));
      if (!used[static_cast<std::size_t>(k)] && d < best) {
        best = d;
        at = k;
      }
    }
    if (at >= 0) used[static_cast<std::size_t>(at)] = true;
    m.refinement_change = best;
  }
  analysis->checked = true;
  analysis->check_method = how;
}

}  // namespace orni
