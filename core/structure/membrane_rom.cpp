// Condensed membrane stiffness of the modal wing (membrane_rom.hpp, docs/theory.md 4.7).
#include "core/structure/membrane_rom.hpp"
#include "core/model/invariant.hpp"
#include "core/structure/product_blocking.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

namespace orni::structure {
namespace {

using Vec2 = Eigen::Vector2d;

// Pair products Q_p = q_i q_j.
void pairProducts(const ModalMembraneStiffness& m, const Eigen::VectorXd& q, Eigen::VectorXd* out) {
  for (int p = 0; p < m.pairCount(); ++p) {
    const auto& ij = m.pairs[static_cast<std::size_t>(p)];
    (*out)(p) = q(ij[0]) * q(ij[1]);
  }
}

// G (R x P) with C ~ G^T G: the diagonally pivoted Cholesky factorisation of A C A (A =
// diag(amplitude)), stopped when the largest remaining diagonal is at most `tolerance` times the
// largest diagonal of A C A, with every kept column divided back by A. With tolerance 0 it runs to
// the numerical rank (a remaining diagonal below 1e-13 of the largest: round-off of a positive
// semi-definite C). The remainder is the Schur complement of the pivots: positive semi-definite.
Eigen::MatrixXd pivotedStrainFactor(const Eigen::MatrixXd& c, const Eigen::VectorXd& amplitude,
                                    double tolerance) {
  const auto n = c.rows();
  const Eigen::MatrixXd a = amplitude.asDiagonal() * c * amplitude.asDiagonal();
  Eigen::VectorXd d = a.diagonal().cwiseMax(0.0);
  const double d_max = d.size() > 0 ? d.maxCoeff() : 0.0;
  const double stop = std::max(tolerance, 1e-13) * d_max;
  Eigen::MatrixXd l = Eigen::MatrixXd::Zero(n, n);  // columns: the kept directions
  std::vector<bool> pivoted(static_cast<std::size_t>(n), false);
  Eigen::Index r = 0;
  for (; r < n; ++r) {
    Eigen::Index piv = -1;
    double best = stop;
    for (Eigen::Index i = 0; i < n; ++i)
      if (!pivoted[static_cast<std::size_t>(i)] && d(i) > best) {
        best = d(i);
        piv = i;
      }
    if (piv < 0) break;
    pivoted[static_cast<std::size_t>(piv)] = true;
    Eigen::VectorXd col = a.col(piv);
    if (r > 0) col.noalias() -= l.leftCols(r) * l.row(piv).head(r).transpose();
    col /= std::sqrt(best);
    for (Eigen::Index i = 0; i < n; ++i)
      if (pivoted[static_cast<std::size_t>(i)] && i != piv) col(i) = 0.0;  // round-off
    l.col(r) = col;
    d -= col.cwiseAbs2();
    d(piv) = 0.0;
  }
  Eigen::MatrixXd g = l.leftCols(r).transpose();  // R x P, of A C A
  for (Eigen::Index p = 0; p < n; ++p) g.col(p) /= amplitude(p);
  return g;
}

// z = C x (P), through G when factored (strain = G x, R entries of scratch).
void applyPairStiffness(const ModalMembraneStiffness& m, const Eigen::VectorXd& x,
                        Eigen::VectorXd* strain, Eigen::VectorXd* z) {
  if (m.factored()) {
    strain->noalias() = m.strain_factor * x;
    z->noalias() = m.strain_factor.transpose() * *strain;
  } else {
    z->noalias() = m.pair_stiffness * x;
  }
}

// S of ModalMembraneStiffness::hessian_pairs from C. The Hessian of V = 1/2 Q^T C Q is
//   d2V/dq_a dq_b = sum_p z_p d2Q_p/dq_a dq_b + (J^T C J)_ab,   z = C Q,
// with d2Q_p/dq_a dq_b = 1 for p = (a, b), a != b, and 2 for p = (a, a), and J_(a,j),a = w q_j
// (w = 2 for j = a, else 1), so (J^T C J)_ab = sum_j sum_l w_aj w_bl C_(a,j),(b,l) q_j q_l; the
// coefficient of Q_(k,l) collects (j, l) = (k, l) and, for k != l, (l, k).
Eigen::MatrixXd pairHessian(const std::vector<std::array<int, 2>>& pairs, int m,
                            const Eigen::MatrixXd& c) {
  const auto np = static_cast<int>(pairs.size());
  std::vector<int> index(static_cast<std::size_t>(m) * m);
  for (int p = 0; p < np; ++p) {
    const auto& ij = pairs[static_cast<std::size_t>(p)];
    index[static_cast<std::size_t>(ij[0] * m + ij[1])] = p;
    index[static_cast<std::size_t>(ij[1] * m + ij[0])] = p;
  }
  const auto pair = [&](int i, int j) { return index[static_cast<std::size_t>(i * m + j)]; };
  const auto w = [](int i, int j) { return i == j ? 2.0 : 1.0; };
  Eigen::MatrixXd s(np, np);
  for (int r = 0; r < np; ++r) {
    const auto& ab = pairs[static_cast<std::size_t>(r)];
    const int a = ab[0], b = ab[1];
    for (int t = 0; t < np; ++t) {
      const auto& kl = pairs[static_cast<std::size_t>(t)];
      const int k = kl[0], l = kl[1];
      double v = w(a, b) * c(r, t);
      v += w(a, k) * w(b, l) * c(pair(a, k), pair(b, l));
      if (k != l) v += w(a, l) * w(b, k) * c(pair(a, l), pair(b, k));
      s(r, t) = v;
    }
  }
  return s;
}

// f_r += scale sum_p z_p dQ_p/dq_r, dQ_p/dq_r = delta_ir q_j + delta_jr q_i.
void addPairForce(const ModalMembraneStiffness& m, const Eigen::VectorXd& q,
                  const Eigen::VectorXd& z, double scale, Eigen::VectorXd* f) {
  for (int p = 0; p < m.pairCount(); ++p) {
    const auto& ij = m.pairs[static_cast<std::size_t>(p)];
    const double zp = scale * z(p);
    (*f)(ij[0]) += zp * q(ij[1]);
    (*f)(ij[1]) += zp * q(ij[0]);
  }
}

/// Column blocks start at multiples of this: Eigen's matrix-product kernel takes the result's
/// columns in panels of 4 (AVX2; 8 with AVX-512) and the last few of a block by another path, so
/// only blocks that start on a panel boundary give every column the arithmetic of the whole
/// product (measured: blocks of 46 columns moved C's last bits, blocks of 48 did not).
constexpr Eigen::Index kColumnBlockAlignment = 24;

/// f(begin, count) over the columns [0, cols) in at most `threads` contiguous blocks, each on its
/// own thread (the first on this one); f must write only its own columns.
template <class F>
void forColumnBlocks(int threads, Eigen::Index cols, const F& f) {
  const Eigen::Index wanted = std::max<Eigen::Index>(1, std::min<Eigen::Index>(threads, cols));
  const Eigen::Index per =
      ((cols + wanted - 1) / wanted + kColumnBlockAlignment - 1) / kColumnBlockAlignment *
      kColumnBlockAlignment;
  const Eigen::Index blocks = (cols + per - 1) / per;
  if (blocks <= 1) {
    f(Eigen::Index{0}, cols);
    return;
  }
  std::vector<std::thread> pool;
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(blocks));
  for (Eigen::Index b = 1; b < blocks; ++b) {
    const Eigen::Index begin = std::min(cols, b * per), count = std::min(cols, begin + per) - begin;
    pool.emplace_back([&f, &errors, b, begin, count] {
      try {
        f(begin, count);
      } catch (...) {
        errors[static_cast<std::size_t>(b)] = std::current_exception();
      }
    });
  }
  try {
    f(Eigen::Index{0}, std::min(cols, per));
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

int condensationThreads(int asked) {
  if (asked > 0) return asked;
  const unsigned cores = std::thread::hardware_concurrency();
  return static_cast<int>(std::clamp(cores, 1u, 4u));
}

}  // namespace

double ModalMembraneStiffness::energy(const Eigen::VectorXd& q, Workspace* ws) const {
  if (empty()) return 0.0;
  ws->holds_evaluation = false;  // z is overwritten
  pairProducts(*this, q, &ws->products);
  applyPairStiffness(*this, ws->products, &ws->strain, &ws->z);
  return 0.5 * ws->products.dot(ws->z);
}

void ModalMembraneStiffness::addForce(const Eigen::VectorXd& q, Workspace* ws,
                                      Eigen::VectorXd* f, double scale) const {
  if (empty()) return;
  ws->holds_evaluation = false;  // z is overwritten
  pairProducts(*this, q, &ws->products);
  applyPairStiffness(*this, ws->products, &ws->strain, &ws->z);
  addPairForce(*this, q, ws->z, scale, f);
}

double ModalMembraneStiffness::addForce(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot,
                                        double beta_s, Workspace* ws, Eigen::VectorXd* f,
                                        double scale) const {
  if (empty()) return 0.0;
  for (int p = 0; p < pairCount(); ++p) {
    const auto& ij = pairs[static_cast<std::size_t>(p)];
    ws->rates(p) = q_dot(ij[0]) * q(ij[1]) + q(ij[0]) * q_dot(ij[1]);
    ws->products(p) = q(ij[0]) * q(ij[1]) + beta_s * ws->rates(p);  // Q + beta Q'
  }
  applyPairStiffness(*this, ws->products, &ws->strain, &ws->z);  // one pass over C or G
  ws->evaluated_q = q;
  ws->evaluated_q_dot = q_dot;
  ws->evaluated_beta_s = beta_s;
  ws->holds_evaluation = true;
  addPairForce(*this, q, ws->z, scale, f);
  return ws->rates.dot(ws->z);
}

bool ModalMembraneStiffness::addForceEvaluatedIn(const Workspace& evaluated,
                                                 const Eigen::VectorXd& q,
                                                 const Eigen::VectorXd& q_dot, double beta_s,
                                                 Eigen::VectorXd* f, double scale) const {
  if (empty()) return true;
  if (!evaluated.holds_evaluation || evaluated.evaluated_beta_s != beta_s ||
      evaluated.evaluated_q != q || evaluated.evaluated_q_dot != q_dot)
    return false;
  addPairForce(*this, q, evaluated.z, scale, f);
  return true;
}

ModalMembraneStiffness::Rates ModalMembraneStiffness::rates(const Eigen::VectorXd& q,
                                                            const Eigen::VectorXd& q_dot,
                                                            double beta_s, Workspace* ws) const {
  Rates r;
  if (empty()) return r;
  ws->holds_evaluation = false;  // z is overwritten
  for (int p = 0; p < pairCount(); ++p) {
    const auto& ij = pairs[static_cast<std::size_t>(p)];
    ws->rates(p) = q_dot(ij[0]) * q(ij[1]) + q(ij[0]) * q_dot(ij[1]);
    ws->products(p) = q(ij[0]) * q(ij[1]);
  }
  applyPairStiffness(*this, ws->products, &ws->strain, &ws->z);
  r.strain_energy_rate_W = ws->rates.dot(ws->z);
  applyPairStiffness(*this, ws->rates, &ws->strain_rate, &ws->z);
  r.dissipation_W = beta_s * ws->rates.dot(ws->z);
  return r;
}

void ModalMembraneStiffness::tangentParts(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot,
                                          double beta_s, TangentWorkspace* ws,
                                          Eigen::MatrixXd* gauss_newton,
                                          Eigen::MatrixXd* rest) const {
  gauss_newton->setZero();
  rest->setZero();
  if (empty()) return;
  const int np = pairCount();
  const bool damped = beta_s != 0.0;
  for (int p = 0; p < np; ++p) {  // Q + beta Q'
    const auto& ij = pairs[static_cast<std::size_t>(p)];
    ws->products(p) = q(ij[0]) * q(ij[1]);
    if (damped) ws->products(p) += beta_s * (q_dot(ij[0]) * q(ij[1]) + q(ij[0]) * q_dot(ij[1]));
  }
  applyPairStiffness(*this, ws->products, &ws->strain, &ws->z);
  // X J(v) with X = C or G, column by column from J's two entries per row: J(v)(p, i) = v_j,
  // J(v)(p, j) = v_i (2 v_i when i = j), i.e. 2 P rows(X) multiply-adds instead of the dense
  // P rows(X) M; J(q) and, damped, J(q') (dQ'/dq = J(q')).
  const Eigen::MatrixXd& x = factored() ? strain_factor : pair_stiffness;
  ws->jac.setZero();
  if (damped) ws->jac_rate.setZero();
  for (int p = 0; p < np; ++p) {
    const auto& ij = pairs[static_cast<std::size_t>(p)];
    const auto c = x.col(p);
    ws->jac.col(ij[0]).noalias() += q(ij[1]) * c;
    ws->jac.col(ij[1]).noalias() += q(ij[0]) * c;
    if (damped) {
      ws->jac_rate.col(ij[0]).noalias() += (beta_s * q_dot(ij[1])) * c;
      ws->jac_rate.col(ij[1]).noalias() += (beta_s * q_dot(ij[0])) * c;
    }
  }
  if (factored()) {  // J^T C J = (G J)^T (G J), beta J^T C J(q') = (G J)^T (beta G J(q'))
    gauss_newton->noalias() = ws->jac.transpose() * ws->jac;
    if (damped) rest->noalias() = ws->jac.transpose() * ws->jac_rate;
  }
  for (int p = 0; p < np; ++p) {  // dense: J^T (C J) from J's two entries per row
    const auto& ij = pairs[static_cast<std::size_t>(p)];
    if (!factored()) {
      gauss_newton->row(ij[0]).noalias() += q(ij[1]) * ws->jac.row(p);
      gauss_newton->row(ij[1]).noalias() += q(ij[0]) * ws->jac.row(p);
      if (damped) {
        rest->row(ij[0]).noalias() += q(ij[1]) * ws->jac_rate.row(p);
        rest->row(ij[1]).noalias() += q(ij[0]) * ws->jac_rate.row(p);
      }
    }
    (*rest)(ij[0], ij[1]) += ws->z(p);  // sum_p z_p d2Q_p/dq2
    (*rest)(ij[1], ij[0]) += ws->z(p);
  }
}

void ModalMembraneStiffness::newtonParts(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot,
                                         double beta_s, TangentWorkspace* ws,
                                         Eigen::MatrixXd* stiffness,
                                         Eigen::MatrixXd* damping,
                                         Workspace* evaluation) const {
  if (empty()) {
    stiffness->setZero();
    damping->setZero();
    return;
  }
  if (hessian_pairs.size() == 0)
    throw std::logic_error("ModalMembraneStiffness::newtonParts: no pair Hessian (factored C)");
  const int np = pairCount();
  for (int p = 0; p < np; ++p) {
    const auto& ij = pairs[static_cast<std::size_t>(p)];
    ws->products_and_rates(p, 0) = q(ij[0]) * q(ij[1]);
    ws->products_and_rates(p, 1) = q_dot(ij[0]) * q(ij[1]) + q(ij[0]) * q_dot(ij[1]);
  }
  for (int c = 0; c < 2; ++c) {  // z0 = C Q, z1 = C Q'; S Q, S Q' (matrix-vector products:
                                 // a product with two columns would pack C and S each time)
    ws->pair_stress.col(c).noalias() = pair_stiffness * ws->products_and_rates.col(c);
    ws->pair_hessian.col(c).noalias() = hessian_pairs * ws->products_and_rates.col(c);
  }
  const double half_beta = 0.5 * beta_s;
  for (int p = 0; p < np; ++p) {
    const auto& ij = pairs[static_cast<std::size_t>(p)];
    const double diag = ij[0] == ij[1] ? 2.0 : 1.0;  // d2Q_p/dq_i dq_j
    const double h = ws->pair_hessian(p, 0);
    const double k = h + half_beta * (ws->pair_hessian(p, 1) + diag * ws->pair_stress(p, 1));
    const double d = beta_s * (h - diag * ws->pair_stress(p, 0));
    (*stiffness)(ij[0], ij[1]) = k;
    (*stiffness)(ij[1], ij[0]) = k;
    (*damping)(ij[0], ij[1]) = d;
    (*damping)(ij[1], ij[0]) = d;
  }
  if (evaluation != nullptr) {
    evaluation->z = ws->pair_stress.col(0) + beta_s * ws->pair_stress.col(1);
    evaluation->evaluated_q = q;
    evaluation->evaluated_q_dot = q_dot;
    evaluation->evaluated_beta_s = beta_s;
    evaluation->holds_evaluation = true;
  }
}

Eigen::MatrixXd ModalMembraneStiffness::tangent(const Eigen::VectorXd& q) const {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(mode_count, mode_count);
  if (empty()) return k;
  TangentWorkspace ws(*this);
  Eigen::MatrixXd rest(mode_count, mode_count);
  tangentParts(q, Eigen::VectorXd::Zero(mode_count), 0.0, &ws, &k, &rest);
  k += rest;
  return k;
}

Eigen::VectorXd ModalMembraneStiffness::membraneDisplacement(const Eigen::VectorXd& q) const {
  ORNI_DEMAND(relaxation.cols() == pairCount(),
              "membraneDisplacement: the relaxation shapes were not kept");
  Eigen::VectorXd products(pairCount());
  pairProducts(*this, q, &products);
  return relaxation * products;
}

ModalMembraneStiffness modalMembraneStiffness(const VonKarmanTerms& terms,
                                              const SparseMatrix& stiffness,
                                              const DofPartition& part,
                                              const std::vector<Vec3>& nodes_W_m,
                                              const Eigen::MatrixXd& shapes,
                                              const MembraneCondensationOptions& options) {
  planProductsWithFixedCacheSizes();  // the same bits on every CPU (docs/theory.md 3.7)
  const int n = terms.dofCount();
  const auto m = static_cast<int>(shapes.cols());
  if (shapes.rows() != n || stiffness.rows() != n ||
      static_cast<int>(nodes_W_m.size()) * kDofsPerNode != n)
    throw std::invalid_argument("membrane stiffness: shapes, K and the mesh differ in size");
  ModalMembraneStiffness out;
  if (m == 0) return out;
  // A flat wing only: the condensation rests on K not coupling in-plane and out-of-plane DOFs.
  double extent = 0.0, height = 0.0;
  for (const Vec3& x : nodes_W_m) {
    extent = std::max(extent, (x - nodes_W_m.front()).norm());
    height = std::max(height, std::abs(x.z() - nodes_W_m.front().z()));
  }
  if (height > 1e-12 * extent)
    throw std::invalid_argument(
        "membrane stiffness: the wing is not flat (the condensation needs the in-plane and the "
        "out-of-plane DOFs uncoupled)");
  out.mode_count = m;
  for (int i = 0; i < m; ++i)
    for (int j = i; j < m; ++j) out.pairs.push_back({i, j});
  const int np = out.pairCount();

  // Element strain coefficients h_p per pair, weighted so that A = H^T H, and the in-plane
  // nodal loads F_p = sum_e w_e B_e^T D_e h_p.
  const std::vector<VonKarmanTerms::Facet>& facets = terms.facets();
  const std::vector<VonKarmanTerms::Member>& members = terms.members();
  const Mat3& c = terms.membraneStiffness();
  const auto nf = static_cast<Eigen::Index>(facets.size());
  const auto nb = static_cast<Eigen::Index>(members.size());
  Eigen::MatrixXd h_weighted(3 * nf + nb, np);
  Eigen::MatrixXd loads = Eigen::MatrixXd::Zero(n, np);
  Mat3 c_chol_t = Mat3::Zero();  // L^T of C = L L^T (C = 0 without skin)
  if (nf > 0) c_chol_t = Eigen::LLT<Mat3>(c).matrixU();
  Eigen::Matrix<double, 2, Eigen::Dynamic> g(2, m);
  for (Eigen::Index e = 0; e < nf; ++e) {
    const VonKarmanTerms::Facet& f = facets[static_cast<std::size_t>(e)];
    Eigen::Matrix<double, 3, Eigen::Dynamic> w(3, m);
    for (int a = 0; a < 3; ++a)
      w.row(a) = f.triad.row(2) * shapes.middleRows<3>(globalDof(f.nodes[static_cast<std::size_t>(a)], kU));
    g.noalias() = f.grad * w;
    const double sqrt_area = std::sqrt(f.area_m2);
    for (int p = 0; p < np; ++p) {
      const int i = out.pairs[static_cast<std::size_t>(p)][0];
      const int j = out.pairs[static_cast<std::size_t>(p)][1];
      Vec3 h(g(0, i) * g(0, j), g(1, i) * g(1, j), g(0, i) * g(1, j) + g(1, i) * g(0, j));
      if (i == j) h *= 0.5;
      h_weighted.block<3, 1>(3 * e, p) = sqrt_area * (c_chol_t * h);
      const Eigen::Matrix<double, 6, 1> f_d = f.area_m2 * (f.b_m.transpose() * (c * h));
      for (int a = 0; a < 3; ++a)
        loads.block<3, 1>(globalDof(f.nodes[static_cast<std::size_t>(a)], kU), p) +=
            f.triad.row(0).transpose() * f_d(2 * a) + f.triad.row(1).transpose() * f_d(2 * a + 1);
    }
  }
  Eigen::Matrix<double, 3, Eigen::Dynamic> s(3, m);
  for (Eigen::Index e = 0; e < nb; ++e) {
    const VonKarmanTerms::Member& b = members[static_cast<std::size_t>(e)];
    const Mat3 proj = Mat3::Identity() - b.axis * b.axis.transpose();
    s.noalias() = proj * (shapes.middleRows<3>(globalDof(b.nodes[1], kU)) -
                          shapes.middleRows<3>(globalDof(b.nodes[0], kU))) /
                  b.length_m;
    const double sqrt_w = std::sqrt(b.axial_stiffness_n * b.length_m);
    for (int p = 0; p < np; ++p) {
      const int i = out.pairs[static_cast<std::size_t>(p)][0];
      const int j = out.pairs[static_cast<std::size_t>(p)][1];
      const double h = (i == j ? 0.5 : 1.0) * s.col(i).dot(s.col(j));
      h_weighted(3 * nf + e, p) = sqrt_w * h;
      const Vec3 f_axial = b.axial_stiffness_n * h * b.axis;
      loads.block<3, 1>(globalDof(b.nodes[1], kU), p) += f_axial;
      loads.block<3, 1>(globalDof(b.nodes[0], kU), p) -= f_axial;
    }
  }
  // C = H^T H by column blocks (the same bits for any count: each entry is the same dot product
  // over the same depth blocking, which depends on the depth alone).
  const int threads = condensationThreads(options.threads);
  Eigen::MatrixXd cmat(np, np);
  forColumnBlocks(threads, np, [&](Eigen::Index begin, Eigen::Index count) {
    cmat.middleCols(begin, count).noalias() =
        h_weighted.transpose() * h_weighted.middleCols(begin, count);
  });

  // In-plane relaxation: K_mm U = -F over the retained in-plane DOFs (u, v, theta_z).
  std::vector<int> in_plane;
  for (int d : part.retained()) {
    const int slot = d % kDofsPerNode;
    if (slot == kU || slot == kV || slot == kThetaZ) in_plane.push_back(d);
  }
  std::sort(in_plane.begin(), in_plane.end());
  if (!in_plane.empty()) {
    const SparseMatrix k_mm = extractBlock(stiffness, in_plane, in_plane);
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(k_mm);
    if (ldlt.info() != Eigen::Success)
      throw std::runtime_error("membrane stiffness: the in-plane stiffness is singular");
    Eigen::MatrixXd f_free(static_cast<Eigen::Index>(in_plane.size()), np);
    for (std::size_t r = 0; r < in_plane.size(); ++r)
      f_free.row(static_cast<Eigen::Index>(r)) = loads.row(in_plane[r]);
    // One back-substitution per pair, by column blocks (each column's arithmetic is its own).
    Eigen::MatrixXd u_free(f_free.rows(), np), relax(np, np);
    forColumnBlocks(threads, np, [&](Eigen::Index begin, Eigen::Index count) {
      u_free.middleCols(begin, count) = -ldlt.solve(f_free.middleCols(begin, count));
    });
    if (!u_free.allFinite())
      throw std::runtime_error("membrane stiffness: the in-plane solve failed");
    // C += U^T F (negative semi-definite: the membrane relaxes).
    forColumnBlocks(threads, np, [&](Eigen::Index begin, Eigen::Index count) {
      relax.middleCols(begin, count).noalias() =
          u_free.transpose() * f_free.middleCols(begin, count);
    });
    cmat += 0.5 * (relax + relax.transpose());
    if (options.keep_relaxation) out.relaxation = expandRows(u_free, in_plane, n);
  }
  cmat = (0.5 * (cmat + cmat.transpose())).eval();  // eval: cmat.transpose() aliases cmat
  Eigen::VectorXd pair_amplitude = Eigen::VectorXd::Ones(np);
  double tolerance = 0.0;
  if (options.mode_amplitude.size() > 0) {
    if (options.mode_amplitude.size() != m || !(options.mode_amplitude.array() > 0.0).all() ||
        !(options.rank_tolerance >= 0.0 && options.rank_tolerance < 1.0))
      throw std::invalid_argument(
          "membrane stiffness: mode amplitudes must be positive, one per mode, and the rank "
          "tolerance in [0, 1)");
    for (int p = 0; p < np; ++p) {
      const auto& ij = out.pairs[static_cast<std::size_t>(p)];
      pair_amplitude(p) = options.mode_amplitude(ij[0]) * options.mode_amplitude(ij[1]);
    }
    tolerance = options.rank_tolerance;
  }
  if (options.storage == MembraneStorage::kDense) {
    out.pair_stiffness = std::move(cmat);
    out.hessian_pairs = pairHessian(out.pairs, m, out.pair_stiffness);
    return out;
  }
  Eigen::MatrixXd factor = pivotedStrainFactor(cmat, pair_amplitude, tolerance);
  // A factor of no rows (C = 0: the modes stretch nothing) is kept as the dense zero C, which
  // factored() can tell from it, whatever the storage asked for.
  if (factor.rows() == 0 ||
      (options.storage == MembraneStorage::kCheaper && 2 * factor.rows() >= np)) {
    out.pair_stiffness = std::move(cmat);
    out.hessian_pairs = pairHessian(out.pairs, m, out.pair_stiffness);
  } else
    out.strain_factor = std::move(factor);
  return out;
}

bool solveModalStatic(const Eigen::VectorXd& stiffness_diagonal,
                      const ModalMembraneStiffness& membrane, const Eigen::VectorXd& modal_load,
                      Eigen::VectorXd* q, int load_steps) {
  const auto m = modal_load.size();
  *q = Eigen::VectorXd::Zero(m);
  const double f_norm = modal_load.norm();
  if (f_norm == 0.0) return true;
  ModalMembraneStiffness::Workspace ws(membrane);
  auto residual = [&](const Eigen::VectorXd& x, double lambda) {
    Eigen::VectorXd r = stiffness_diagonal.cwiseProduct(x) - lambda * modal_load;
    membrane.addForce(x, &ws, &r);
    return r;
  };
  auto potential = [&](const Eigen::VectorXd& x, double lambda) {
    return 0.5 * x.dot(stiffness_diagonal.cwiseProduct(x)) + membrane.energy(x, &ws) -
           lambda * modal_load.dot(x);
  };
  for (int step = 1; step <= load_steps; ++step) {
    const double lambda = static_cast<double>(step) / load_steps;
    Eigen::VectorXd r = residual(*q, lambda);
    int it = 0;
    while (r.norm() > 1e-11 * lambda * f_norm) {
      if (++it > 200) return false;
      Eigen::MatrixXd k = membrane.tangent(*q);
      k.diagonal() += stiffness_diagonal;
      Eigen::VectorXd dq = k.ldlt().solve(-r);
      double slope = r.dot(dq);
      if (!(slope < 0.0)) {  // an indefinite tangent (compressed membrane): steepest descent
        dq = -r.cwiseQuotient(stiffness_diagonal);
        slope = r.dot(dq);
      }
      // Armijo backtracking on the potential (the residual grows with the cube of a long step).
      Eigen::VectorXd r_trial = residual(*q + dq, lambda);
      double alpha = 1.0;
      if (!(r_trial.norm() < r.norm())) {  // else the full step (see solveNonlinearStatic)
        const double pi0 = potential(*q, lambda);
        for (int h = 0; h < 40 && potential(*q + alpha * dq, lambda) > pi0 + 1e-4 * alpha * slope;
             ++h)
          alpha *= 0.5;
        r_trial = residual(*q + alpha * dq, lambda);
      }
      *q += alpha * dq;
      r = r_trial;
    }
  }
  return q->allFinite();
}

}  // namespace orni::structure
