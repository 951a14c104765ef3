#include "core/analysis/periodic_continuation.hpp"

#include <Eigen/LU>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <thread>
#include <utility>

#include "core/analysis/monodromy.hpp"

namespace orni {

const char* toString(ContinuationStatus s) {
  switch (s) {
    case ContinuationStatus::kCompleted: return "completed";
    case ContinuationStatus::kNotConverged: return "not_converged";
    case ContinuationStatus::kFailed: return "failed";
    case ContinuationStatus::kInterrupted: return "interrupted";
  }
  return "failed";
}

bool ContinuationOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(std::isfinite(lambda_min) && std::isfinite(lambda_max) && lambda_min < lambda_max))
    return fail("the parameter range must be finite with min < max");
  if (!(min_step > 0.0 && min_step <= initial_step && initial_step <= max_step &&
        std::isfinite(max_step)))
    return fail("steps must satisfy 0 < min_step <= initial_step <= max_step");
  if (direction != 1 && direction != -1) return fail("direction must be +1 or -1");
  if (max_points < 1 || max_points > 100000) return fail("max_points must be in [1, 100000]");
  if (max_corrector_iterations < 1 || max_corrector_iterations > 100)
    return fail("max_corrector_iterations must be in [1, 100]");
  if (target_iterations < 1 || target_iterations > max_corrector_iterations)
    return fail("target_iterations must be in [1, max_corrector_iterations]");
  if (!(residual_tol > 0.0 && residual_tol <= 1e-2)) return fail("residual_tol must be in (0, 1e-2]");
  if (!(fd_step > 0.0 && fd_step <= 1e-2)) return fail("fd_step must be in (0, 1e-2]");
  if (!(locate_tol > 0.0)) return fail("locate_tol must be > 0");
  if (max_bisections < 1 || max_bisections > 200) return fail("max_bisections must be in [1, 200]");
  if (leading_multipliers < 0 || leading_multipliers > 100)
    return fail("leading_multipliers must be in [0, 100]");
  if (!(tangent_tol > 0.0 && tangent_tol <= 1e-2)) return fail("tangent_tol must be in (0, 1e-2]");
  if (max_krylov < 2 || max_krylov > 400) return fail("max_krylov must be in [2, 400]");
  if (leading_multipliers > 0 && leading_multipliers + 1 > max_krylov)
    return fail("max_krylov must exceed leading_multipliers");
  return true;
}

namespace {

double maxAbs(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

/// The largest modulus among the multipliers of one kind: real near +1 (Re > 0, |Im| tiny),
/// real near -1, complex.
enum class CrossingKind { kPositiveReal, kNegativeReal, kComplex };

CrossingKind kindOf(std::complex<double> mu) {
  const double tiny = 1e-9 * std::max(1.0, std::abs(mu));
  if (std::abs(mu.imag()) > tiny) return CrossingKind::kComplex;
  return mu.real() >= 0.0 ? CrossingKind::kPositiveReal : CrossingKind::kNegativeReal;
}

/// Count of multipliers outside the unit circle per kind.
struct OutsideCount {
  int positive = 0, negative = 0, complex = 0;
};

OutsideCount outside(const Eigen::VectorXcd& mu) {
  OutsideCount c;
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    if (std::abs(mu[i]) < 1.0) continue;
    switch (kindOf(mu[i])) {
      case CrossingKind::kPositiveReal: ++c.positive; break;
      case CrossingKind::kNegativeReal: ++c.negative; break;
      case CrossingKind::kComplex: ++c.complex; break;
    }
  }
  return c;
}

/// The curve H(y) = R(z; lambda) of the shooting system with lambda as the last unknown.
class Curve {
 public:
  Curve(PeriodMap& map, const ShootingOptions& so, const std::vector<double>& p, int parameter)
      : map_(map),
        sys_(map, so.free_parameters, so.conditions, p),
        parameter_(parameter),
        scale_(map.parameterScale(parameter)),
        N_(sys_.unknownCount()) {
    sys_.setJacobianThreads(so.jacobian_threads);
    threads_ = so.jacobian_threads;
  }
  int threads() const { return threads_; }

  int N() const { return N_; }
  int n() const { return sys_.stateCount(); }
  PeriodMap& map() { return map_; }
  long maps() const { return sys_.periodMaps() + extra_maps_; }

  Eigen::VectorXd pack(const std::vector<double>& x, const std::vector<double>& p) {
    for (std::size_t j = 0; j < p.size(); ++j) sys_.setParameter(static_cast<int>(j), p[j]);
    Eigen::VectorXd y(N_ + 1);
    y.head(N_) = sys_.pack(x.data());
    y[N_] = p[static_cast<std::size_t>(parameter_)] / scale_;
    return y;
  }
  /// x and every parameter of y.
  void unpack(const Eigen::VectorXd& y, std::vector<double>* x, std::vector<double>* p) {
    sys_.setParameter(parameter_, y[N_] * scale_);
    x->assign(static_cast<std::size_t>(n()), 0.0);
    sys_.unpack(y.head(N_), x->data());
    *p = sys_.parameters();
  }
  double lambda(const Eigen::VectorXd& y) const { return y[N_] * scale_; }
  double scale() const { return scale_; }

  bool residual(const Eigen::VectorXd& y, Eigen::VectorXd* H, std::string* why) {
    sys_.setParameter(parameter_, y[N_] * scale_);
    return sys_.residual(y.head(N_), H, why);
  }
  /// DH = [dR/dz, dR/d(lambda / s)] at y (H = H(y)).
  bool jacobian(const Eigen::VectorXd& y, const Eigen::VectorXd& H, double step,
                Eigen::MatrixXd* DH, std::string* why) {
    sys_.setParameter(parameter_, y[N_] * scale_);
    Eigen::MatrixXd J, Jl;
    if (!sys_.jacobian(y.head(N_), H, step, false, &J, why, {parameter_}, &Jl)) return false;
    DH->resize(N_, N_ + 1);
    DH->leftCols(N_) = J;
    DH->col(N_) = Jl.col(0);
    return true;
  }
  /// DH with only the columns of `states` (all when empty), the free parameters' and lambda's
  /// differenced; every other state column is -e_j (dPhi/dx_j = 0: decayed over a period).
  bool partialJacobian(const Eigen::VectorXd& y, const Eigen::VectorXd& H, double step,
                       const std::vector<int>& states, Eigen::MatrixXd* DH, std::string* why) {
    if (states.empty()) return jacobian(y, H, step, DH, why);
    sys_.setParameter(parameter_, y[N_] * scale_);
    Eigen::MatrixXd J;
    // Its columns on this thread: it runs beside Arnoldi (completeLeading), which has the other.
    sys_.setJacobianThreads(1);
    const bool partial_ok = sys_.partialJacobian(y.head(N_), H, step, states, &J, why);
    sys_.setJacobianThreads(threads_);
    if (!partial_ok) return false;
    DH->resize(N_, N_ + 1);
    DH->leftCols(N_) = J;
    // lambda's column as ShootingSystem's parameter columns: a step of step * max(1, |y_N|).
    const double h = step * std::max(1.0, std::abs(y[N_]));
    Eigen::VectorXd yp = y, Hp;
    yp[N_] += h;
    const bool ok = residual(yp, &Hp, why);
    restore(y);
    if (!ok) return false;
    DH->col(N_) = (Hp - H) / h;
    return true;
  }
  /// DH v by a forward difference along v (H = H(y)): a step of step * max(1, |y|_inf) / |v|_2.
  bool directional(const Eigen::VectorXd& y, const Eigen::VectorXd& H, const Eigen::VectorXd& v,
                   double step, Eigen::VectorXd* out, std::string* why) {
    const double norm = v.norm();
    if (!(norm > 0.0)) {
      out->setZero(N_);
      return true;
    }
    const double h = step * std::max(1.0, y.cwiseAbs().maxCoeff()) / norm;
    Eigen::VectorXd Hp;
    const bool ok = residual(y + h * v, &Hp, why);
    restore(y);
    if (!ok) return false;
    *out = (Hp - H) / h;
    return true;
  }
  /// The parameters (free and lambda) of the system back at y after runs at other points.
  void restore(const Eigen::VectorXd& y) {
    std::vector<double> x;
    std::vector<double> p;
    unpack(y, &x, &p);
  }
  /// Maps run outside the shooting system (Arnoldi's) count in maps().
  void addMaps(long maps) { extra_maps_ += maps; }
  bool refreshGrid(const Eigen::VectorXd& y, std::string* why) {
    std::vector<double> x, p;
    unpack(y, &x, &p);
    ++extra_maps_;
    return map_.refreshDiscretisation(x.data(), p.data(), why);
  }

 private:
  PeriodMap& map_;
  ShootingSystem sys_;
  int parameter_;
  double scale_;
  int N_;
  long extra_maps_ = 0;
  int threads_ = 1;
};

/// Unit null vector of DH (N x (N + 1)) oriented like `previous`: the last column of Q in
/// DH^T = Q R (Householder), which depends on DH alone, so a resumed run finds the same bits.
bool tangentOf(const Eigen::MatrixXd& DH, const Eigen::VectorXd& previous, Eigen::VectorXd* t) {
  const Eigen::Index N = DH.rows();
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(DH.transpose());
  Eigen::VectorXd e = Eigen::VectorXd::Zero(N + 1);
  e[N] = 1.0;
  *t = qr.householderQ() * e;
  const double norm = t->norm();
  if (!t->allFinite() || !(norm > 0.0)) return false;
  *t /= norm;
  if (t->dot(previous) < 0.0) *t = -*t;
  return true;
}

/// Right-preconditioned GMRES (modified Gram-Schmidt, twice) for A d = b with the operator
/// `apply` (v -> A v) and the preconditioner `precondition` (v -> P^-1 v), from d = 0; stops when
/// |b - A d|_2 <= tol or after max_products operator products. False when a product fails; *done
/// says whether the tolerance was met; *products counts the products.
template <class Apply, class Precondition>
bool gmres(const Apply& apply, const Precondition& precondition, const Eigen::VectorXd& b,
           double tol, int max_products, Eigen::VectorXd* d, bool* done, int* products) {
  const Eigen::Index n = b.size();
  *done = false;
  *products = 0;
  d->setZero(n);
  const double beta = b.norm();
  if (beta <= tol) {
    *done = true;
    return true;
  }
  Eigen::MatrixXd V = Eigen::MatrixXd::Zero(n, max_products + 1);
  Eigen::MatrixXd Hm = Eigen::MatrixXd::Zero(max_products + 1, max_products);
  V.col(0) = b / beta;
  Eigen::VectorXd w, c;
  for (int j = 0; j < max_products; ++j) {
    if (!apply(precondition(V.col(j)), &w)) return false;
    ++*products;
    for (int pass = 0; pass < 2; ++pass)
      for (int i = 0; i <= j; ++i) {
        const double h = V.col(i).dot(w);
        Hm(i, j) += h;
        w -= h * V.col(i);
      }
    const double h_next = w.norm();
    Hm(j + 1, j) = h_next;
    const int m = j + 1;
    // The least-squares problem min |beta e_1 - H_m c| (small: a dense QR each time).
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + 1);
    rhs[0] = beta;
    const Eigen::MatrixXd Hj = Hm.topLeftCorner(m + 1, m);
    c = Hj.colPivHouseholderQr().solve(rhs);
    const double residual = (rhs - Hj * c).norm();
    const bool breakdown = !(h_next > 1e-14 * std::max(1.0, Hm.col(j).norm()));
    if (residual <= tol || breakdown || m == max_products) {
      *d = precondition(V.leftCols(m) * c);
      *done = residual <= tol || breakdown;
      return d->allFinite();
    }
    V.col(j + 1) = w / h_next;
  }
  return true;
}

/// Everything of one solve along the curve.
struct Corrected {
  Eigen::VectorXd y, H, grid_origin;
  int iterations = 0;
};

class Continuation {
 public:
  Continuation(PeriodMap& map, const ShootingOptions& so, const std::vector<double>& p0,
               const ContinuationOptions& o, const ContinuationCallback& on_point,
               const ContinuationPrepare& prepare, const ContinuationResumeHook& on_resume)
      : curve_(map, so, p0, o.parameter),
        o_(o),
        on_point_(on_point),
        prepare_(prepare),
        on_resume_(on_resume) {}

  ContinuationSummary run(const std::vector<double>& x0, const std::vector<double>& p0,
                          const ShootingOptions& so, const ContinuationPoint* resume);

 private:
  /// Predictor from (y, t) by h, corrector on [H; row . (y - y_from) - h] (row = t, or e_lambda
  /// with the parameter fixed at `lambda_fixed_scaled`), chord matrix [DH; row^T] with Broyden
  /// updates. The grid is refreshed at the predicted point when `refresh`.
  bool correct(const Eigen::VectorXd& y0, const Eigen::VectorXd& t0, const Eigen::MatrixXd& DH0,
               double h, bool fix_lambda, double lambda_fixed_scaled, bool refresh, Corrected* c,
               std::string* why);
  /// The point at the corrected y: DH, tangent (oriented like previous_tangent), multipliers.
  bool complete(const Corrected& c, const Eigen::VectorXd& previous_tangent,
                ContinuationPoint* pt, Eigen::MatrixXd* DH, std::string* why);
  /// complete()'s tangent and multipliers with the partial DH, GMRES and Arnoldi (the header's
  /// "leading ones"). kFallback: Arnoldi or GMRES did not converge (the caller forms the full DH).
  enum class Leading { kDone, kFallback, kFailed };
  Leading completeLeading(const Eigen::VectorXd& y, const Eigen::VectorXd& H,
                          const Eigen::VectorXd& previous_tangent, ContinuationPoint* pt,
                          Eigen::MatrixXd* DH, std::string* why);
  /// Its partial DH and GMRES tangent (pt->tangent, tangent_lambda).
  Leading leadingTangent(const Eigen::VectorXd& y, const Eigen::VectorXd& H,
                         const Eigen::VectorXd& previous_tangent, ContinuationPoint* pt,
                         Eigen::MatrixXd* DH, std::string* why);
  /// The caller's prepare on the corrected point; when it changed the map, the point is corrected
  /// again at its parameter on the same grid (chord matrix DH_chord).
  bool refine(Corrected* c, const Eigen::MatrixXd& DH_chord, std::string* why) {
    if (!prepare_) return true;
    ContinuationPoint pt;
    pt.y = c->y;
    pt.lambda = curve_.lambda(c->y);
    curve_.unpack(c->y, &pt.x, &pt.p);
    if (!prepare_(pt)) return true;
    Corrected again;
    const Eigen::Index N = curve_.N();
    const Eigen::VectorXd none = Eigen::VectorXd::Zero(N + 1);
    if (!correct(c->y, none, DH_chord, 0.0, true, c->y[N], false, &again, why)) return false;
    // The step control reads the first correction's iterations (how far the predictor missed).
    c->y = again.y;
    c->H = again.H;
    return true;
  }
  bool emit(const ContinuationPoint& pt) {
    summary_.points.push_back(pt);
    return !on_point_ || on_point_(pt);
  }
  /// Locate the event between regular points a and b (b accepted from a with step h); false only
  /// when the run must stop (callback). The event point is emitted when found.
  bool locate(const ContinuationPoint& a, const Eigen::MatrixXd& DH_a, double h,
              const ContinuationPoint& b, const std::string& event, bool* stop);
  double eventFunction(const std::string& event, const ContinuationPoint& pt) const;

  ContinuationSummary finish(ContinuationStatus status, std::string message) {
    summary_.status = status;
    summary_.message = std::move(message);
    summary_.period_maps = curve_.maps();
    return summary_;
  }

  Curve curve_;
  ContinuationOptions o_;
  const ContinuationCallback& on_point_;
  const ContinuationPrepare& prepare_;
  const ContinuationResumeHook& on_resume_;
  ContinuationSummary summary_;
  double step_scale_ = 1.0;  // steps_in_parameter's factor on the step limits
};

bool Continuation::correct(const Eigen::VectorXd& y0, const Eigen::VectorXd& t0,
                           const Eigen::MatrixXd& DH0, double h, bool fix_lambda,
                           double lambda_fixed_scaled, bool refresh, Corrected* c,
                           std::string* why) {
  const Eigen::Index N = curve_.N();
  Eigen::VectorXd row = Eigen::VectorXd::Zero(N + 1);
  if (fix_lambda)
    row[N] = 1.0;
  else
    row = t0;
  Eigen::VectorXd y = y0 + h * t0;
  if (fix_lambda) y[N] = lambda_fixed_scaled;
  c->grid_origin = y;
  if (refresh && !curve_.refreshGrid(y, why)) return false;
  auto last = [&](const Eigen::VectorXd& v) {
    return fix_lambda ? v[N] - lambda_fixed_scaled : t0.dot(v - y0) - h;
  };
  Eigen::MatrixXd A(N + 1, N + 1);
  A.topRows(N) = DH0;
  A.row(N) = row.transpose();
  Eigen::VectorXd H;
  if (!curve_.residual(y, &H, why)) return false;
  const double start = maxAbs(H);
  Eigen::VectorXd F(N + 1), H_new;
  for (int it = 1; it <= o_.max_corrector_iterations; ++it) {
    F.head(N) = H;
    F[N] = last(y);
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
    const Eigen::VectorXd dy = -lu.solve(F);
    if (!dy.allFinite()) {
      *why = "singular corrector matrix";
      return false;
    }
    const Eigen::VectorXd y_new = y + dy;
    if (!curve_.residual(y_new, &H_new, why)) return false;
    // Broyden on the DH block only (the last row is exact).
    A.topRows(N).noalias() += ((H_new - H) - A.topRows(N) * dy) *
                              (dy.transpose() / dy.squaredNorm());
    y = y_new;
    H = H_new;
    if (maxAbs(H) <= o_.residual_tol) {
      c->y = y;
      c->H = H;
      c->iterations = it;
      return true;
    }
    if (!(maxAbs(H) < 1e3 * std::max(start, o_.residual_tol))) break;  // diverging
  }
  char buf[160];
  std::snprintf(buf, sizeof buf, "the corrector did not converge (residual %.3e)", maxAbs(H));
  *why = buf;
  return false;
}

bool Continuation::complete(const Corrected& c, const Eigen::VectorXd& previous_tangent,
                            ContinuationPoint* pt, Eigen::MatrixXd* DH,
                            std::string* why) {
  const int n = curve_.n();
  const Eigen::Index N = curve_.N();
  pt->y = c.y;
  pt->grid_origin = c.grid_origin;
  pt->lambda = curve_.lambda(c.y);
  curve_.unpack(c.y, &pt->x, &pt->p);
  pt->residual_max = maxAbs(c.H);
  pt->corrector_iterations = c.iterations;
  Eigen::VectorXd H;
  if (!curve_.residual(c.y, &H, why)) return false;
  if (o_.leading_multipliers > 0) {
    const Leading l = completeLeading(c.y, H, previous_tangent, pt, DH, why);
    if (l == Leading::kFailed) return false;
    if (l == Leading::kDone) {
      pt->period_maps = curve_.maps();
      return true;
    }
  }
  if (!curve_.jacobian(c.y, H, o_.fd_step, DH, why)) return false;
  if (!tangentOf(*DH, previous_tangent, &pt->tangent)) {
    *why = "no tangent (singular extended Jacobian)";
    return false;
  }
  pt->tangent_lambda = pt->tangent[N];
  const Eigen::MatrixXd M = DH->topLeftCorner(n, n) + Eigen::MatrixXd::Identity(n, n);
  const MonodromyEigen e = eigenOfMonodromy(M);
  if (!e.ok) {
    *why = e.message;
    return false;
  }
  pt->multipliers = e.multipliers;
  pt->multipliers_complete = true;
  pt->max_modulus = std::abs(e.multipliers[0]);
  pt->leading_vector = e.vectors.col(0);
  pt->stable = pt->max_modulus < 1.0;
  pt->period_maps = curve_.maps();
  return true;
}

Continuation::Leading Continuation::completeLeading(const Eigen::VectorXd& y,
                                                   const Eigen::VectorXd& H,
                                                   const Eigen::VectorXd& previous_tangent,
                                                   ContinuationPoint* pt, Eigen::MatrixXd* DH,
                                                   std::string* why) {
  // Arnoldi depends on the point alone: with two or more threads it runs on a copy of the map
  // (the same grid and coefficients, so the same bits) while this thread finds the tangent.
  ArnoldiOptions ao;
  ao.count = o_.leading_multipliers;
  ao.max_dimension = o_.max_krylov;
  ao.fd_step = o_.fd_step;
  MonodromyEigen e;
  std::unique_ptr<PeriodMap> copy = curve_.threads() > 1 ? curve_.map().clone() : nullptr;
  std::exception_ptr arnoldi_error;
  std::thread arnoldi;
  if (copy)
    arnoldi = std::thread([&] {
      try {
        e = leadingMultipliers(*copy, pt->x, pt->p, ao);
      } catch (...) {
        arnoldi_error = std::current_exception();
      }
    });
  // The tangent's maps may throw (a cancellation): the Arnoldi thread is joined first.
  Leading tangent = Leading::kFailed;
  std::exception_ptr tangent_error;
  try {
    tangent = leadingTangent(y, H, previous_tangent, pt, DH, why);
  } catch (...) {
    tangent_error = std::current_exception();
  }
  if (copy) {
    arnoldi.join();
    curve_.map().addWorkOf(*copy);
  }
  if (tangent_error) std::rethrow_exception(tangent_error);
  if (arnoldi_error) std::rethrow_exception(arnoldi_error);
  if (!copy && tangent == Leading::kDone) {
    e = leadingMultipliers(curve_.map(), pt->x, pt->p, ao);
  }
  curve_.addMaps(e.period_maps);
  if (tangent != Leading::kDone) return tangent;
  if (!e.ok) return Leading::kFallback;
  pt->multipliers = e.multipliers;
  pt->multipliers_complete = e.complete;
  pt->max_modulus = std::abs(e.multipliers[0]);
  pt->leading_vector = e.vectors.col(0);
  pt->stable = pt->max_modulus < 1.0;
  return Leading::kDone;
}

Continuation::Leading Continuation::leadingTangent(const Eigen::VectorXd& y,
                                                   const Eigen::VectorXd& H,
                                                   const Eigen::VectorXd& previous_tangent,
                                                   ContinuationPoint* pt, Eigen::MatrixXd* DH,
                                                   std::string* why) {
  const Eigen::Index N = curve_.N();
  if (!curve_.partialJacobian(y, H, o_.fd_step, o_.slow_states, DH, why)) return Leading::kFailed;
  // t0: the partial DH's null vector, not yet oriented (the refinement below must not depend on
  // the previous tangent, or a resumed run would find other bits).
  Eigen::VectorXd t0;
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(N + 1);
  if (!tangentOf(*DH, none, &t0)) {
    *why = "no tangent (singular extended Jacobian)";
    return Leading::kFailed;
  }
  // t = t0 + d, [DH; t0^T] d = [-DH t0; 0]; preconditioner [DH_partial; t0^T].
  Eigen::MatrixXd P(N + 1, N + 1);
  P.topRows(N) = *DH;
  P.row(N) = t0.transpose();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(P);
  Eigen::VectorXd dh_t0;
  if (!curve_.directional(y, H, t0, o_.fd_step, &dh_t0, why)) return Leading::kFailed;
  Eigen::VectorXd b(N + 1);
  b.head(N) = -dh_t0;
  b[N] = 0.0;
  auto apply = [&](const Eigen::VectorXd& v, Eigen::VectorXd* w) {
    Eigen::VectorXd dv;
    if (!curve_.directional(y, H, v, o_.fd_step, &dv, why)) return false;
    w->resize(N + 1);
    w->head(N) = dv;
    (*w)[N] = t0.dot(v);
    return true;
  };
  auto precondition = [&](const Eigen::VectorXd& v) { return Eigen::VectorXd(lu.solve(v)); };
  Eigen::VectorXd d;
  bool done = false;
  int products = 0;
  if (!gmres(apply, precondition, b, o_.tangent_tol, o_.max_krylov, &d, &done, &products))
    return Leading::kFailed;
  if (!done) return Leading::kFallback;
  Eigen::VectorXd t = t0 + d;
  const double norm = t.norm();
  if (!t.allFinite() || !(norm > 0.0)) return Leading::kFallback;
  t /= norm;
  if (t.dot(previous_tangent) < 0.0) t = -t;
  pt->tangent = t;
  pt->tangent_lambda = t[N];
  return Leading::kDone;
}

double Continuation::eventFunction(const std::string& event, const ContinuationPoint& pt) const {
  if (event == "fold") return pt.tangent_lambda;
  // The largest modulus of the kind that crossed, minus 1.
  const CrossingKind want = event == "period_doubling" ? CrossingKind::kNegativeReal
                            : event == "neimark_sacker" ? CrossingKind::kComplex
                                                        : CrossingKind::kPositiveReal;
  double m = 0.0;
  for (Eigen::Index i = 0; i < pt.multipliers.size(); ++i)
    if (kindOf(pt.multipliers[i]) == want) m = std::max(m, std::abs(pt.multipliers[i]));
  return m - 1.0;
}

bool Continuation::locate(const ContinuationPoint& a, const Eigen::MatrixXd& DH_a, double h,
                          const ContinuationPoint& b, const std::string& event, bool* stop) {
  *stop = false;
  double s_lo = 0.0, s_hi = h;
  const double g_lo = eventFunction(event, a);
  ContinuationPoint lo = a, hi = b, best = b;
  std::string why;
  for (int k = 0; k < o_.max_bisections; ++k) {
    if (std::abs(hi.lambda - lo.lambda) <= o_.locate_tol) break;
    const double s = 0.5 * (s_lo + s_hi);
    Corrected c;
    ContinuationPoint mid;
    Eigen::MatrixXd DH;
    if (!correct(a.y, a.tangent, DH_a, s, false, 0.0, false, &c, &why) ||
        !complete(c, a.tangent, &mid, &DH, &why))
      break;  // the bracket so far is the answer
    const double g = eventFunction(event, mid);
    if ((g < 0.0) == (g_lo < 0.0)) {
      s_lo = s;
      lo = mid;
    } else {
      s_hi = s;
      hi = mid;
    }
  }
  // The end of the bracket nearer the crossing by linear interpolation of the event function.
  const double glo = eventFunction(event, lo), ghi = eventFunction(event, hi);
  best = std::abs(glo) <= std::abs(ghi) ? lo : hi;
  best.event = event;
  best.index = b.index;
  best.arclength = a.arclength + (std::abs(glo) <= std::abs(ghi) ? s_lo : s_hi);
  best.step = 0.0;
  best.step_scale = step_scale_;
  best.period_maps = curve_.maps();
  ++summary_.events;
  if (!emit(best)) *stop = true;
  return true;
}

ContinuationSummary Continuation::run(const std::vector<double>& x0,
                                      const std::vector<double>& p0, const ShootingOptions& so,
                                      const ContinuationPoint* resume) {
  const Eigen::Index N = curve_.N();
  std::string why;
  char buf[320];
  ContinuationPoint a;
  Eigen::MatrixXd DH_a;
  double h = o_.initial_step;
  if (resume) {
    // The recorded point again: its map, grid and Jacobian as when it was accepted.
    Corrected c;
    c.y = resume->y;
    c.grid_origin = resume->grid_origin;
    if (!curve_.refreshGrid(resume->grid_origin, &why))
      return finish(ContinuationStatus::kFailed, "the resumed point could not be mapped: " + why);
    if (on_resume_) on_resume_();
    if (!curve_.residual(resume->y, &c.H, &why))
      return finish(ContinuationStatus::kFailed, "the resumed point could not be mapped: " + why);
    c.iterations = resume->corrector_iterations;
    if (!complete(c, resume->tangent, &a, &DH_a, &why))
      return finish(ContinuationStatus::kFailed, "the resumed point: " + why);
    a.index = resume->index;
    a.arclength = resume->arclength;
    a.residual_max = resume->residual_max;
    a.period_maps = resume->period_maps;
    h = resume->step;
    step_scale_ = resume->step_scale;
    a.step_scale = step_scale_;
    o_.initial_step *= step_scale_;
    o_.min_step *= step_scale_;
    o_.max_step *= step_scale_;
  } else {
    // The caller's prepare on the given orbit first (its map for the whole first step).
    if (prepare_) {
      ContinuationPoint given;
      given.x = x0;
      given.p = p0;
      given.lambda = p0[static_cast<std::size_t>(o_.parameter)];
      prepare_(given);
    }
    // The start: solved again on a grid refreshed at the given orbit (reproducible).
    ShootingOptions s0 = so;
    s0.residual_tol = o_.residual_tol;
    s0.refresh_below = 0.0;
    s0.jacobian_at_solution = false;
    s0.initial_jacobian.resize(0, 0);
    const ShootingSummary start = solveShooting(curve_.map(), x0, p0, s0);
    if (start.status != ShootingStatus::kConverged)
      return finish(ContinuationStatus::kFailed, "the start orbit: " + start.message);
    Corrected c;
    c.y = curve_.pack(start.x, start.p);
    c.grid_origin = curve_.pack(x0, p0);
    c.iterations = start.iterations;
    if (!curve_.residual(c.y, &c.H, &why))
      return finish(ContinuationStatus::kFailed, "the start orbit: " + why);
    Eigen::VectorXd along = Eigen::VectorXd::Zero(N + 1);
    along[N] = o_.direction;
    if (!complete(c, along, &a, &DH_a, &why))
      return finish(ContinuationStatus::kFailed, "the start orbit: " + why);
    a.index = 0;
    a.arclength = 0.0;
    if (o_.steps_in_parameter) {
      step_scale_ = 1.0 / std::max(std::abs(a.tangent[N]), 0.05);
      o_.initial_step *= step_scale_;
      o_.min_step *= step_scale_;
      o_.max_step *= step_scale_;
      h = o_.initial_step;
    }
    a.step = h;
    a.step_scale = step_scale_;
    if (!emit(a)) return finish(ContinuationStatus::kInterrupted, "stopped after the start");
  }

  const double s = curve_.scale();
  const double lo_scaled = o_.lambda_min / s, hi_scaled = o_.lambda_max / s;
  while (a.index < o_.max_points) {
    // Land on the end of the range exactly when the predictor would leave it.
    const double lam_pred = a.y[N] + h * a.tangent[N];
    bool fix = false;
    double target = 0.0;
    if (lam_pred > hi_scaled || lam_pred < lo_scaled) {
      target = lam_pred > hi_scaled ? hi_scaled : lo_scaled;
      if (std::abs(a.y[N] - target) * s <= 1e-12 * std::max(1.0, std::abs(target * s)))
        return finish(ContinuationStatus::kCompleted,
                      "the branch reached the end of the parameter range");
      fix = true;
    }
    Corrected c;
    if (!correct(a.y, a.tangent, DH_a, h, fix, target, true, &c, &why) ||
        !refine(&c, DH_a, &why)) {
      h *= 0.5;
      if (h < o_.min_step) {
        std::snprintf(buf, sizeof buf,
                      "the step fell below %.1e at parameter %.6g: %s", o_.min_step, a.lambda,
                      why.c_str());
        return finish(ContinuationStatus::kNotConverged, buf);
      }
      continue;
    }
    ContinuationPoint b;
    Eigen::MatrixXd DH_b;
    if (!complete(c, a.tangent, &b, &DH_b, &why)) {
      std::snprintf(buf, sizeof buf, "at parameter %.6g: %s", curve_.lambda(c.y), why.c_str());
      return finish(ContinuationStatus::kFailed, buf);
    }
    const double taken = (c.y - a.y).norm();
    b.index = a.index + 1;
    b.arclength = a.arclength + taken;
    double h_next = h;
    if (c.iterations < o_.target_iterations)
      h_next = std::min(1.5 * h, o_.max_step);
    else if (c.iterations > o_.target_iterations)
      h_next = std::max(0.7 * h, o_.min_step);
    b.step = h_next;
    b.step_scale = step_scale_;
    const std::string event = continuationEventBetween(a, b);
    if (!event.empty()) {
      bool stop = false;
      if (o_.locate_events) {
        locate(a, DH_a, a.tangent.dot(b.y - a.y), b, event, &stop);
      } else {
        ContinuationPoint flag = b;
        flag.event = event;
        ++summary_.events;
        stop = !emit(flag);
      }
      if (stop) return finish(ContinuationStatus::kInterrupted, "stopped at an event");
    }
    if (!emit(b)) return finish(ContinuationStatus::kInterrupted, "stopped by the caller");
    a = b;
    DH_a = DH_b;
    h = h_next;
    if (fix)
      return finish(ContinuationStatus::kCompleted,
                    "the branch reached the end of the parameter range");
  }
  std::snprintf(buf, sizeof buf,
                "%d points reached at parameter %.6g before the end of the range", o_.max_points,
                a.lambda);
  return finish(ContinuationStatus::kNotConverged, buf);
}

}  // namespace

std::string continuationEventBetween(const ContinuationPoint& a, const ContinuationPoint& b) {
  if ((a.tangent_lambda > 0.0) != (b.tangent_lambda > 0.0)) return "fold";
  const OutsideCount ca = outside(a.multipliers), cb = outside(b.multipliers);
  if (ca.negative != cb.negative) return "period_doubling";
  if (ca.complex != cb.complex) return "neimark_sacker";
  if (ca.positive != cb.positive) return "branch_point";
  return "";
}

ContinuationSummary continuePeriodicOrbits(PeriodMap& map, const std::vector<double>& x0,
                                           const std::vector<double>& p0,
                                           const ShootingOptions& shooting,
                                           const ContinuationOptions& options,
                                           const ContinuationCallback& on_point,
                                           const ContinuationPrepare& prepare,
                                           const ContinuationPoint* resume_from,
                                           const ContinuationResumeHook& on_resume) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("continuation options: " + why);
  if (!shooting.IsValid(map.parameterCount(), map.conditionCount(), &why))
    throw std::invalid_argument("shooting options: " + why);
  if (options.parameter < 0 || options.parameter >= map.parameterCount())
    throw std::invalid_argument("continuation: parameter index out of range");
  for (int j : shooting.free_parameters)
    if (j == options.parameter)
      throw std::invalid_argument("continuation: the parameter is one of the free parameters");
  if (static_cast<int>(x0.size()) != map.stateCount() ||
      static_cast<int>(p0.size()) != map.parameterCount())
    throw std::invalid_argument("continuation: one value per state and parameter");
  const double lambda0 = p0[static_cast<std::size_t>(options.parameter)];
  if (!resume_from && !(lambda0 >= options.lambda_min && lambda0 <= options.lambda_max))
    throw std::invalid_argument("continuation: the start lies outside the parameter range");
  Continuation c(map, shooting, p0, options, on_point, prepare, on_resume);
  return c.run(x0, p0, shooting, resume_from);
}

}  // namespace orni
