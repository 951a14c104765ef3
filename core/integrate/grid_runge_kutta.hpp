// Runge-Kutta integration on a recorded step grid, for flow maps whose derivatives are taken by
// finite differences (internal numerical differentiation, Bock 1981).
//
// The flow of an adaptive integrator is a noisy function of the initial state: its step sequence
// changes from one run to the next, and a finite difference of two such runs mixes the derivative
// with the change of the discretisation. Here a grid is chosen once, adaptively, by
// integrateAdaptive(); integrateOnGrid() then takes exactly those steps (as fractions of the
// interval) from any initial state, so its result is a smooth function of the initial state, the
// interval and the right-hand side's parameters, and finite differences of it are clean to
// rounding. The periodic-orbit solver (core/analysis/periodic_shooting.hpp) evaluates every period
// map this way.
//
// Methods (the tables are SUNDIALS ARKODE's, loaded at run time):
//   explicit  y' = f(t, y): Dormand-Prince 5(4) (the rigid wing's method in free flight);
//   IMEX      y' = f_E(t, y) + L y, L linear and constant (the flexible wing's modal stiffness,
//             core/dynamics/modal_implicit_split.hpp): Kennedy-Carpenter ARK4(3)7L[2]SA, the
//             implicit stages solved exactly by the LinearImplicitPart's (I - gamma L)^{-1}.
// Error control of integrateAdaptive (weighted RMS norm with rel_tol and per-state abs_tol, as
// ARKODE) decides the grid only. No allocation after construction; no exception crosses it (the
// right-hand side's exceptions propagate to the caller).
#pragma once

#include <string>
#include <vector>

#include "core/integrate/integrator_options.hpp"

namespace orni {

/// Step control of integrateAdaptive (chooses the grid; docs/design.md 7.5).
struct GridStepControl {
  double rel_tol = 1e-6;          ///< (0, 1e-2]
  std::vector<double> abs_tol;    ///< one per state, > 0
  double max_step_fraction = 0.125;  ///< largest step as a fraction of the interval, (0, 1]
  long max_steps = 100000;        ///< per interval, >= 1

  bool IsValid(int state_size, std::string* why) const;
};

/// Called at every grid node (t, y) including the first and the last (integrateOnGrid only).
using GridObserver = void (*)(int node, double t_s, const double* y, void* user_data);

class GridRungeKutta {
 public:
  /// Explicit: y' = rhs(t, y), Dormand-Prince 5(4).
  GridRungeKutta(int state_size, RhsFunction rhs, void* user_data);
  /// IMEX: y' = explicit_rhs(t, y) + L y, ARK4(3)7L[2]SA.
  GridRungeKutta(int state_size, RhsFunction explicit_rhs, LinearImplicitPart implicit,
                 void* user_data);

  /// Integrate from (t0, y0) to t1 with step control; the accepted steps go to *grid as node
  /// fractions tau_0 = 0 < tau_1 < ... < tau_N = 1 of [t0, t1]. y1 receives y(t1). False on
  /// failure (lastError() says why; a step that the right-hand side rejects or makes non-finite is
  /// retried smaller, down to 1e-12 of the interval).
  bool integrateAdaptive(double t0_s, double t1_s, const double* y0, const GridStepControl& control,
                         std::vector<double>* grid, double* y1);
  /// The same steps (node fractions `grid`, from integrateAdaptive or merged with output nodes)
  /// from (t0, y0) to t1: y1 = y(t1). False when the right-hand side fails or a state becomes
  /// non-finite. `observer` (may be null) sees every node.
  bool integrateOnGrid(double t0_s, double t1_s, const std::vector<double>& grid, const double* y0,
                       double* y1, GridObserver observer = nullptr, void* observer_data = nullptr);

  bool imex() const { return implicit_.apply != nullptr; }
  long rhsEvaluations() const { return rhs_evaluations_; }  ///< explicit-part evaluations so far
  const std::string& lastError() const { return last_error_; }
  /// "Dormand-Prince 5(4)" or "ARK4(3)7L[2]SA IMEX" and the grid mode, for summaries.
  std::string methodName() const;

 private:
  struct Table {
    int stages = 0, order = 0, embedded_order = 0;
    std::vector<double> AE, AI, b, d, c;  // A row-major stages x stages
    bool fsal = false;  // last stage = the step's result (first stage of the next step reusable)
  };
  void loadTables();
  // One step of size h from (t, y_) into y_new_ (and the embedded solution's error in err_ when
  // `with_error`). `first_stage_known`: Fe_[0], Fi_[0] already hold f at (t, y_). False when the
  // right-hand side fails (rhs_code_ says how).
  bool step(double t, double h, bool first_stage_known, bool with_error);
  double errorNorm(const GridStepControl& control) const;
  // After an accepted step with a first-same-as-last table: the last stage's derivatives become
  // the first stage's of the next step. Returns whether they did (tab_.fsal).
  bool carryLastStage();

  int n_;
  RhsFunction fe_;
  LinearImplicitPart implicit_;
  void* user_;
  Table tab_;
  std::vector<double> y_, y_new_, err_, z_, rhs_;  // n each
  std::vector<double> Fe_, Fi_;                    // stages x n
  long rhs_evaluations_ = 0;
  int rhs_code_ = 0;
  std::string last_error_;
};

}  // namespace orni
