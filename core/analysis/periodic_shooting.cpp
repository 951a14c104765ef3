#include "core/analysis/periodic_shooting.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <thread>
#include <utility>

namespace orni {

const char* toString(ShootingStatus s) {
  switch (s) {
    case ShootingStatus::kConverged: return "converged";
    case ShootingStatus::kNotConverged: return "not_converged";
    case ShootingStatus::kFailed: return "failed";
  }
  return "failed";
}

bool ShootingOptions::IsValid(int parameter_count, int condition_count, std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (free_parameters.size() != conditions.size())
    return fail("as many conditions as free parameters are needed (a square system)");
  for (std::size_t a = 0; a < free_parameters.size(); ++a) {
    if (free_parameters[a] < 0 || free_parameters[a] >= parameter_count)
      return fail("free parameter index out of range");
    if (conditions[a] < 0 || conditions[a] >= condition_count)
      return fail("condition index out of range");
    for (std::size_t b = 0; b < a; ++b)
      if (free_parameters[a] == free_parameters[b] || conditions[a] == conditions[b])
        return fail("free parameters and conditions must be distinct");
  }
  if (!(residual_tol > 0.0 && residual_tol <= 1e-2)) return fail("residual_tol must be in (0, 1e-2]");
  if (max_iterations < 1 || max_iterations > 1000) return fail("max_iterations must be in [1, 1000]");
  if (max_jacobians < 1 || max_jacobians > 100) return fail("max_jacobians must be in [1, 100]");
  if (!(fd_step > 0.0 && fd_step <= 1e-2)) return fail("fd_step must be in (0, 1e-2]");
  if (!(refresh_below >= 0.0)) return fail("refresh_below must be >= 0");
  if (!(slow_contraction > 0.0 && slow_contraction < 1.0))
    return fail("slow_contraction must be in (0, 1)");
  if (jacobian_threads < 1 || jacobian_threads > 64)
    return fail("jacobian_threads must be in [1, 64]");
  return true;
}

std::string ShootingSummary::BriefReport() const {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "%s: periodic residual %.3e (scaled, max norm) after %d Newton iterations; %ld "
                "period maps, %d Jacobians, %d Broyden updates, %d grid refreshes",
                toString(status), residual_max, iterations, period_maps, jacobians,
                broyden_updates, refreshes);
  return buf;
}

// ------------------------------------------------------------------------------------------------

ShootingSystem::ShootingSystem(PeriodMap& map, std::vector<int> free_parameters,
                               std::vector<int> conditions, std::vector<double> p)
    : map_(map),
      n_(map.stateCount()),
      free_(std::move(free_parameters)),
      cond_(std::move(conditions)),
      p_(std::move(p)),
      x_(static_cast<std::size_t>(n_)),
      x_T_(static_cast<std::size_t>(n_)),
      g_(static_cast<std::size_t>(map.conditionCount())) {
  if (static_cast<int>(p_.size()) != map.parameterCount())
    throw std::invalid_argument("ShootingSystem: one value per parameter needed");
}

Eigen::VectorXd ShootingSystem::pack(const double* x) const {
  Eigen::VectorXd z(unknownCount());
  for (int i = 0; i < n_; ++i) z[i] = x[i] / map_.stateScale(i);
  for (std::size_t a = 0; a < free_.size(); ++a)
    z[n_ + static_cast<Eigen::Index>(a)] =
        p_[static_cast<std::size_t>(free_[a])] / map_.parameterScale(free_[a]);
  return z;
}

void ShootingSystem::unpackInto(const Eigen::VectorXd& z, double* x, std::vector<double>* p) const {
  for (int i = 0; i < n_; ++i) x[i] = z[i] * map_.stateScale(i);
  for (std::size_t a = 0; a < free_.size(); ++a)
    (*p)[static_cast<std::size_t>(free_[a])] =
        z[n_ + static_cast<Eigen::Index>(a)] * map_.parameterScale(free_[a]);
}

void ShootingSystem::unpack(const Eigen::VectorXd& z, double* x) { unpackInto(z, x, &p_); }

bool ShootingSystem::evaluate(Run& run, const Eigen::VectorXd& z, Eigen::VectorXd* R,
                              std::string* why) const {
  unpackInto(z, run.x.data(), &run.p);
  ++run.maps;
  if (!run.map.flow(run.x.data(), run.p.data(), run.x_T.data(),
                    run.g.empty() ? nullptr : run.g.data(), why))
    return false;
  R->resize(unknownCount());
  for (int i = 0; i < n_; ++i)
    (*R)[i] = (run.x_T[static_cast<std::size_t>(i)] - run.x[static_cast<std::size_t>(i)]) /
              map_.stateScale(i);
  for (std::size_t a = 0; a < cond_.size(); ++a)
    (*R)[n_ + static_cast<Eigen::Index>(a)] =
        run.g[static_cast<std::size_t>(cond_[a])] / map_.conditionScale(cond_[a]);
  for (Eigen::Index i = 0; i < R->size(); ++i)
    if (!std::isfinite((*R)[i])) {
      if (why) *why = "non-finite period map";
      return false;
    }
  return true;
}

bool ShootingSystem::evaluate(const Eigen::VectorXd& z, Eigen::VectorXd* R, std::string* why) {
  Run run = own();
  return evaluate(run, z, R, why);
}

bool ShootingSystem::residual(const Eigen::VectorXd& z, Eigen::VectorXd* R, std::string* why) {
  return evaluate(z, R, why);
}

bool ShootingSystem::column(Run& run, const Eigen::VectorXd& z, const Eigen::VectorXd& R,
                            Eigen::Index j, double step, bool central, Eigen::MatrixXd* J,
                            std::string* why) const {
  const double h = step * std::max(1.0, std::abs(z[j]));
  Eigen::VectorXd zp = z, Rp, Rm;
  zp[j] += h;
  if (!evaluate(run, zp, &Rp, why)) return false;
  if (!central) {
    J->col(j) = (Rp - R) / h;
    return true;
  }
  zp[j] = z[j] - h;
  if (!evaluate(run, zp, &Rm, why)) return false;
  J->col(j) = (Rp - Rm) / (2.0 * h);
  return true;
}

bool ShootingSystem::parameterColumn(Run& run, const Eigen::VectorXd& z, const Eigen::VectorXd& R,
                                     int j, Eigen::Index e, double step, bool central,
                                     Eigen::MatrixXd* J_extra, std::string* why) const {
  const double s = map_.parameterScale(j);
  const double v = run.p[static_cast<std::size_t>(j)];
  const double h = step * std::max(1.0, std::abs(v / s));
  Eigen::VectorXd Rp, Rm;
  run.p[static_cast<std::size_t>(j)] = v + h * s;
  bool ok = evaluate(run, z, &Rp, why);
  if (ok && central) {
    run.p[static_cast<std::size_t>(j)] = v - h * s;
    ok = evaluate(run, z, &Rm, why);
    if (ok) J_extra->col(e) = (Rp - Rm) / (2.0 * h);
  } else if (ok) {
    J_extra->col(e) = (Rp - R) / h;
  }
  run.p[static_cast<std::size_t>(j)] = v;
  return ok;
}

bool ShootingSystem::partialJacobian(const Eigen::VectorXd& z, const Eigen::VectorXd& R,
                                     double step, const std::vector<int>& states,
                                     Eigen::MatrixXd* J, std::string* why) {
  const std::vector<double> x_T = x_T_, g = g_;
  const Eigen::Index N = unknownCount();
  J->setZero(N, N);
  for (int i = 0; i < n_; ++i) (*J)(i, i) = -1.0;
  // The differenced columns in the serial order: the listed states, then the parameters.
  std::vector<Eigen::Index> cols;
  for (int i : states)
    if (i >= 0 && i < n_) cols.push_back(i);
  for (Eigen::Index j = n_; j < N; ++j) cols.push_back(j);
  bool ok = true, cloned = false;
  if (threads_ > 1) ok = parallelJacobian(z, R, step, false, cols, J, why, {}, nullptr, &cloned);
  if (!cloned) {
    Run run = own();
    ok = true;
    for (std::size_t k = 0; k < cols.size() && ok; ++k)
      ok = column(run, z, R, cols[k], step, false, J, why);
  }
  unpack(z, x_.data());
  x_T_ = x_T;
  g_ = g;
  return ok;
}

bool ShootingSystem::parallelJacobian(const Eigen::VectorXd& z, const Eigen::VectorXd& R,
                                      double step, bool central,
                                      const std::vector<Eigen::Index>& cols, Eigen::MatrixXd* J,
                                      std::string* why, const std::vector<int>& extra,
                                      Eigen::MatrixXd* J_extra, bool* cloned) {
  const int N = static_cast<int>(cols.size());  // the columns of J, then the extra ones
  const int columns = N + (J_extra ? static_cast<int>(extra.size()) : 0);
  const int workers = std::min(threads_, columns);
  // Each worker: a copy of the map (same grid), the parameters and its own buffers.
  struct Worker {
    std::unique_ptr<PeriodMap> map;
    std::vector<double> p, x, x_T, g;
  };
  std::vector<Worker> pool(static_cast<std::size_t>(workers));
  for (Worker& w : pool) {
    w.map = map_.clone();
    if (!w.map) {
      *cloned = false;
      return false;
    }
    w.x.assign(x_.size(), 0.0);
    w.x_T.assign(x_T_.size(), 0.0);
    w.g.assign(g_.size(), 0.0);
  }
  *cloned = true;
  if (J_extra) J_extra->resize(unknownCount(), static_cast<Eigen::Index>(extra.size()));
  // Per column: success, its reason, the maps it used, an exception it threw. Every column writes
  // only its own column of J or J_extra.
  struct Outcome {
    bool ok = false;
    std::string why;
    long maps = 0;
    std::exception_ptr error;
  };
  std::vector<Outcome> out(static_cast<std::size_t>(columns));
  std::atomic<int> next{0};
  auto work = [&](Worker& w) {
    for (int k = next.fetch_add(1); k < columns; k = next.fetch_add(1)) {
      Outcome& o = out[static_cast<std::size_t>(k)];
      long maps = 0;
      Run run{*w.map, w.p, w.x, w.x_T, w.g, maps};
      w.p = p_;  // the parameter columns move one entry: start every column from the same values
      try {
        o.ok = k < N ? column(run, z, R, cols[static_cast<std::size_t>(k)], step, central, J,
                              &o.why)
                     : parameterColumn(run, z, R, extra[static_cast<std::size_t>(k - N)], k - N,
                                       step, central, J_extra, &o.why);
      } catch (...) {
        o.error = std::current_exception();
      }
      o.maps = maps;
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t t = 1; t < pool.size(); ++t) threads.emplace_back(work, std::ref(pool[t]));
  work(pool[0]);
  for (std::thread& t : threads) t.join();
  for (Worker& w : pool) map_.addWorkOf(*w.map);
  // As the serial loop: the maps up to the first column that failed, its reason or exception.
  for (const Outcome& o : out) {
    maps_ += o.maps;
    if (o.error) std::rethrow_exception(o.error);
    if (!o.ok) {
      if (why) *why = o.why;
      return false;
    }
  }
  return true;
}

bool ShootingSystem::jacobian(const Eigen::VectorXd& z, const Eigen::VectorXd& R, double step,
                              bool central, Eigen::MatrixXd* J, std::string* why,
                              const std::vector<int>& extra, Eigen::MatrixXd* J_extra) {
  const std::vector<double> x_T = x_T_, g = g_;  // the caller's last residual run
  const Eigen::Index N = unknownCount();
  const bool want_extra = !extra.empty() && J_extra;
  bool ok = true, cloned = false;
  J->resize(N, N);
  if (threads_ > 1) {
    std::vector<Eigen::Index> cols(static_cast<std::size_t>(N));
    for (Eigen::Index j = 0; j < N; ++j) cols[static_cast<std::size_t>(j)] = j;
    ok = parallelJacobian(z, R, step, central, cols, J, why, extra,
                          want_extra ? J_extra : nullptr, &cloned);
  }
  if (!cloned) {
    Run run = own();
    ok = true;
    for (Eigen::Index j = 0; j < N && ok; ++j) ok = column(run, z, R, j, step, central, J, why);
    if (ok && want_extra) {
      J_extra->resize(N, static_cast<Eigen::Index>(extra.size()));
      for (std::size_t e = 0; e < extra.size() && ok; ++e)
        ok = parameterColumn(run, z, R, extra[e], static_cast<Eigen::Index>(e), step, central,
                             J_extra, why);
    }
  }
  unpack(z, x_.data());
  x_T_ = x_T;
  g_ = g;
  return ok;
}

// ------------------------------------------------------------------------------------------------

namespace {

double maxAbs(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

}  // namespace

ShootingSummary solveShooting(PeriodMap& map, const std::vector<double>& x0,
                              const std::vector<double>& p0, const ShootingOptions& options) {
  std::string why;
  if (!options.IsValid(map.parameterCount(), map.conditionCount(), &why))
    throw std::invalid_argument("shooting options: " + why);
  if (static_cast<int>(x0.size()) != map.stateCount())
    throw std::invalid_argument("solveShooting: one initial value per state needed");
  ShootingSummary s;
  ShootingSystem sys(map, options.free_parameters, options.conditions, p0);
  sys.setJacobianThreads(options.jacobian_threads);
  const int n = sys.stateCount();
  Eigen::VectorXd z = sys.pack(x0.data());
  Eigen::VectorXd R, R_new, z_new, dz;
  auto finish = [&](ShootingStatus status, const std::string& message) {
    s.status = status;
    if (R.size() > 0) {
      s.residual_max = maxAbs(R);
      s.residual_norm = R.norm();
    }
    s.message = message;
    s.x.assign(static_cast<std::size_t>(n), 0.0);
    sys.unpack(z, s.x.data());
    s.p = sys.parameters();
    s.x_T = sys.lastEndState();
    s.g = sys.lastConditions();
    s.period_maps = sys.periodMaps();
    return s;
  };

  if (!map.refreshDiscretisation(x0.data(), p0.data(), &why))
    return finish(ShootingStatus::kFailed, "the period map failed at the initial guess: " + why);
  s.refreshes = 1;
  if (!sys.residual(z, &R, &why))
    return finish(ShootingStatus::kFailed, "the period map failed at the initial guess: " + why);
  Eigen::MatrixXd J;
  if (options.initial_jacobian.rows() == sys.unknownCount() &&
      options.initial_jacobian.cols() == sys.unknownCount())
    J = options.initial_jacobian;
  auto freshJacobian = [&]() {
    if (!sys.jacobian(z, R, options.fd_step, options.central_differences, &J, &why)) return false;
    ++s.jacobians;
    return true;
  };
  bool fresh = false;
  bool refreshed = options.refresh_below <= 0.0;
  bool refreshed_now = false;
  char buf[320];
  auto record = [&](int it, double step_norm, double damping) {
    ShootingIteration r;
    r.iteration = it;
    r.residual_max = maxAbs(R);
    r.residual_norm = R.norm();
    r.step_norm = step_norm;
    r.damping = damping;
    r.fresh_jacobian = fresh;
    r.refreshed = refreshed_now;
    r.period_maps = sys.periodMaps();
    s.log.push_back(r);
    refreshed_now = false;
  };
  record(0, 0.0, 1.0);

  bool converged = false;
  for (int it = 1;; ++it) {
    // Refresh the step grid once the orbit is close: the grid then belongs to the orbit found.
    if (!refreshed && maxAbs(R) < options.refresh_below) {
      std::vector<double> x(static_cast<std::size_t>(n));
      sys.unpack(z, x.data());
      if (!map.refreshDiscretisation(x.data(), sys.parameters().data(), &why) ||
          !sys.residual(z, &R, &why))
        return finish(ShootingStatus::kFailed, "the period map failed after a grid refresh: " + why);
      ++s.refreshes;
      refreshed = true;
      refreshed_now = true;
      s.log.back().refreshed = true;
      s.log.back().residual_max = maxAbs(R);
      s.log.back().residual_norm = R.norm();
    }
    if (maxAbs(R) <= options.residual_tol) {
      converged = true;
      break;
    }
    if (it > options.max_iterations) break;
    if (J.size() == 0) {
      const bool partial = !options.first_jacobian_states.empty();
      if (partial ? !sys.partialJacobian(z, R, options.fd_step, options.first_jacobian_states, &J,
                                         &why)
                  : !freshJacobian())
        return finish(ShootingStatus::kFailed, "a finite-difference run failed: " + why);
      s.partial_jacobians += partial ? 1 : 0;
      fresh = !partial;
    }
    // Newton step with backtracking on |R|; a failed search with an updated Jacobian retries with
    // a fresh one.
    bool accepted = false;
    double lambda = 1.0;
    for (int attempt = 0; attempt < 2 && !accepted; ++attempt) {
      Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
      dz = -lu.solve(R);
      if (!dz.allFinite()) {
        if (fresh || s.jacobians >= options.max_jacobians) break;
        if (!freshJacobian())
          return finish(ShootingStatus::kFailed, "a finite-difference run failed: " + why);
        fresh = true;
        continue;
      }
      lambda = 1.0;
      for (int ls = 0; ls < 8; ++ls, lambda *= 0.5) {
        z_new = z + lambda * dz;
        if (sys.residual(z_new, &R_new, &why) && R_new.norm() < (1.0 - 1e-4 * lambda) * R.norm()) {
          accepted = true;
          break;
        }
      }
      if (!accepted) {
        if (fresh || s.jacobians >= options.max_jacobians) break;
        if (!sys.residual(z, &R, &why) || !freshJacobian())
          return finish(ShootingStatus::kFailed, "a finite-difference run failed: " + why);
        fresh = true;
      }
    }
    if (!accepted) {
      std::snprintf(buf, sizeof buf,
                    "no step reduces the residual (max %.3e) along the Newton direction of a "
                    "fresh Jacobian",
                    maxAbs(R));
      s.iterations = it - 1;
      return finish(ShootingStatus::kNotConverged, buf);
    }
    const Eigen::VectorXd step = z_new - z;
    const double contraction = R_new.norm() / R.norm();
    if (options.broyden) {
      // Good Broyden: J += ((R_new - R) - J s) s^T / (s^T s).
      J.noalias() += ((R_new - R) - J * step) * (step.transpose() / step.squaredNorm());
      ++s.broyden_updates;
    }
    z = z_new;
    R = R_new;
    s.iterations = it;
    record(it, step.norm(), lambda);
    fresh = false;
    if (contraction > options.slow_contraction && maxAbs(R) > options.residual_tol &&
        s.jacobians < options.max_jacobians) {
      if (!freshJacobian())
        return finish(ShootingStatus::kFailed, "a finite-difference run failed: " + why);
      fresh = true;
    }
  }
  if (!converged) {
    std::snprintf(buf, sizeof buf, "iteration limit (%d) reached; periodic residual %.3e > %.1e",
                  options.max_iterations, maxAbs(R), options.residual_tol);
    return finish(ShootingStatus::kNotConverged, buf);
  }

  // The Jacobian at the solution (its state block + I is the monodromy matrix); one more Newton
  // step with it polishes the orbit when that lowers the residual.
  if (options.jacobian_at_solution) {
    if (!freshJacobian())
      return finish(ShootingStatus::kFailed, "a finite-difference run at the solution failed: " +
                                                 why);
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
    dz = -lu.solve(R);
    if (dz.allFinite()) {
      z_new = z + dz;
      if (sys.residual(z_new, &R_new, &why) && maxAbs(R_new) < maxAbs(R)) {
        z = z_new;
        R = R_new;
      } else if (!sys.residual(z, &R, &why)) {
        return finish(ShootingStatus::kFailed, "the period map failed at the solution: " + why);
      }
    }
    s.jacobian_valid = true;
    s.monodromy = J.topLeftCorner(n, n) + Eigen::MatrixXd::Identity(n, n);
  }
  s.jacobian = J;
  std::snprintf(buf, sizeof buf, "periodic orbit found: residual %.3e <= %.1e (scaled, max norm)",
                maxAbs(R), options.residual_tol);
  return finish(ShootingStatus::kConverged, buf);
}

}  // namespace orni
