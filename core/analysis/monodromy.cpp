#include "core/analysis/monodromy.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <stdexcept>

namespace orni {

bool ArnoldiOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (count < 1) return fail("count must be >= 1");
  if (!(tol > 0.0 && tol <= 1e-2)) return fail("tol must be in (0, 1e-2]");
  if (max_dimension < count + 1) return fail("max_dimension must be >= count + 1");
  if (!(fd_step > 0.0 && fd_step <= 1e-2)) return fail("fd_step must be in (0, 1e-2]");
  return true;
}

namespace {

// Indices of `mu` by modulus, largest first; equal moduli (to rounding: a conjugate pair) by
// argument, the positive one first, so the order does not depend on the last bit.
std::vector<Eigen::Index> leadingOrder(const Eigen::VectorXcd& mu) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(mu.size()));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::stable_sort(order.begin(), order.end(), [&mu](Eigen::Index a, Eigen::Index b) {
    const double ma = std::abs(mu[a]), mb = std::abs(mu[b]);
    const double tol = 1e-12 * std::max(1.0, std::max(ma, mb));
    if (std::abs(ma - mb) > tol) return ma > mb;
    return std::arg(mu[a]) > std::arg(mu[b]);
  });
  return order;
}

// How many of the sorted multipliers to keep so that `count` are kept and a conjugate pair is not
// split at the end.
int keepCount(const Eigen::VectorXcd& sorted, int count) {
  int k = std::min<int>(count, static_cast<int>(sorted.size()));
  if (k < sorted.size() && k > 0) {
    const std::complex<double> last = sorted[k - 1], next = sorted[k];
    if (last.imag() != 0.0 && std::abs(next - std::conj(last)) <= 1e-9 * std::max(1.0, std::abs(last)))
      ++k;
  }
  return k;
}

// A fixed pseudo-random start vector (64-bit LCG, Knuth's MMIX constants), unit 2-norm.
Eigen::VectorXd startVector(int n) {
  Eigen::VectorXd v(n);
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;
  for (int i = 0; i < n; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    v[i] = static_cast<double>(state >> 11) * 0x1.0p-53 - 0.5;
  }
  return v / v.norm();
}

}  // namespace

bool monodromyByDifferences(PeriodMap& map, const std::vector<double>& x,
                            const std::vector<double>& p, double fd_step, Eigen::MatrixXd* M,
                            long* maps, std::string* why) {
  const int n = map.stateCount();
  if (static_cast<int>(x.size()) != n || static_cast<int>(p.size()) != map.parameterCount())
    throw std::invalid_argument("monodromyByDifferences: one value per state and parameter");
  std::vector<double> g(static_cast<std::size_t>(map.conditionCount()) + 1);
  std::vector<double> base(static_cast<std::size_t>(n)), xp = x, end(static_cast<std::size_t>(n));
  long used = 0;
  auto done = [&](bool ok) {
    if (maps) *maps = used;
    return ok;
  };
  ++used;
  if (!map.flow(x.data(), p.data(), base.data(), g.data(), why)) return done(false);
  M->resize(n, n);
  for (int j = 0; j < n; ++j) {
    const double s_j = map.stateScale(j);
    const double h = fd_step * std::max(1.0, std::abs(x[static_cast<std::size_t>(j)] / s_j));
    xp[static_cast<std::size_t>(j)] = x[static_cast<std::size_t>(j)] + h * s_j;
    ++used;
    const bool ok = map.flow(xp.data(), p.data(), end.data(), g.data(), why);
    xp[static_cast<std::size_t>(j)] = x[static_cast<std::size_t>(j)];
    if (!ok) return done(false);
    for (int i = 0; i < n; ++i)
      (*M)(i, j) = (end[static_cast<std::size_t>(i)] - base[static_cast<std::size_t>(i)]) /
                   (map.stateScale(i) * h);
  }
  if (!M->allFinite()) {
    if (why) *why = "non-finite monodromy";
    return done(false);
  }
  return done(true);
}

MonodromyEigen eigenOfMonodromy(const Eigen::MatrixXd& M) {
  MonodromyEigen e;
  e.state_count = static_cast<int>(M.rows());
  e.complete = true;
  if (M.rows() < 1 || M.cols() != M.rows() || !M.allFinite()) {
    e.message = "not a finite square monodromy matrix";
    return e;
  }
  Eigen::EigenSolver<Eigen::MatrixXd> es(M, true);
  if (es.info() != Eigen::Success) {
    e.message = "the eigenvalue iteration did not converge";
    return e;
  }
  const std::vector<Eigen::Index> order = leadingOrder(es.eigenvalues());
  const Eigen::Index n = M.rows();
  e.multipliers.resize(n);
  e.vectors.resize(n, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    e.multipliers[k] = es.eigenvalues()[order[static_cast<std::size_t>(k)]];
    Eigen::VectorXcd v = es.eigenvectors().col(order[static_cast<std::size_t>(k)]);
    const double norm = v.norm();
    e.vectors.col(k) = norm > 0.0 ? Eigen::VectorXcd(v / norm) : v;
  }
  e.residuals.assign(static_cast<std::size_t>(n), 0.0);
  e.ok = true;
  e.message = "all " + std::to_string(n) + " multipliers of the full monodromy matrix";
  return e;
}

MonodromyEigen leadingMultipliers(PeriodMap& map, const std::vector<double>& x,
                                  const std::vector<double>& p, const ArnoldiOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("Arnoldi options: " + why);
  const int n = map.stateCount();
  if (static_cast<int>(x.size()) != n || static_cast<int>(p.size()) != map.parameterCount())
    throw std::invalid_argument("leadingMultipliers: one value per state and parameter");
  MonodromyEigen e;
  e.state_count = n;
  const int m_max = std::min(options.max_dimension, n);
  const int wanted = std::min(options.count, n);

  // The operator v -> M v (scaled states) by a forward difference along v.
  Eigen::VectorXd scale(n), z(n);
  for (int i = 0; i < n; ++i) {
    scale[i] = map.stateScale(i);
    z[i] = x[static_cast<std::size_t>(i)] / scale[i];
  }
  const double h = options.fd_step * std::max(1.0, z.cwiseAbs().maxCoeff());
  std::vector<double> g(static_cast<std::size_t>(map.conditionCount()) + 1);
  std::vector<double> base(static_cast<std::size_t>(n)), xp(static_cast<std::size_t>(n)),
      end(static_cast<std::size_t>(n));
  ++e.period_maps;
  if (!map.flow(x.data(), p.data(), base.data(), g.data(), &why)) {
    e.message = "the period map failed at the orbit: " + why;
    return e;
  }
  auto apply = [&](const Eigen::VectorXd& v, Eigen::VectorXd* w) {
    for (int i = 0; i < n; ++i)
      xp[static_cast<std::size_t>(i)] = x[static_cast<std::size_t>(i)] + h * scale[i] * v[i];
    ++e.period_maps;
    if (!map.flow(xp.data(), p.data(), end.data(), g.data(), &why)) return false;
    w->resize(n);
    for (int i = 0; i < n; ++i)
      (*w)[i] = (end[static_cast<std::size_t>(i)] - base[static_cast<std::size_t>(i)]) /
                (scale[i] * h);
    return w->allFinite();
  };

  Eigen::MatrixXd V = Eigen::MatrixXd::Zero(n, m_max + 1);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m_max + 1, m_max);
  V.col(0) = startVector(n);
  Eigen::VectorXd w;
  char buf[320];
  for (int j = 0; j < m_max; ++j) {
    if (!apply(V.col(j), &w)) {
      e.message = "a period map of the Arnoldi iteration failed: " + (why.empty() ? "non-finite" : why);
      return e;
    }
    // Modified Gram-Schmidt, twice (the second pass restores orthogonality lost to rounding).
    for (int pass = 0; pass < 2; ++pass)
      for (int i = 0; i <= j; ++i) {
        const double c = V.col(i).dot(w);
        H(i, j) += c;
        w -= c * V.col(i);
      }
    const double beta = w.norm();
    H(j + 1, j) = beta;
    const int m = j + 1;
    const bool breakdown = !(beta > 1e-14 * std::max(1.0, H.col(j).norm()));
    const bool full = m == n;
    if (m >= wanted || breakdown) {
      Eigen::EigenSolver<Eigen::MatrixXd> es(H.topLeftCorner(m, m), true);
      if (es.info() != Eigen::Success) {
        e.message = "the Hessenberg eigenvalue iteration did not converge";
        return e;
      }
      const std::vector<Eigen::Index> order = leadingOrder(es.eigenvalues());
      Eigen::VectorXcd sorted(m);
      for (int k = 0; k < m; ++k) sorted[k] = es.eigenvalues()[order[static_cast<std::size_t>(k)]];
      const int keep = keepCount(sorted, wanted);
      bool converged = true;
      std::vector<double> res(static_cast<std::size_t>(keep));
      for (int k = 0; k < keep; ++k) {
        const Eigen::VectorXcd y = es.eigenvectors().col(order[static_cast<std::size_t>(k)]);
        res[static_cast<std::size_t>(k)] = (breakdown || full) ? 0.0 : beta * std::abs(y[m - 1]) / y.norm();
        converged = converged && res[static_cast<std::size_t>(k)] <= options.tol;
      }
      if (converged || breakdown || full) {
        e.multipliers = sorted.head(keep);
        e.vectors.resize(n, keep);
        for (int k = 0; k < keep; ++k) {
          const Eigen::VectorXcd y = es.eigenvectors().col(order[static_cast<std::size_t>(k)]);
          Eigen::VectorXcd v = V.leftCols(m).cast<std::complex<double>>() * y;
          const double norm = v.norm();
          e.vectors.col(k) = norm > 0.0 ? Eigen::VectorXcd(v / norm) : v;
        }
        e.residuals = res;
        e.krylov_dimension = m;
        e.complete = full;
        e.ok = true;
        std::snprintf(buf, sizeof buf,
                      "%d leading multipliers of %d by Arnoldi (Krylov dimension %d, Ritz "
                      "residuals <= %.1e%s; %ld period maps)",
                      keep, n, m, options.tol, breakdown ? ", invariant subspace" : "",
                      e.period_maps);
        e.message = buf;
        return e;
      }
    }
    V.col(j + 1) = w / beta;
  }
  std::snprintf(buf, sizeof buf,
                "Arnoldi did not converge: %d leading Ritz residuals not below %.1e at Krylov "
                "dimension %d",
                wanted, options.tol, m_max);
  e.message = buf;
  return e;
}

}  // namespace orni
