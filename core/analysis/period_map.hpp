// The period map of a T-periodically forced system, the object the periodic-orbit solver
// (periodic_shooting.hpp) and the Floquet analysis (floquet.hpp) work on.
//
// x (n states) at phase 0 is carried over one forcing period T(p) to Phi(x, p); the map also
// returns scalar conditions g(x, p) of the same run (e.g. the altitude gained over the period) that
// a solve may drive to zero by freeing as many parameters p (e.g. the tail angle). States that the
// system does not depend on (a flight vehicle's position and altitude) are not part of x: their
// gains over the period are conditions. Every quantity has a scale: the solver works in x / scale,
// the Floquet eigenvectors are reported in those units.
//
// A map may have a discretisation (an adaptive integrator's step grid) that it keeps fixed between
// refreshDiscretisation() calls, so that flow() is a smooth function of (x, p) and finite
// differences of it are clean (grid_runge_kutta.hpp).
#pragma once

#include <memory>
#include <string>

namespace orni {

class PeriodMap {
 public:
  virtual ~PeriodMap() = default;

  virtual int stateCount() const = 0;      ///< n >= 1
  virtual int parameterCount() const = 0;  ///< P >= 0
  virtual int conditionCount() const = 0;  ///< C >= 0

  /// Typical size of state i, of parameter j and of condition k (> 0): the units of the scaled
  /// residual and of the finite-difference steps.
  virtual double stateScale(int i) const = 0;
  virtual double parameterScale(int j) const = 0;
  virtual double conditionScale(int k) const = 0;

  /// The forcing period T (s) at parameters p (P values).
  virtual double period_s(const double* p) const = 0;

  /// One period from x (n values) at parameters p: the end state into x_T (n) and the conditions
  /// into g (C; may be null when C = 0). False when the integration fails, with the reason in
  /// *why. Uses the current discretisation.
  virtual bool flow(const double* x, const double* p, double* x_T, double* g,
                    std::string* why) = 0;

  /// Choose a new discretisation along the trajectory from (x, p); the default has none. False
  /// with the reason when the integration fails.
  virtual bool refreshDiscretisation(const double* /*x*/, const double* /*p*/,
                                     std::string* /*why*/) {
    return true;
  }

  /// An independent copy with the same discretisation (step grid) and settings, so that flow()
  /// of the copy gives the bits flow() of this map gives; used to difference the map on several
  /// threads (ShootingOptions::jacobian_threads). Null (the default) when the map cannot be
  /// copied: the differences then run on this map, one after the other.
  virtual std::unique_ptr<PeriodMap> clone() const { return nullptr; }
  /// Add the work counters of a clone that has run flows (after a parallel Jacobian).
  virtual void addWorkOf(const PeriodMap& /*clone*/) {}
};

}  // namespace orni
