// The constrained flight test and the zero moment point (paper section 4, Eq. 6-7, Fig. 9).
//
// The tethered run holds P1 (= the CG) at the trim state; its loads over one cycle become
// coefficients
//   C_F,V = FV / (q S_M),  C_F,H = FH / (q S_M),  C_M,CG = M / (q S_M c_MEAN),
// q = rho U^2 / 2, S_M the area of the wing pair, c_MEAN = S_M / b_M, and the zero moment point
// (ZMP) is the point of the body x axis about which the loads have no moment.
//
// Sign conventions (flight_core.hpp LoadSample, paper Eq. 2): FV up, FH forward (thrust), M
// nose-up, all in the flight-path frame; the body axis x_B is pitched up by theta. Moving the
// moment from the CG to the point a distance x aft of it along x_B gives
//   M(x) = M_CG - x (FV cos theta - FH sin theta) ... paper Eq. 6 (x measured aft, as there),
// so the ZMP lies at
//   epsilon = (x_ZMP - x_CG) / c_MEAN = -C_M,CG / (C_F,V cos theta - C_F,H sin theta),
// epsilon > 0: the ZMP is aft of the CG. The denominator is the coefficient of the force normal
// to the body axis (up), -F_ZB / (q S_M) in paper Eq. 2. Paper Eq. 7 prints "+ C_F,H sin theta";
// that sign contradicts its own Eq. 6 and Eq. 2 for a forward-positive FH (it holds only for an
// aft-positive, drag-like H force), so the Eq. 6 form is used here.
//
// Singular points: the body-normal force passes through zero twice a cycle, where the ZMP runs
// off to infinity. Where |denominator| < ZmpOptions::singular_fraction times its largest |value|
// over the analysed cycle, epsilon is undefined (std::nullopt): never NaN, and the writers leave
// the cell empty (CSV) or write null (JSON).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/simulation_result.hpp"

namespace orni {

/// Reference values of the coefficients (paper section 4, below Eq. 7).
struct CoefficientReference {
  double dynamic_pressure_Pa = 0.0;  ///< q = rho U^2 / 2, > 0
  double wing_area_m2 = 0.0;         ///< S_M, area of the wing pair, > 0
  double mean_chord_m = 0.0;         ///< c_MEAN = S_M / b_M, > 0
  double theta_mean_rad = 0.0;       ///< pitch attitude held in the test (theta_MEAN)
};

/// q from the vehicle's air density and point.speed_mps, S_M = model.wing_area_both_m2,
/// c_MEAN = model.mean_chord_m, theta_MEAN = point.theta_rad.
CoefficientReference coefficientReference(const FlightCoreModel& model,
                                          const OperatingPoint& point);

/// Dimensionless constraint loads at P1 = CG (paper Fig. 9a).
struct LoadCoefficients {
  double CF_V = 0.0;   ///< FV / (q S_M), up
  double CF_H = 0.0;   ///< FH / (q S_M), forward
  double CM_CG = 0.0;  ///< M / (q S_M c_MEAN), nose-up
};

/// The total loads of `s` (FV_N, FH_N, M_Nm: wings aero + inertial + tail) as coefficients.
LoadCoefficients loadCoefficients(const LoadSample& s, const CoefficientReference& ref);

/// Body-normal force coefficient C_F,V cos theta - C_F,H sin theta (the denominator of epsilon).
double zmpDenominator(const LoadCoefficients& c, double theta_rad);

/// epsilon = -C_M,CG / zmpDenominator(c, theta); nullopt where |denominator| < min_abs_denominator
/// (or is zero when min_abs_denominator is 0).
std::optional<double> zmpEpsilon(const LoadCoefficients& c, double theta_rad,
                                 double min_abs_denominator);

/// Half strokes of delta_M = A sin(2 pi f t) (flapping.hpp; delta_M > 0 raises the tip).
enum class Stroke { kUp, kDown };
const char* toString(Stroke s);  ///< "up", "down"

/// Downstroke while delta_M decreases (delta_dot < 0), upstroke while it increases. At a reversal
/// (|delta_dot| <= reversal_tol_radps) the stroke that begins there: down at the top (delta > 0),
/// up at the bottom.
Stroke strokeOf(double delta_rad, double delta_dot_radps, double reversal_tol_radps);

struct ZmpOptions {
  /// epsilon is undefined where |denominator| < singular_fraction * max |denominator| over the
  /// analysed cycle; (0, 1). 0.1 keeps |epsilon| below 10 |C_M,CG|max / |C_F,normal|max.
  double singular_fraction = 0.1;

  bool IsValid(std::string* why) const {
    if (singular_fraction > 0.0 && singular_fraction < 1.0) return true;
    if (why) *why = "singular_fraction must be in (0, 1)";
    return false;
  }
};

/// One sample of the analysed cycle.
struct ZmpSample {
  double t_s = 0.0;
  double delta_rad = 0.0;
  Stroke stroke = Stroke::kUp;
  LoadCoefficients coefficients;
  double denominator = 0.0;       ///< zmpDenominator(coefficients, theta_MEAN)
  std::optional<double> epsilon;  ///< nullopt at the singular points
};

/// Mean, extremes and half peak-to-peak of one coefficient over the cycle.
struct ChannelStats {
  double mean = 0.0, min = 0.0, max = 0.0, amplitude = 0.0;
};

/// epsilon over the samples of one half stroke (or the whole cycle).
struct EpsilonMetrics {
  int samples = 0;
  int defined_samples = 0;
  /// Mean of the defined epsilon weighted by |denominator|: sum |D| eps / sum |D|
  /// = -sum C_M sign(D) / sum |D|; nullopt without defined samples.
  std::optional<double> weighted_mean;
  /// -mean(C_M,CG) / mean(denominator) over all the samples (the ZMP of the mean loads); nullopt
  /// when |mean(denominator)| is below the singular threshold.
  std::optional<double> of_mean_loads;
  std::optional<double> min, max;  ///< of the defined epsilon
};

/// Result of analyseConstrainedFlightTest.
struct ConstrainedFlightTest {
  CoefficientReference reference;
  ZmpOptions options;
  std::vector<ZmpSample> samples;
  ChannelStats CF_V, CF_H, CM_CG;
  double denominator_max_abs = 0.0;   ///< max |denominator| over the cycle
  double singular_threshold = 0.0;    ///< options.singular_fraction * denominator_max_abs
  EpsilonMetrics cycle, upstroke, downstroke;
};

/// The constrained flight test over one flapping period sampled uniformly (endpoint excluded):
/// t_s, delta_rad, delta_dot_radps and loads have the same length n >= 1. Strokes by strokeOf with
/// a reversal tolerance of 1e-9 max |delta_dot|. Throws std::invalid_argument for mismatched
/// lengths, an empty cycle, a non-positive reference or invalid options.
ConstrainedFlightTest analyseConstrainedFlightTest(const std::vector<double>& t_s,
                                                   const std::vector<double>& delta_rad,
                                                   const std::vector<double>& delta_dot_radps,
                                                   const std::vector<LoadSample>& loads,
                                                   const CoefficientReference& reference,
                                                   const ZmpOptions& options = {});

/// The constrained flight test of the last whole cycle of a tethered run's `history` at `point`
/// (samples_per_cycle samples a cycle, endpoint excluded; the flap rate from the vehicle's
/// flapping at point.freq_hz); nullopt when the history holds less than one whole cycle.
std::optional<ConstrainedFlightTest> lastCycleConstrainedFlightTest(const FlightCoreModel& model,
                                                                    const OperatingPoint& point,
                                                                    const TimeHistory& history,
                                                                    int samples_per_cycle);

}  // namespace orni
