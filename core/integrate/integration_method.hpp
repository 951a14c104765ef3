// The one choice an OdeIntegrator is built with (the policy of ode_integrator.hpp): explicit
// Runge-Kutta, every term of the right-hand side explicit (ARKODE ERKStep with a Butcher table),
// or an implicit-explicit additive pair y' = f_E(t, y) + L y with a linear, constant implicit part
// (ARKODE ARKStep; the stiff modal stiffness and damping of the flexible wing,
// core/dynamics/modal_implicit_split.hpp), whose stage equations (I - gamma L) z = b are solved
// exactly by the part's own solve. Everything else (tolerances, stepping, counters, the error
// path) is the same for both.
#pragma once

#include "core/integrate/integrator_options.hpp"

namespace orni {

/// Butcher tables of the explicit method. kArk436 is the explicit table of Kennedy and Carpenter's
/// ARK4(3)6L[2]SA: on the flexible wing and in free flight, where the step is limited by the
/// stability of the modes and the tip-strip lag states rather than by accuracy, it needs a third
/// fewer RHS evaluations than Dormand-Prince for the same cycle means (measured on the magpie:
/// 2933 vs 4441 evaluations for 10 free cycles, 3423 vs 4441 tethered); on the rigid RFW rig
/// Dormand-Prince is better (1363 vs 1778).
enum class ErkMethod { kDormandPrince5, kVerner6, kFehlberg8, kBogackiShampine3, kArk436 };

/// Additive Runge-Kutta pairs of Kennedy and Carpenter (explicit table + ESDIRK table).
enum class ImexMethod { kArk324, kArk436, kArk437, kArk548 };

class IntegrationMethod {
 public:
  /// y' = rhs(t, y), all explicit, with the Butcher table `table`.
  static IntegrationMethod explicitRungeKutta(ErkMethod table);
  /// y' = rhs(t, y) + L y: rhs explicit, L (`linear_part`, apply and solve both needed) implicit,
  /// with the additive pair `pair`.
  static IntegrationMethod implicitExplicit(LinearImplicitPart linear_part, ImexMethod pair);

  bool isImplicitExplicit() const { return imex_; }
  ErkMethod explicitTable() const { return table_; }  ///< of an explicit method
  ImexMethod additivePair() const { return pair_; }   ///< of an implicit-explicit method
  const LinearImplicitPart& linearPart() const { return linear_; }  ///< empty when explicit
  /// "ARKODE ERKStep <table>" or "ARKODE ARKStep <pair> IMEX, ...", for the summaries.
  const char* name() const;

 private:
  IntegrationMethod() = default;
  bool imex_ = false;
  ErkMethod table_ = ErkMethod::kDormandPrince5;
  ImexMethod pair_ = ImexMethod::kArk437;
  LinearImplicitPart linear_;
};

}  // namespace orni
