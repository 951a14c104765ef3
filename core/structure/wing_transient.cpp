#include "core/structure/wing_transient.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/structure/fe_types.hpp"
#include "core/structure/sparse_solve.hpp"

namespace orni::structure {

bool WingTransientOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why != nullptr) *why = m;
    return false;
  };
  if (!(damping_s >= 0.0) || !std::isfinite(damping_s)) return fail("damping_s: expected >= 0");
  if (!(hht_alpha >= -1.0 / 3.0 && hht_alpha <= 0.0)) return fail("hht_alpha: expected in [-1/3, 0]");
  if (max_newton_iterations < 1) return fail("max_newton_iterations: expected >= 1");
  if (!(force_tolerance > 0.0 && force_tolerance < 1.0))
    return fail("force_tolerance: expected in (0, 1)");
  if (!(displacement_tolerance > 0.0 && displacement_tolerance < 1.0))
    return fail("displacement_tolerance: expected in (0, 1)");
  return true;
}

WingTransient::WingTransient(SparseMatrix stiffness, SparseMatrix mass, const VonKarmanTerms& terms,
                             const DofPartition& part,
                             std::vector<Eigen::Vector3d> nodes_from_p2_W_m,
                             const WingTransientOptions& options)
    : terms_(terms), nodes_(std::move(nodes_from_p2_W_m)), options_(options) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("wing transient: " + why);
  n_ = terms.dofCount();
  if (stiffness.rows() != n_ || mass.rows() != n_ ||
      static_cast<int>(nodes_.size()) * kDofsPerNode != n_)
    throw std::invalid_argument("wing transient: K, M, the nodes and the mesh differ in size");
  free_ = part.retained();
  std::sort(free_.begin(), free_.end());
  if (free_.empty()) throw std::invalid_argument("wing transient: no free DOF");
  k_ff_ = extractBlock(stiffness, free_, free_);
  m_ff_ = extractBlock(mass, free_, free_);
  m_full_ = std::move(mass);
  const auto nf = static_cast<Eigen::Index>(free_.size());
  u_ = Eigen::VectorXd::Zero(nf);
  v_ = Eigen::VectorXd::Zero(nf);
  a_ = Eigen::VectorXd::Zero(nf);
}

Eigen::VectorXd WingTransient::restrictToFree(const Eigen::VectorXd& full) const {
  Eigen::VectorXd r(static_cast<Eigen::Index>(free_.size()));
  for (std::size_t i = 0; i < free_.size(); ++i) r(static_cast<Eigen::Index>(i)) = full(free_[i]);
  return r;
}

Eigen::VectorXd WingTransient::expand(const Eigen::VectorXd& free) const {
  return expandRows(free, free_, n_);
}

Eigen::VectorXd WingTransient::displacement() const { return expand(u_); }
Eigen::VectorXd WingTransient::velocity() const { return expand(v_); }

double WingTransient::kineticEnergy() const { return 0.5 * v_.dot(m_ff_ * v_); }

double WingTransient::strainEnergy() const {
  return 0.5 * u_.dot(k_ff_ * u_) + terms_.energy(expand(u_));
}

Eigen::VectorXd WingTransient::frameInertia(const WingTransientLoads& loads,
                                            const Eigen::VectorXd& u_full,
                                            const Eigen::VectorXd& v_full) const {
  const Eigen::Vector3d w(loads.omega_x_radps, 0.0, 0.0), al(loads.alpha_x_radps2, 0.0, 0.0);
  Eigen::VectorXd acc = Eigen::VectorXd::Zero(n_);
  for (std::size_t p = 0; p < nodes_.size(); ++p) {
    const Eigen::Index d = static_cast<Eigen::Index>(p) * kDofsPerNode;
    const Eigen::Vector3d x = nodes_[p] + u_full.segment<3>(d);
    acc.segment<3>(d) = al.cross(x) + w.cross(w.cross(x)) + 2.0 * w.cross(v_full.segment<3>(d));
    acc.segment<3>(d + 3) = al;  // the rigid rotation's angular acceleration
  }
  return restrictToFree(m_full_ * acc);
}

Eigen::VectorXd WingTransient::nonInertial(const WingTransientLoads& loads, const Eigen::VectorXd& u,
                                           const Eigen::VectorXd& v, SparseMatrix* h_ff) const {
  const Eigen::VectorXd u_full = expand(u), v_full = expand(v);
  *h_ff = extractBlock(terms_.tangent(u_full), free_, free_);
  Eigen::VectorXd g = k_ff_ * u + restrictToFree(terms_.internalForce(u_full)) + c_ff_ * v +
                      frameInertia(loads, u_full, v_full);
  if (loads.force) g -= restrictToFree(*loads.force);
  if (loads.added_stiffness) g += restrictToFree(*loads.added_stiffness * u_full);
  if (loads.added_damping) g += restrictToFree(*loads.added_damping * v_full);
  return g;
}

void WingTransient::setState(const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                             const WingTransientLoads& loads, double start_step_s) {
  if (u.size() != n_ || v.size() != n_)
    throw std::invalid_argument("wing transient: the state must have 6n entries");
  u_ = restrictToFree(u);
  v_ = restrictToFree(v);
  relaxInPlane(loads);
  SparseMatrix h_ff = extractBlock(terms_.tangent(expand(u_)), free_, free_);
  c_ff_ = options_.damping_s * (k_ff_ + h_ff);
  g_ = nonInertial(loads, u_, v_, &h_ff);
  SparseMatrix mass = m_ff_;
  if (loads.added_mass) mass += extractBlock(*loads.added_mass, free_, free_);
  // The acceleration of the first implicit step rather than M^-1 of the imbalance: the skin's
  // rotations carry 1e-18 kg m^2 and any state not in equilibrium in them (a reduced wing's)
  // would start at 1e11 rad/s^2; with start_step_s > 0 the tangent bounds it (0: M^-1).
  if (start_step_s > 0.0) {
    const double beta_n = 0.25 * (1.0 - options_.hht_alpha) * (1.0 - options_.hht_alpha);
    mass += (beta_n * start_step_s * start_step_s) * (k_ff_ + h_ff);
  }
  if (!solveSparseSymmetric(mass, Eigen::VectorXd(-g_), &a_))
    throw std::runtime_error("wing transient: the mass over the free DOFs is singular");
}

void WingTransient::relaxInPlane(const WingTransientLoads& loads) {
  // The in-plane DOFs (u, v, theta_z) of the free set, in the order of free_.
  std::vector<int> in_plane;
  for (std::size_t i = 0; i < free_.size(); ++i) {
    const int d = free_[i] % kDofsPerNode;
    if (d == 0 || d == 1 || d == 5) in_plane.push_back(static_cast<int>(i));
  }
  if (in_plane.empty()) return;
  auto rows = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd r(static_cast<Eigen::Index>(in_plane.size()));
    for (std::size_t i = 0; i < in_plane.size(); ++i) r(static_cast<Eigen::Index>(i)) = x(in_plane[i]);
    return r;
  };
  const Eigen::VectorXd f = loads.force ? restrictToFree(*loads.force)
                                        : Eigen::VectorXd::Zero(u_.size());
  Eigen::VectorXd du;
  SparseMatrix k_pp;
  // Displacement: the static equilibrium of the in-plane rows (Newton; the members' transverse
  // stretch makes it nonlinear in the in-plane DOFs).
  for (int it = 0; it < options_.max_newton_iterations; ++it) {
    const Eigen::VectorXd u_full = expand(u_);
    const SparseMatrix k_t = k_ff_ + extractBlock(terms_.tangent(u_full), free_, free_);
    k_pp = extractBlock(k_t, in_plane, in_plane);
    const Eigen::VectorXd r = k_ff_ * u_ + restrictToFree(terms_.internalForce(u_full)) +
                              frameInertia(loads, u_full, expand(v_)) - f;
    if (!solveSparseSymmetric(k_pp, Eigen::VectorXd(-rows(r)), &du))
      throw std::runtime_error("wing transient: the in-plane stiffness is singular");
    for (std::size_t i = 0; i < in_plane.size(); ++i) u_(in_plane[i]) += du(static_cast<Eigen::Index>(i));
    if (du.norm() <= options_.displacement_tolerance * std::max(u_.norm(), 1e-300)) break;
  }
  // Velocity: the rate of that equilibrium, (K + H)_pp v_p = -[(K + H) v]_p with v_p from zero.
  const SparseMatrix k_t = k_ff_ + extractBlock(terms_.tangent(expand(u_)), free_, free_);
  for (int i : in_plane) v_(i) = 0.0;
  if (!solveSparseSymmetric(k_pp, Eigen::VectorXd(-rows(k_t * v_)), &du))
    throw std::runtime_error("wing transient: the in-plane stiffness is singular");
  for (std::size_t i = 0; i < in_plane.size(); ++i) v_(in_plane[i]) = du(static_cast<Eigen::Index>(i));
}

WingTransient::StepReport WingTransient::step(double h, const WingTransientLoads& loads) {
  if (!(h > 0.0)) throw std::invalid_argument("wing transient: the step must be positive");
  StepReport rep;
  SparseMatrix mass = m_ff_;
  if (loads.added_mass) mass += extractBlock(*loads.added_mass, free_, free_);
  // Hilber-Hughes-Taylor: (M + A) a_{n+1} + (1 + alpha) g_{n+1} - alpha g_n = 0 with Newmark's
  // gamma = 1/2 - alpha, beta_N = (1 - alpha)^2 / 4.
  const double al = options_.hht_alpha;
  const double gamma = 0.5 - al, beta_n = 0.25 * (1.0 - al) * (1.0 - al);
  const double c_a = 1.0 / (beta_n * h * h), c_v = gamma / (beta_n * h);
  const Eigen::VectorXd base = u_ + h * v_ + h * h * (0.5 - beta_n) * a_;
  Eigen::VectorXd u = u_ + h * v_;  // predictor (not with a_: see setState)
  // The frame terms' derivative, M (alpha^ + omega^2 S^2 + 2 c_v omega^) with S = e_x x (.) on the
  // translations: small against c_a M for the mass's own DOF, but the Coriolis force couples the
  // large in-plane Newton corrections of a relaxing membrane into the out-of-plane rows (without
  // it: a 13 % wrong Newton matrix there and a stalled line search, measured on the EFW).
  SparseMatrix frame_jacobian(static_cast<Eigen::Index>(free_.size()),
                              static_cast<Eigen::Index>(free_.size()));
  if (loads.omega_x_radps != 0.0 || loads.alpha_x_radps2 != 0.0) {
    const double w = loads.omega_x_radps;
    std::vector<Eigen::Triplet<double>> t;
    for (std::size_t p = 0; p < nodes_.size(); ++p) {
      const int y = static_cast<int>(p) * kDofsPerNode + 1, z = y + 1;
      // (alpha + 2 c_v omega) S + omega^2 S^2: S e_y = e_z, S e_z = -e_y, S^2 = -1 on (y, z).
      const double skew = loads.alpha_x_radps2 + 2.0 * c_v * w;
      t.emplace_back(z, y, skew);
      t.emplace_back(y, z, -skew);
      t.emplace_back(y, y, -w * w);
      t.emplace_back(z, z, -w * w);
    }
    SparseMatrix op(n_, n_);
    op.setFromTriplets(t.begin(), t.end());
    frame_jacobian = extractBlock(SparseMatrix(m_full_ * op), free_, free_);
  }
  Eigen::VectorXd a, v, g, du;
  SparseMatrix h_ff;
  for (int it = 0; it < options_.max_newton_iterations; ++it) {
    a = c_a * (u - base);
    v = v_ + h * ((1.0 - gamma) * a_ + gamma * a);
    g = nonInertial(loads, u, v, &h_ff);
    const Eigen::VectorXd inertia = mass * a;
    const Eigen::VectorXd r = inertia + (1.0 + al) * g - al * g_;
    const double scale = std::max({inertia.norm(), g.norm(), g_.norm()});
    // An absolute floor for an unloaded start (a residual at round-off of zero loads).
    rep.residual_ratio = r.norm() / std::max(scale, options_.force_floor_n / options_.force_tolerance);
    if (rep.residual_ratio <= options_.force_tolerance) {
      rep.converged = true;
      break;
    }
    SparseMatrix jac = c_a * mass + (1.0 + al) * (c_v * c_ff_ + k_ff_ + h_ff);
    if (frame_jacobian.nonZeros() > 0) jac += (1.0 + al) * frame_jacobian;
    if (loads.added_stiffness) jac += (1.0 + al) * extractBlock(*loads.added_stiffness, free_, free_);
    if (loads.added_damping)
      jac += ((1.0 + al) * c_v) * extractBlock(*loads.added_damping, free_, free_);
    const bool symmetric =
        !loads.added_stiffness && !loads.added_damping && frame_jacobian.nonZeros() == 0;
    if (!(symmetric ? solveSparseSymmetric(jac, Eigen::VectorXd(-r), &du)
                    : solveSparseGeneral(jac, Eigen::VectorXd(-r), &du))) {
      rep.message = "the Newton matrix is singular";
      return rep;
    }
    // Backtracking on the residual: a slack skin has almost no tangent stiffness out of its
    // plane (a film's bending and the inertia of 1e-8 kg nodes), so a full Newton step from a
    // state off equilibrium can be orders of magnitude too long (the membrane stiffens with the
    // cube of the deflection).
    double lambda = 1.0;
    const double r_norm = r.norm();
    for (int halving = 0; halving < 30; ++halving) {
      const Eigen::VectorXd trial = u + lambda * du;
      const Eigen::VectorXd a_t = c_a * (trial - base);
      const Eigen::VectorXd v_t = v_ + h * ((1.0 - gamma) * a_ + gamma * a_t);
      SparseMatrix h_t;
      const Eigen::VectorXd r_t =
          mass * a_t + (1.0 + al) * nonInertial(loads, trial, v_t, &h_t) - al * g_;
      if (r_t.norm() < r_norm) break;
      lambda *= 0.5;
    }
    du *= lambda;
    u += du;
    ++rep.newton_iterations;
    if (du.norm() <= options_.displacement_tolerance * std::max(u.norm(), 1e-300)) {
      a = c_a * (u - base);
      v = v_ + h * ((1.0 - gamma) * a_ + gamma * a);
      g = nonInertial(loads, u, v, &h_ff);
      rep.converged = true;
      break;
    }
  }
  if (!rep.converged) {
    rep.message = "Newton did not converge in " + std::to_string(rep.newton_iterations) +
                  " iterations (residual " + std::to_string(rep.residual_ratio) + ")";
    return rep;
  }
  u_ = u;
  v_ = v;
  a_ = a;
  g_ = g;
  c_ff_ = options_.damping_s * (k_ff_ + h_ff);  // the next step's damping: the tangent here
  return rep;
}

}  // namespace orni::structure
