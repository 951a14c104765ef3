// The periodic-orbit solver and the Floquet analysis (core/analysis/periodic_shooting.hpp,
// floquet.hpp) on the recorded-grid integrator (core/integrate/grid_runge_kutta.hpp), the same
// code the vehicle's periodic trim runs, against independent truths:
//   - a forced, damped linear oscillator: the periodic (particular) solution and the multipliers
//     exp(lambda T) of its eigenvalues, analytic; once fully explicit (Dormand-Prince) and once
//     with the stiffness and damping in the implicit part (IMEX ARK4(3)7L[2]SA, a 300 Hz mode
//     forced at 12 Hz like the magpie's highest wing mode), and once with a free parameter and an
//     ignorable state's gain as condition (the level-flight structure of the vehicle's trim);
//   - the damped, forced Mathieu equation: orbit and multipliers against a fixed-step RK4
//     fundamental matrix computed here (20000 steps per period), and det M = exp(-2 zeta T)
//     (Liouville), in a stable and an unstable (parametric resonance) case.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "core/analysis/floquet.hpp"
#include "core/analysis/periodic_shooting.hpp"
#include "core/integrate/grid_runge_kutta.hpp"

namespace orni {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTruthTol = 1e-6;  // the tolerance on orbits and multipliers

// A PeriodMap over a GridRungeKutta of a system with `n` periodic states and `extra` trailing
// ignorable states whose gains are the conditions.
class GridMap : public PeriodMap {
 public:
  GridMap(int n, int extra, int params, double period, GridRungeKutta* rk, double rel_tol,
          double max_step_fraction = 0.125)
      : n_(n), extra_(extra), params_(params), period_(period), rk_(rk) {
    control_.rel_tol = rel_tol;
    control_.max_step_fraction = max_step_fraction;
    control_.abs_tol.assign(static_cast<std::size_t>(n + extra), rel_tol * 1e-2);
    y0_.resize(static_cast<std::size_t>(n + extra));
    y1_.resize(static_cast<std::size_t>(n + extra));
  }
  int stateCount() const override { return n_; }
  int parameterCount() const override { return params_; }
  int conditionCount() const override { return extra_; }
  double stateScale(int) const override { return 1.0; }
  double parameterScale(int) const override { return 1.0; }
  double conditionScale(int) const override { return 1.0; }
  double period_s(const double*) const override { return period_; }
  double* p = nullptr;  // the system reads its parameters here
  bool flow(const double* x, const double* pp, double* x_T, double* g, std::string* why) override {
    set(x, pp);
    if (!rk_->integrateOnGrid(0.0, period_, grid_, y0_.data(), y1_.data())) {
      *why = rk_->lastError();
      return false;
    }
    for (int i = 0; i < n_; ++i) x_T[i] = y1_[static_cast<std::size_t>(i)];
    for (int k = 0; k < extra_; ++k) g[k] = y1_[static_cast<std::size_t>(n_ + k)];
    return true;
  }
  bool refreshDiscretisation(const double* x, const double* pp, std::string* why) override {
    set(x, pp);
    ++refreshes;
    if (rk_->integrateAdaptive(0.0, period_, y0_.data(), control_, &grid_, y1_.data())) return true;
    *why = rk_->lastError();
    return false;
  }
  int refreshes = 0;
  std::size_t gridSteps() const { return grid_.size() - 1; }

 private:
  void set(const double* x, const double* pp) {
    for (int i = 0; i < n_; ++i) y0_[static_cast<std::size_t>(i)] = x[i];
    for (int k = 0; k < extra_; ++k) y0_[static_cast<std::size_t>(n_ + k)] = 0.0;
    for (int j = 0; j < params_; ++j) p[j] = pp[j];
  }
  int n_, extra_, params_;
  double period_;
  GridRungeKutta* rk_;
  GridStepControl control_;
  std::vector<double> grid_, y0_, y1_;
};

std::vector<FloquetStateInfo> plainStates(int n) {
  std::vector<FloquetStateInfo> s;
  for (int i = 0; i < n; ++i) s.push_back({"x" + std::to_string(i), FloquetStateKind::kOther, 0});
  return s;
}

// ------------------------------------------------------------------------------------------------
// Forced damped oscillator x'' + 2 zeta w x' + w^2 x = F0 + F cos(W t), state (x, v[, y]) with the
// ignorable y' = x. Parameter p[0] = F0.
struct Oscillator {
  double w, zeta, W, F;
  double p[1] = {0.0};
  bool imex = false;  // stiffness and damping in the implicit part
  int n = 2;          // 3 with the ignorable y
  double period() const { return 2.0 * kPi / W; }
  // Particular solution of the cos forcing: x = X cos(W t - phase) (+ F0 / w^2).
  double X() const {
    const double a = w * w - W * W, b = 2.0 * zeta * w * W;
    return F / std::sqrt(a * a + b * b);
  }
  double phase() const { return std::atan2(2.0 * zeta * w * W, w * w - W * W); }
  std::complex<double> lambda() const {
    return {-zeta * w, w * std::sqrt(1.0 - zeta * zeta)};
  }
};

int oscillatorFull(double t, const double* y, double* dy, void* u) {
  auto* o = static_cast<Oscillator*>(u);
  const double force = o->p[0] + o->F * std::cos(o->W * t);
  dy[0] = o->imex ? 0.0 : y[1];  // IMEX: x' = v is in the implicit part
  dy[1] = force - (o->imex ? 0.0 : 2.0 * o->zeta * o->w * y[1] + o->w * o->w * y[0]);
  if (o->n == 3) dy[2] = y[0];
  return 0;
}
int oscillatorImplicit(double, const double* y, double* dy, void* u) {
  auto* o = static_cast<Oscillator*>(u);
  dy[0] = y[1];
  dy[1] = -2.0 * o->zeta * o->w * y[1] - o->w * o->w * y[0];
  if (o->n == 3) dy[2] = 0.0;
  return 0;
}
// (I - gamma L) x = b: x0 - gamma x1 = b0, x1 + gamma (k x0 + c x1) = b1.
int oscillatorSolve(double gamma, const double* b, double* x, void* u) {
  auto* o = static_cast<Oscillator*>(u);
  const double k = o->w * o->w, c = 2.0 * o->zeta * o->w;
  x[1] = (b[1] - gamma * k * b[0]) / (1.0 + gamma * c + gamma * gamma * k);
  x[0] = b[0] + gamma * x[1];
  if (o->n == 3) x[2] = b[2];
  return 0;
}

void checkOscillatorOrbit(Oscillator& o, double rel_tol, bool with_condition,
                          double max_step_fraction = 0.125) {
  o.n = with_condition ? 3 : 2;
  GridRungeKutta rk = o.imex ? GridRungeKutta(o.n, &oscillatorFull,
                                              LinearImplicitPart{&oscillatorImplicit,
                                                                 &oscillatorSolve},
                                              &o)
                             : GridRungeKutta(o.n, &oscillatorFull, &o);
  GridMap map(2, with_condition ? 1 : 0, 1, o.period(), &rk, rel_tol, max_step_fraction);
  map.p = o.p;
  ShootingOptions opt;
  if (with_condition) {
    opt.free_parameters = {0};
    opt.conditions = {0};
  }
  const std::vector<double> x0 = {0.3, -0.2};
  const std::vector<double> p0 = {with_condition ? 0.5 * o.w * o.w * o.X() : 0.0};
  const ShootingSummary s = solveShooting(map, x0, p0, opt);
  ASSERT_EQ(s.status, ShootingStatus::kConverged) << s.message;
  EXPECT_LE(s.residual_max, opt.residual_tol);
  // The particular solution at t = 0, and F0 = 0 for zero mean displacement.
  const double X = o.X(), ph = o.phase();
  EXPECT_NEAR(s.x[0], X * std::cos(ph), kTruthTol * X);
  EXPECT_NEAR(s.x[1], X * o.W * std::sin(ph), kTruthTol * X * o.W);
  if (with_condition) {
    EXPECT_NEAR(s.p[0], 0.0, kTruthTol * o.w * o.w * X);
  }
  // Multipliers exp(lambda T), the conjugate pair.
  ASSERT_TRUE(s.jacobian_valid);
  const FloquetAnalysis f = analyseFloquet(s.monodromy, o.period(), plainStates(2));
  ASSERT_EQ(f.multipliers.size(), 2u);
  const std::complex<double> mu = std::exp(o.lambda() * o.period());
  const std::complex<double> mu_up = mu.imag() >= 0.0 ? mu : std::conj(mu);
  EXPECT_NEAR(std::abs(f.multipliers[0].mu - mu_up), 0.0, kTruthTol) << f.multipliers[0].mu;
  EXPECT_NEAR(std::abs(f.multipliers[1].mu - std::conj(mu_up)), 0.0, kTruthTol);
  EXPECT_TRUE(f.stable);
  EXPECT_NEAR(f.max_modulus, std::exp(-o.zeta * o.w * o.period()), kTruthTol);
  // The continuous eigenvalue's real part and the damping ratio of a pair.
  EXPECT_NEAR(f.multipliers[0].exponent_per_s.real(), -o.zeta * o.w, 1e-5 * o.w);
}

TEST(AnalysisPeriodicShooting, ForcedDampedOscillatorExplicit) {
  Oscillator o{2.0 * kPi * 3.0, 0.1, 2.0 * kPi * 1.0, 1.0};
  checkOscillatorOrbit(o, 1e-10, false);
}

// The grid is chosen on the orbit, where the 300 Hz mode only follows the 12 Hz forcing; its free
// motion (25 cycles per period) is resolved only when the step is limited: 1/2000 of the period,
// 80 steps per 300 Hz cycle (with the default T/8 the multiplier is off by 8e-5: floquet.hpp).
TEST(AnalysisPeriodicShooting, ForcedDampedOscillatorImexStiff) {
  Oscillator o{2.0 * kPi * 300.0, 0.015, 2.0 * kPi * 12.0, 1.0};
  o.imex = true;
  checkOscillatorOrbit(o, 1e-9, false, 1.0 / 2000.0);
}

TEST(AnalysisPeriodicShooting, FreeParameterAndIgnorableStateCondition) {
  // F0 (started away from 0) must make the mean displacement zero: the gain of y' = x vanishes.
  Oscillator o{2.0 * kPi * 3.0, 0.1, 2.0 * kPi * 1.0, 1.0};
  checkOscillatorOrbit(o, 1e-10, true);
}

// ------------------------------------------------------------------------------------------------
// Damped, forced Mathieu equation x'' + 2 zeta x' + (a - 2 q cos 2t) x = F cos 2t, period pi.
struct Mathieu {
  double a, q, zeta, F;
  double p[1] = {0.0};
};

int mathieuRhs(double t, const double* y, double* dy, void* u) {
  auto* m = static_cast<Mathieu*>(u);
  dy[0] = y[1];
  dy[1] = -2.0 * m->zeta * y[1] - (m->a - 2.0 * m->q * std::cos(2.0 * t)) * y[0] +
          m->F * std::cos(2.0 * t);
  return 0;
}

// Independent reference: classical RK4 with `steps` fixed steps over one period of the fundamental
// matrix (columns from e1, e2 without forcing) and of the forced response from rest.
void mathieuReference(const Mathieu& m, int steps, Eigen::Matrix2d* M, Eigen::Vector2d* forced) {
  auto f = [&](double t, const Eigen::Vector2d& y, bool forcing) {
    return Eigen::Vector2d(y[1], -2.0 * m.zeta * y[1] - (m.a - 2.0 * m.q * std::cos(2.0 * t)) * y[0] +
                                     (forcing ? m.F * std::cos(2.0 * t) : 0.0));
  };
  auto integrate = [&](Eigen::Vector2d y, bool forcing) {
    const double h = kPi / steps;
    for (int i = 0; i < steps; ++i) {
      const double t = i * h;
      const Eigen::Vector2d k1 = f(t, y, forcing);
      const Eigen::Vector2d k2 = f(t + 0.5 * h, y + 0.5 * h * k1, forcing);
      const Eigen::Vector2d k3 = f(t + 0.5 * h, y + 0.5 * h * k2, forcing);
      const Eigen::Vector2d k4 = f(t + h, y + h * k3, forcing);
      y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    return y;
  };
  M->col(0) = integrate(Eigen::Vector2d(1.0, 0.0), false);
  M->col(1) = integrate(Eigen::Vector2d(0.0, 1.0), false);
  *forced = integrate(Eigen::Vector2d::Zero(), true);
}

void checkMathieu(Mathieu m, bool expect_stable) {
  GridRungeKutta rk(2, &mathieuRhs, &m);
  GridMap map(2, 0, 1, kPi, &rk, 1e-11);
  map.p = m.p;
  const ShootingSummary s = solveShooting(map, {0.5, 0.5}, {0.0}, ShootingOptions{});
  ASSERT_EQ(s.status, ShootingStatus::kConverged) << s.message;
  ASSERT_TRUE(s.jacobian_valid);

  Eigen::Matrix2d M;
  Eigen::Vector2d forced;
  mathieuReference(m, 20000, &M, &forced);
  // The orbit: x* = M x* + forced.
  const Eigen::Vector2d x_ref = (Eigen::Matrix2d::Identity() - M).lu().solve(forced);
  EXPECT_NEAR(s.x[0], x_ref[0], kTruthTol * (1.0 + x_ref.norm()));
  EXPECT_NEAR(s.x[1], x_ref[1], kTruthTol * (1.0 + x_ref.norm()));

  const FloquetAnalysis f = analyseFloquet(s.monodromy, kPi, plainStates(2));
  Eigen::EigenSolver<Eigen::Matrix2d> es(M);
  std::vector<std::complex<double>> ref = {es.eigenvalues()[0], es.eigenvalues()[1]};
  for (const FloquetMultiplier& mu : f.multipliers) {
    double best = 1e300;
    for (const std::complex<double>& r : ref) best = std::min(best, std::abs(mu.mu - r));
    EXPECT_LT(best, kTruthTol) << "multiplier " << mu.mu;
  }
  // Liouville: det M = exp(-2 zeta T).
  const std::complex<double> det = f.multipliers[0].mu * f.multipliers[1].mu;
  EXPECT_NEAR(det.real(), std::exp(-2.0 * m.zeta * kPi), kTruthTol);
  EXPECT_NEAR(det.imag(), 0.0, kTruthTol);
  EXPECT_EQ(f.stable, expect_stable);
  EXPECT_NEAR(f.margin, 1.0 - f.max_modulus, 0.0);
}

TEST(AnalysisPeriodicShooting, DampedMathieuStable) {
  // Between the first two tongues: an oscillatory pair of modulus exp(-zeta pi).
  checkMathieu({2.5, 0.5, 0.05, 0.3}, true);
}

TEST(AnalysisPeriodicShooting, DampedMathieuParametricResonance) {
  // Inside the first tongue (a ~ 1): real multipliers, one outside the unit circle.
  checkMathieu({1.0, 0.4, 0.02, 0.3}, false);
}

TEST(AnalysisPeriodicShooting, RecordedGridReproducesTheAdaptiveRun) {
  Mathieu m{2.5, 0.5, 0.05, 0.3};
  GridRungeKutta rk(2, &mathieuRhs, &m);
  GridStepControl c;
  c.rel_tol = 1e-8;
  c.abs_tol = {1e-10, 1e-10};
  std::vector<double> grid;
  const double y0[2] = {0.2, -0.1};
  double ya[2], yb[2];
  ASSERT_TRUE(rk.integrateAdaptive(0.0, kPi, y0, c, &grid, ya));
  ASSERT_GT(grid.size(), 10u);
  ASSERT_TRUE(rk.integrateOnGrid(0.0, kPi, grid, y0, yb));
  EXPECT_NEAR(ya[0], yb[0], 1e-13);
  EXPECT_NEAR(ya[1], yb[1], 1e-13);
}

}  // namespace
}  // namespace orni
