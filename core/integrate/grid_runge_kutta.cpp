#include "core/integrate/grid_runge_kutta.hpp"

#include <arkode/arkode_butcher.h>
#include <arkode/arkode_butcher_dirk.h>
#include <arkode/arkode_butcher_erk.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace orni {

bool GridStepControl::IsValid(int state_size, std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(rel_tol > 0.0 && rel_tol <= 1e-2)) return fail("rel_tol must be in (0, 1e-2]");
  if (static_cast<int>(abs_tol.size()) != state_size)
    return fail("abs_tol must have one entry per state");
  for (double a : abs_tol)
    if (!(a > 0.0)) return fail("abs_tol entries must be > 0");
  if (!(max_step_fraction > 0.0 && max_step_fraction <= 1.0))
    return fail("max_step_fraction must be in (0, 1]");
  if (max_steps < 1) return fail("max_steps must be >= 1");
  return true;
}

namespace {

// Copy an ARKODE Butcher table (A row-major) and free it.
void copyTable(ARKodeButcherTable t, std::vector<double>* A, std::vector<double>* b,
               std::vector<double>* d, std::vector<double>* c, int* stages, int* q, int* p) {
  if (!t) throw std::runtime_error("GridRungeKutta: ARKODE Butcher table not available");
  const int s = t->stages;
  *stages = s;
  *q = t->q;
  *p = t->p;
  A->assign(static_cast<std::size_t>(s * s), 0.0);
  b->assign(static_cast<std::size_t>(s), 0.0);
  d->assign(static_cast<std::size_t>(s), 0.0);
  c->assign(static_cast<std::size_t>(s), 0.0);
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < s; ++j) (*A)[static_cast<std::size_t>(i * s + j)] = t->A[i][j];
    (*b)[static_cast<std::size_t>(i)] = t->b[i];
    (*d)[static_cast<std::size_t>(i)] = t->d ? t->d[i] : t->b[i];
    (*c)[static_cast<std::size_t>(i)] = t->c[i];
  }
  ARKodeButcherTable_Free(t);
}

}  // namespace

GridRungeKutta::GridRungeKutta(int state_size, RhsFunction rhs, void* user_data)
    : n_(state_size), fe_(rhs), user_(user_data) {
  if (state_size < 1 || !rhs) throw std::invalid_argument("GridRungeKutta: state size and rhs");
  loadTables();
}

GridRungeKutta::GridRungeKutta(int state_size, RhsFunction explicit_rhs,
                               LinearImplicitPart implicit, void* user_data)
    : n_(state_size), fe_(explicit_rhs), implicit_(implicit), user_(user_data) {
  if (state_size < 1 || !explicit_rhs || !implicit.apply || !implicit.solve)
    throw std::invalid_argument("GridRungeKutta: state size, explicit rhs and implicit part");
  loadTables();
}

void GridRungeKutta::loadTables() {
  std::vector<double> b2, d2, c2;
  int s2 = 0, q2 = 0, p2 = 0;
  if (imex()) {
    copyTable(ARKodeButcherTable_LoadERK(ARKODE_ARK437L2SA_ERK_7_3_4), &tab_.AE, &tab_.b, &tab_.d,
              &tab_.c, &tab_.stages, &tab_.order, &tab_.embedded_order);
    copyTable(ARKodeButcherTable_LoadDIRK(ARKODE_ARK437L2SA_DIRK_7_3_4), &tab_.AI, &b2, &d2, &c2,
              &s2, &q2, &p2);
    if (s2 != tab_.stages) throw std::runtime_error("GridRungeKutta: ARK tables differ in size");
  } else {
    copyTable(ARKodeButcherTable_LoadERK(ARKODE_DORMAND_PRINCE_7_4_5), &tab_.AE, &tab_.b, &tab_.d,
              &tab_.c, &tab_.stages, &tab_.order, &tab_.embedded_order);
    tab_.AI.assign(tab_.AE.size(), 0.0);
  }
  // First same as last: the last stage is evaluated at t + h on the step's result.
  const int s = tab_.stages;
  bool fsal = std::abs(tab_.c[static_cast<std::size_t>(s - 1)] - 1.0) < 1e-14;
  for (int j = 0; j < s && fsal; ++j) {
    const double bj = tab_.b[static_cast<std::size_t>(j)];
    const auto k = static_cast<std::size_t>((s - 1) * s + j);
    fsal = std::abs(tab_.AE[k] - (j < s - 1 ? bj : 0.0)) < 1e-14 &&
           (!imex() || std::abs(tab_.AI[k] - bj) < 1e-14);
  }
  tab_.fsal = fsal;
  const auto n = static_cast<std::size_t>(n_);
  y_.assign(n, 0.0);
  y_new_.assign(n, 0.0);
  err_.assign(n, 0.0);
  z_.assign(n, 0.0);
  rhs_.assign(n, 0.0);
  Fe_.assign(n * static_cast<std::size_t>(s), 0.0);
  Fi_.assign(n * static_cast<std::size_t>(s), 0.0);
}

std::string GridRungeKutta::methodName() const {
  return imex() ? "ARK4(3)7L[2]SA IMEX (modal stiffness implicit) on a recorded step grid"
                : "Dormand-Prince 5(4) on a recorded step grid";
}

bool GridRungeKutta::step(double t, double h, bool first_stage_known, bool with_error) {
  const int s = tab_.stages;
  const std::size_t n = static_cast<std::size_t>(n_);
  // A new starting state: the implicit part re-linearises about it (its stage values are then
  // all of this step; carryLastStage() does not carry them over).
  if (implicit_.update && !first_stage_known) {
    rhs_code_ = implicit_.update(t, y_.data(), user_);
    if (rhs_code_ != 0) return false;
  }
  for (int i = 0; i < s; ++i) {
    double* Fe_i = &Fe_[static_cast<std::size_t>(i) * n];
    double* Fi_i = &Fi_[static_cast<std::size_t>(i) * n];
    if (i == 0 && first_stage_known) continue;
    for (std::size_t k = 0; k < n; ++k) rhs_[k] = y_[k];
    for (int j = 0; j < i; ++j) {
      const double ae = h * tab_.AE[static_cast<std::size_t>(i * s + j)];
      const double ai = h * tab_.AI[static_cast<std::size_t>(i * s + j)];
      const double* Fe_j = &Fe_[static_cast<std::size_t>(j) * n];
      const double* Fi_j = &Fi_[static_cast<std::size_t>(j) * n];
      if (ae != 0.0)
        for (std::size_t k = 0; k < n; ++k) rhs_[k] += ae * Fe_j[k];
      if (ai != 0.0)
        for (std::size_t k = 0; k < n; ++k) rhs_[k] += ai * Fi_j[k];
    }
    const double ti = t + tab_.c[static_cast<std::size_t>(i)] * h;
    const double* z = rhs_.data();
    if (imex()) {
      const double gamma = h * tab_.AI[static_cast<std::size_t>(i * s + i)];
      if (gamma != 0.0) {
        rhs_code_ = implicit_.solve(gamma, rhs_.data(), z_.data(), user_);
        if (rhs_code_ != 0) return false;
        const double inv = 1.0 / gamma;  // the stage's L z, deduced from the exact solve
        for (std::size_t k = 0; k < n; ++k) Fi_i[k] = (z_[k] - rhs_[k]) * inv;
        z = z_.data();
      } else {
        rhs_code_ = implicit_.apply(ti, rhs_.data(), Fi_i, user_);
        if (rhs_code_ != 0) return false;
      }
    }
    rhs_code_ = fe_(ti, z, Fe_i, user_);
    ++rhs_evaluations_;
    if (rhs_code_ != 0) return false;
    for (std::size_t k = 0; k < n; ++k)
      if (!std::isfinite(Fe_i[k])) {
        rhs_code_ = 1;  // recoverable: a smaller step may stay finite
        return false;
      }
  }
  for (std::size_t k = 0; k < n; ++k) y_new_[k] = y_[k];
  if (with_error) std::fill(err_.begin(), err_.end(), 0.0);
  for (int i = 0; i < s; ++i) {
    const double bi = h * tab_.b[static_cast<std::size_t>(i)];
    const double ei = h * (tab_.b[static_cast<std::size_t>(i)] - tab_.d[static_cast<std::size_t>(i)]);
    const double* Fe_i = &Fe_[static_cast<std::size_t>(i) * n];
    const double* Fi_i = &Fi_[static_cast<std::size_t>(i) * n];
    for (std::size_t k = 0; k < n; ++k) {
      const double f = imex() ? Fe_i[k] + Fi_i[k] : Fe_i[k];
      y_new_[k] += bi * f;
      if (with_error) err_[k] += ei * f;
    }
  }
  return true;
}

double GridRungeKutta::errorNorm(const GridStepControl& control) const {
  double sum = 0.0;
  for (int k = 0; k < n_; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double w = control.rel_tol * std::abs(y_[i]) + control.abs_tol[i];
    const double e = err_[i] / w;
    sum += e * e;
  }
  return std::sqrt(sum / n_);
}

bool GridRungeKutta::carryLastStage() {
  if (!tab_.fsal || implicit_.update) return false;
  const std::size_t n = static_cast<std::size_t>(n_);
  const std::size_t s1 = static_cast<std::size_t>(tab_.stages - 1) * n;
  std::copy(Fe_.begin() + static_cast<std::ptrdiff_t>(s1),
            Fe_.begin() + static_cast<std::ptrdiff_t>(s1 + n), Fe_.begin());
  std::copy(Fi_.begin() + static_cast<std::ptrdiff_t>(s1),
            Fi_.begin() + static_cast<std::ptrdiff_t>(s1 + n), Fi_.begin());
  return true;
}

bool GridRungeKutta::integrateAdaptive(double t0_s, double t1_s, const double* y0,
                                       const GridStepControl& control, std::vector<double>* grid,
                                       double* y1) {
  std::string why;
  if (!control.IsValid(n_, &why)) throw std::invalid_argument("GridRungeKutta: " + why);
  if (!(t1_s > t0_s)) throw std::invalid_argument("GridRungeKutta: t1 must be after t0");
  const double span = t1_s - t0_s;
  const double h_max = control.max_step_fraction * span;
  const double h_min = 1e-12 * span;
  const double expo = -1.0 / (tab_.embedded_order + 1.0);
  std::copy(y0, y0 + n_, y_.begin());
  grid->clear();
  grid->push_back(0.0);
  double t = t0_s, h = std::min(h_max, 1e-2 * span);
  bool first_known = false, rejected = false;
  long steps = 0;
  char buf[200];
  while (t < t1_s) {
    if (++steps > control.max_steps) {
      std::snprintf(buf, sizeof buf, "more than %ld steps at t = %.6g s", control.max_steps, t);
      last_error_ = buf;
      return false;
    }
    const double left = t1_s - t;
    double h_try = std::min(h, left);
    const bool last = left - h_try < 0.1 * h_try;
    if (last) h_try = left;
    if (!step(t, h_try, first_known, true)) {
      first_known = false;
      if (rhs_code_ < 0 || h_try < h_min) {
        std::snprintf(buf, sizeof buf, "the right-hand side failed (code %d) at t = %.6g s",
                      rhs_code_, t);
        last_error_ = buf;
        return false;
      }
      h = 0.25 * h_try;
      rejected = true;
      continue;
    }
    const double err = errorNorm(control);
    if (!(err <= 1.0)) {
      if (h_try < h_min) {
        std::snprintf(buf, sizeof buf, "step size below %.3g s at t = %.6g s", h_min, t);
        last_error_ = buf;
        return false;
      }
      h = std::isfinite(err) ? h_try * std::max(0.2, 0.9 * std::pow(err, expo)) : 0.25 * h_try;
      rejected = true;
      first_known = true;  // stage 1 at (t, y) was evaluated and is still valid
      continue;
    }
    t = last ? t1_s : t + h_try;
    std::copy(y_new_.begin(), y_new_.end(), y_.begin());
    grid->push_back(last ? 1.0 : (t - t0_s) / span);
    first_known = carryLastStage();
    double factor = err > 0.0 ? 0.9 * std::pow(err, expo) : 5.0;
    factor = std::min(rejected ? 1.0 : 5.0, std::max(0.2, factor));
    h = std::min(h_max, h_try * factor);
    rejected = false;
  }
  std::copy(y_.begin(), y_.end(), y1);
  return true;
}

bool GridRungeKutta::integrateOnGrid(double t0_s, double t1_s, const std::vector<double>& grid,
                                     const double* y0, double* y1, GridObserver observer,
                                     void* observer_data) {
  if (grid.size() < 2 || grid.front() != 0.0 || grid.back() != 1.0)
    throw std::invalid_argument("GridRungeKutta: a grid runs from 0 to 1 with at least one step");
  const double span = t1_s - t0_s;
  std::copy(y0, y0 + n_, y_.begin());
  if (observer) observer(0, t0_s, y_.data(), observer_data);
  bool first_known = false;
  const std::size_t nodes = grid.size();
  double t = t0_s;
  char buf[160];
  for (std::size_t k = 1; k < nodes; ++k) {
    const double t_next = k + 1 == nodes ? t1_s : t0_s + grid[k] * span;
    if (!step(t, t_next - t, first_known, false)) {
      std::snprintf(buf, sizeof buf, "the right-hand side failed (code %d) at t = %.6g s",
                    rhs_code_, t);
      last_error_ = buf;
      return false;
    }
    for (int i = 0; i < n_; ++i)
      if (!std::isfinite(y_new_[static_cast<std::size_t>(i)])) {
        std::snprintf(buf, sizeof buf, "non-finite state at t = %.6g s", t_next);
        last_error_ = buf;
        return false;
      }
    std::copy(y_new_.begin(), y_new_.end(), y_.begin());
    t = t_next;
    first_known = carryLastStage();
    if (observer) observer(static_cast<int>(k), t, y_.data(), observer_data);
  }
  std::copy(y_.begin(), y_.end(), y1);
  return true;
}

}  // namespace orni
