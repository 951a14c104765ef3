// Von Karman strain terms of the wing and the nonlinear static solve (docs/theory.md 4.7).
#include "core/structure/von_karman.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/structure/beam_element.hpp"
#include "core/structure/corotational.hpp"
#include "core/structure/geometric_stiffness.hpp"
#include "core/structure/product_blocking.hpp"
#include "core/structure/shell_element.hpp"
#include "core/structure/skin_pretension.hpp"
#include "core/structure/sparse_solve.hpp"

namespace orni::structure {
namespace {

using Vec2 = Eigen::Vector2d;
using Triplet = Eigen::Triplet<double, int>;
using Mat9 = Eigen::Matrix<double, 9, 9>;
using Vec9 = Eigen::Matrix<double, 9, 1>;

Mat3 planeStressStiffness(const ShellProperties& p) {
  const double nu = p.poisson_ratio;
  Mat3 c;
  c << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
  return (p.youngs_modulus_pa * p.thickness_m / (1.0 - nu * nu)) * c;
}

// Local translations of a facet's three nodes, per node (u, v, w) in the facet triad.
Vec9 facetLocal(const VonKarmanTerms::Facet& f, const Eigen::VectorXd& u) {
  Vec9 l;
  for (int a = 0; a < 3; ++a)
    l.segment<3>(3 * a) = f.triad * u.segment<3>(globalDof(f.nodes[static_cast<std::size_t>(a)], kU));
  return l;
}

// Membrane DOFs (u1 v1 u2 v2 u3 v3) and normal displacements (w1 w2 w3) of the local vector.
Eigen::Matrix<double, 6, 1> membraneDofs(const Vec9& l) {
  Eigen::Matrix<double, 6, 1> d;
  for (int a = 0; a < 3; ++a) d.segment<2>(2 * a) = l.segment<2>(3 * a);
  return d;
}
Vec3 normalDofs(const Vec9& l) { return Vec3(l(2), l(5), l(8)); }

Vec3 etaOf(const Vec2& g) { return Vec3(0.5 * g.x() * g.x(), 0.5 * g.y() * g.y(), g.x() * g.y()); }

// d eta / d grad(w): [[g_x, 0], [0, g_y], [g_y, g_x]].
Eigen::Matrix<double, 3, 2> etaJacobian(const Vec2& g) {
  Eigen::Matrix<double, 3, 2> j;
  j << g.x(), 0.0, 0.0, g.y(), g.y(), g.x();
  return j;
}

}  // namespace

VonKarmanTerms::VonKarmanTerms(const WingStructure& wing_structure, const WingMesh& mesh,
                               MemberStretch member_stretch, SkinMembrane skin_membrane,
                               const FilmLaw& film)
    : dof_count_(kDofsPerNode * mesh.nodeCount()), skin_membrane_(skin_membrane), film_(film) {
  if (skin_membrane == SkinMembrane::kTensionField) {
    std::string why;
    if (!film.IsValid(&why)) throw std::invalid_argument("von Karman terms: " + why);
    if (wing_structure.wing.skin.pretension_N_per_m != 0.0)
      throw std::invalid_argument(
          "von Karman terms: a tension-field skin with a pretension is not built (the shrunk "
          "film's strain is not measured from the flat mesh); set wing.skin.pretension_N_per_m "
          "= 0 or use the elastic membrane");
  }
  if (!mesh.triangles.empty()) {
    const ShellProperties skin = skinShellProperties(wing_structure);
    c_t_ = planeStressStiffness(skin);
    skin_nu_ = skin.poisson_ratio;
    skin_et_n_per_m_ = skin.youngs_modulus_pa * skin.thickness_m;
    facets_.reserve(mesh.triangles.size());
    for (const std::array<int, 3>& tri : mesh.triangles) {
      Facet f;
      f.nodes = tri;
      std::array<Vec3, 3> x;
      for (int a = 0; a < 3; ++a)
        x[static_cast<std::size_t>(a)] = mesh.nodes_W_m[static_cast<std::size_t>(tri[static_cast<std::size_t>(a)])];
      f.triad = shellTriad(x);
      std::array<Vec2, 3> xy;
      for (int a = 0; a < 3; ++a) {
        const Vec3 d = x[static_cast<std::size_t>(a)] - x[0];
        xy[static_cast<std::size_t>(a)] = Vec2(f.triad.row(0).dot(d), f.triad.row(1).dot(d));
      }
      f.b_m = cstStrainMatrix(xy);
      for (int a = 0; a < 3; ++a) {
        f.grad(0, a) = f.b_m(0, 2 * a);
        f.grad(1, a) = f.b_m(1, 2 * a + 1);
      }
      f.area_m2 = triangleArea(x);
      facets_.push_back(f);
    }
  }
  if (!mesh.beams.empty()) {
    const std::vector<BeamProperties> props = memberBeamProperties(wing_structure);
    members_.reserve(mesh.beams.size());
    for (const BeamElement& b : mesh.beams) {
      if (b.member < 0 || b.member >= static_cast<int>(props.size()))
        throw std::invalid_argument("von Karman terms: beam member index " +
                                    std::to_string(b.member) + " out of range");
      Member m;
      m.nodes = b.nodes;
      const Vec3 d = mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[1])] -
                     mesh.nodes_W_m[static_cast<std::size_t>(b.nodes[0])];
      m.length_m = d.norm();
      m.axis = d / m.length_m;
      m.transverse = member_stretch == MemberStretch::kOutOfPlaneOnly
                         ? Mat3(Vec3::UnitZ() * Vec3::UnitZ().transpose())
                         : Mat3(Mat3::Identity() - m.axis * m.axis.transpose());
      const BeamProperties& p = props[static_cast<std::size_t>(b.member)];
      m.axial_stiffness_n = p.youngs_modulus_pa * p.section.area_m2;
      members_.push_back(m);
    }
  }
}

std::vector<FilmState> VonKarmanTerms::facetStates(const Eigen::VectorXd& u) const {
  if (u.size() != dof_count_) throw std::invalid_argument("von Karman: displacement size");
  std::vector<FilmState> states(facets_.size(), FilmState::kTaut);
  if (skin_membrane_ != SkinMembrane::kTensionField) return states;
  for (std::size_t i = 0; i < facets_.size(); ++i) {
    const Facet& e = facets_[i];
    const Vec9 l = facetLocal(e, u);
    states[i] = skinLaw(e.b_m * membraneDofs(l) + etaOf(e.grad * normalDofs(l)),
                        FilmOutput::kEnergyAndStress)
                    .state;
  }
  return states;
}

RelaxedMembrane VonKarmanTerms::skinLaw(const Vec3& strain, FilmOutput output) const {
  if (skin_membrane_ == SkinMembrane::kTensionField)
    return relaxedMembrane(strain, skin_et_n_per_m_, skin_nu_, film_, output);
  RelaxedMembrane elastic;
  elastic.stress_n_per_m = c_t_ * strain;
  elastic.tangent_n_per_m = c_t_;
  elastic.energy_j_per_m2 = 0.5 * strain.dot(elastic.stress_n_per_m);
  return elastic;
}

Eigen::VectorXd VonKarmanTerms::internalForce(const Eigen::VectorXd& u) const {
  if (u.size() != dof_count_) throw std::invalid_argument("von Karman: displacement size");
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dof_count_);
  for (const Facet& e : facets_) {
    const Vec9 l = facetLocal(e, u);
    const Vec2 g = e.grad * normalDofs(l);
    const Vec3 eps0 = e.b_m * membraneDofs(l);
    const Vec3 eta = etaOf(g);
    const RelaxedMembrane law = skinLaw(eps0 + eta, FilmOutput::kEnergyAndStress);
    const Vec3& n_total = law.stress_n_per_m;
    // The linear part C eps0 is K's (CST): only the rest is added here (for the elastic law
    // exactly C eta, without the round-off of N - C eps0 when eta << eps0).
    const Vec3 n_beyond_linear =
        skin_membrane_ == SkinMembrane::kElastic ? Vec3(c_t_ * eta) : Vec3(n_total - c_t_ * eps0);
    const Eigen::Matrix<double, 6, 1> f_d = e.area_m2 * (e.b_m.transpose() * n_beyond_linear);
    Eigen::Matrix2d s;
    s << n_total(0), n_total(2), n_total(2), n_total(1);
    const Vec3 f_w = e.area_m2 * (e.grad.transpose() * (s * g));
    for (int a = 0; a < 3; ++a) {
      const Vec3 local(f_d(2 * a), f_d(2 * a + 1), f_w(a));
      f.segment<3>(globalDof(e.nodes[static_cast<std::size_t>(a)], kU)) += e.triad.transpose() * local;
    }
  }
  for (const Member& m : members_) {
    const Vec3 du = u.segment<3>(globalDof(m.nodes[1], kU)) - u.segment<3>(globalDof(m.nodes[0], kU));
    const double l = m.length_m;
    const Vec3 pdu = m.transverse * du;
    const double eta = 0.5 * pdu.squaredNorm() / (l * l);
    const double n_total = m.axial_stiffness_n * (m.axis.dot(du) / l + eta);
    const Vec3 fe = m.axial_stiffness_n * eta * m.axis + (n_total / l) * pdu;
    f.segment<3>(globalDof(m.nodes[1], kU)) += fe;
    f.segment<3>(globalDof(m.nodes[0], kU)) -= fe;
  }
  return f;
}

double VonKarmanTerms::energy(const Eigen::VectorXd& u) const {
  if (u.size() != dof_count_) throw std::invalid_argument("von Karman: displacement size");
  double pi = 0.0;
  for (const Facet& e : facets_) {
    const Vec9 l = facetLocal(e, u);
    const Vec3 eta = etaOf(e.grad * normalDofs(l));
    const Vec3 eps0 = e.b_m * membraneDofs(l);
    // W(eps0 + eta) less K's linear part 1/2 eps0^T C eps0 (elastic: written out, exact).
    pi += skin_membrane_ == SkinMembrane::kElastic
              ? e.area_m2 * (eps0.dot(c_t_ * eta) + 0.5 * eta.dot(c_t_ * eta))
              : e.area_m2 * (skinLaw(eps0 + eta, FilmOutput::kEnergyAndStress).energy_j_per_m2 -
                             0.5 * eps0.dot(c_t_ * eps0));
  }
  for (const Member& m : members_) {
    const Vec3 du = u.segment<3>(globalDof(m.nodes[1], kU)) - u.segment<3>(globalDof(m.nodes[0], kU));
    const double l = m.length_m;
    const Vec3 pdu = m.transverse * du;
    const double eta = 0.5 * pdu.squaredNorm() / (l * l);
    pi += m.axial_stiffness_n * l * (m.axis.dot(du) / l * eta + 0.5 * eta * eta);
  }
  return pi;
}

Eigen::Matrix3Xd VonKarmanTerms::membraneForces(const Eigen::VectorXd& u) const {
  Eigen::Matrix3Xd n(3, static_cast<Eigen::Index>(facets_.size()));
  for (std::size_t i = 0; i < facets_.size(); ++i) {
    const Facet& e = facets_[i];
    const Vec9 l = facetLocal(e, u);
    n.col(static_cast<Eigen::Index>(i)) =
        skinLaw(e.b_m * membraneDofs(l) + etaOf(e.grad * normalDofs(l)), FilmOutput::kEnergyAndStress)
            .stress_n_per_m;
  }
  return n;
}

SparseMatrix VonKarmanTerms::tangent(const Eigen::VectorXd& u) const {
  if (u.size() != dof_count_) throw std::invalid_argument("von Karman: displacement size");
  std::vector<Triplet> trip;
  trip.reserve(81 * facets_.size() + 36 * members_.size());
  for (const Facet& e : facets_) {
    const Vec9 l = facetLocal(e, u);
    const Vec2 g = e.grad * normalDofs(l);
    const Vec3 eps0 = e.b_m * membraneDofs(l);
    const RelaxedMembrane law = skinLaw(eps0 + etaOf(g));
    const Vec3& n_total = law.stress_n_per_m;
    const Mat3& h = law.tangent_n_per_m;
    Eigen::Matrix2d s;
    s << n_total(0), n_total(2), n_total(2), n_total(1);
    const Eigen::Matrix<double, 3, 2> lam = etaJacobian(g);
    const Eigen::Matrix<double, 3, 3> deta_dw = lam * e.grad;  // 3 x (w1 w2 w3)
    // In-plane block beyond K's CST: zero for the elastic law (H = C).
    const Eigen::Matrix<double, 6, 6> k_dd = e.area_m2 * (e.b_m.transpose() * (h - c_t_) * e.b_m);
    const Eigen::Matrix<double, 6, 3> k_dw = e.area_m2 * (e.b_m.transpose() * h * deta_dw);
    const Mat3 k_ww = e.area_m2 * (deta_dw.transpose() * h * deta_dw +
                                   e.grad.transpose() * s * e.grad);
    Mat9 k = Mat9::Zero();  // local per node (u, v, w)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        for (int i = 0; i < 2; ++i) {
          k(3 * a + i, 3 * b + 2) = k_dw(2 * a + i, b);
          k(3 * b + 2, 3 * a + i) = k_dw(2 * a + i, b);
          for (int j = 0; j < 2; ++j) k(3 * a + i, 3 * b + j) = k_dd(2 * a + i, 2 * b + j);
        }
        k(3 * a + 2, 3 * b + 2) = k_ww(a, b);
      }
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const Mat3 block = e.triad.transpose() * k.block<3, 3>(3 * a, 3 * b) * e.triad;
        const int ra = globalDof(e.nodes[static_cast<std::size_t>(a)], kU);
        const int cb = globalDof(e.nodes[static_cast<std::size_t>(b)], kU);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            if (block(i, j) != 0.0) trip.emplace_back(ra + i, cb + j, block(i, j));
      }
  }
  for (const Member& m : members_) {
    const Vec3 du = u.segment<3>(globalDof(m.nodes[1], kU)) - u.segment<3>(globalDof(m.nodes[0], kU));
    const double l = m.length_m;
    const Mat3& p = m.transverse;
    const Vec3 pdu = p * du;
    const double eta = 0.5 * pdu.squaredNorm() / (l * l);
    const double ea = m.axial_stiffness_n;
    const double n_total = ea * (m.axis.dot(du) / l + eta);
    const Mat3 k = ea / (l * l) * (m.axis * pdu.transpose() + pdu * m.axis.transpose()) +
                   ea / (l * l * l) * pdu * pdu.transpose() + (n_total / l) * p;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const double sign = a == b ? 1.0 : -1.0;
        const int ra = globalDof(m.nodes[static_cast<std::size_t>(a)], kU);
        const int cb = globalDof(m.nodes[static_cast<std::size_t>(b)], kU);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            if (k(i, j) != 0.0) trip.emplace_back(ra + i, cb + j, sign * k(i, j));
      }
  }
  SparseMatrix t(dof_count_, dof_count_);
  t.setFromTriplets(trip.begin(), trip.end());
  return t;
}

bool NonlinearStaticOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why != nullptr) *why = m;
    return false;
  };
  if (load_steps < 1) return fail("load_steps: expected >= 1");
  if (max_newton_iterations < 1) return fail("max_newton_iterations: expected >= 1");
  if (!(force_tolerance > 0.0 && force_tolerance < 1.0))
    return fail("force_tolerance: expected in (0, 1)");
  if (!(displacement_tolerance > 0.0 && displacement_tolerance < 1.0))
    return fail("displacement_tolerance: expected in (0, 1)");
  if (skin_membrane == SkinMembrane::kTensionField && !film.IsValid(why)) return false;
  return true;
}

NonlinearStaticResult solveNonlinearStatic(const SparseMatrix& stiffness,
                                           const StaticNonlinearity& terms, const DofPartition& part,
                                           const Eigen::VectorXd& load,
                                           const NonlinearStaticOptions& options) {
  planProductsWithFixedCacheSizes();  // the same bits on every CPU (docs/theory.md 3.7)
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("nonlinear static: " + why);
  const int n = terms.dofCount();
  if (stiffness.rows() != n || load.size() != n)
    throw std::invalid_argument("nonlinear static: K, the load and the mesh differ in size");
  std::vector<int> free = part.retained();
  std::sort(free.begin(), free.end());
  if (free.empty()) throw std::invalid_argument("nonlinear static: no free DOF");
  const auto nf = static_cast<Eigen::Index>(free.size());
  auto restrict = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd r(nf);
    for (Eigen::Index i = 0; i < nf; ++i) r(i) = v(free[static_cast<std::size_t>(i)]);
    return r;
  };
  const SparseMatrix k_ff = extractBlock(stiffness, free, free);
  const Eigen::VectorXd f_free = restrict(load);
  const double f_norm = f_free.norm();

  NonlinearStaticResult res;
  res.displacement = Eigen::VectorXd::Zero(n);
  if (f_norm == 0.0) {
    res.converged = true;
    return res;
  }
  Eigen::VectorXd u_free = Eigen::VectorXd::Zero(nf);
  if (!options.nonlinear) {
    res.converged = solveSparseSymmetric(k_ff, f_free, &u_free);
    if (!res.converged) res.message = "the stiffness over the free DOFs is singular";
    res.displacement = expandRows(u_free, free, n);
    return res;
  }
  auto residual = [&](const Eigen::VectorXd& uf, double lambda, Eigen::VectorXd* full) {
    *full = expandRows(uf, free, n);
    return Eigen::VectorXd(k_ff * uf + restrict(terms.internalForce(*full)) - lambda * f_free);
  };
  // The total potential Pi(u) = 1/2 u^T K u + Pi_NL(u) - lambda F^T u, whose stationary point
  // the residual seeks: the merit function of the line search. From a soft start (a film) the
  // first Newton step is the linear solution, orders of magnitude too large, where the residual
  // norm is useless as a merit (it grows with the cube of the step) but the potential is not.
  auto potential = [&](const Eigen::VectorXd& uf, const Eigen::VectorXd& full, double lambda) {
    return 0.5 * uf.dot(k_ff * uf) + terms.energy(full) - lambda * f_free.dot(uf);
  };
  Eigen::VectorXd u_full(n), du(nf), trial_full(n);
  // Load fractions in geometric progression from 1 % (a film's first increments carry it from
  // plate to membrane) with a membrane predictor u ~ lambda^(1/3) between increments.
  double previous_lambda = 0.0;
  for (int step = 1; step <= options.load_steps; ++step) {
    const double lambda =
        options.load_steps == 1
            ? 1.0
            : std::pow(0.01, static_cast<double>(options.load_steps - step) / (options.load_steps - 1));
    if (previous_lambda > 0.0) u_free *= std::cbrt(lambda / previous_lambda);
    previous_lambda = lambda;
    const double tol = options.force_tolerance * lambda * f_norm;
    Eigen::VectorXd r = residual(u_free, lambda, &u_full);
    bool done = r.norm() <= tol;
    for (int it = 0; it < options.max_newton_iterations && !done; ++it) {
      ++res.newton_iterations;
      const SparseMatrix k_t = k_ff + extractBlock(terms.tangent(u_full), free, free);
      if (!solveSparseSymmetric(k_t, -r, &du)) {
        res.message = "the tangent stiffness is singular at load fraction " + std::to_string(lambda);
        res.displacement = u_full;
        return res;
      }
      double slope = r.dot(du);  // d Pi / d alpha at alpha = 0
      if (!(slope < 0.0)) {      // not a descent direction (an indefinite tangent): steepest descent
        du = -r * (r.squaredNorm() / std::max(r.dot(k_ff * r), 1e-300));
        slope = r.dot(du);
      }
      // The full Newton step when it reduces the residual (near the solution, where the
      // potential's decrease is below its round-off); else Armijo backtracking on the potential.
      Eigen::VectorXd trial = u_free + du;
      Eigen::VectorXd r_trial = residual(trial, lambda, &trial_full);
      if (!(r_trial.norm() < r.norm())) {
        const double pi0 = potential(u_free, u_full, lambda);
        double alpha = 1.0;
        for (int halving = 0; halving < 40; ++halving) {
          if (potential(trial, trial_full, lambda) <= pi0 + 1e-4 * alpha * slope) break;
          alpha *= 0.5;
          trial = u_free + alpha * du;
          trial_full = expandRows(trial, free, n);
        }
        r_trial = residual(trial, lambda, &trial_full);
      }
      const double step_norm = (trial - u_free).norm();
      u_free = trial;
      u_full = trial_full;
      r = r_trial;
      // Converged on the residual, or on a Newton correction at round-off of the displacement
      // (stiff members and a film in one model: their internal forces cancel to ~1e-12 of the
      // largest, which can lie above a small load's tolerance).
      done = r.norm() <= tol || step_norm <= options.displacement_tolerance * u_free.norm();
    }
    if (!done) {
      res.message = "Newton did not converge at load fraction " + std::to_string(lambda) +
                    " (residual " + std::to_string(r.norm() / (lambda * f_norm)) + " of the load)";
      res.displacement = u_full;
      res.residual_ratio = r.norm() / f_norm;
      return res;
    }
    res.residual_ratio = r.norm() / f_norm;
  }
  res.converged = true;
  res.displacement = u_full;
  return res;
}

NonlinearStaticResult solveWingStatic(const WingStructure& wing_structure, const WingMesh& mesh,
                                      const WingSupport& support, const Eigen::VectorXd& load,
                                      const NonlinearStaticOptions& options) {
  WingFeModel fe = assembleWingFe(wing_structure, mesh);
  addSkinPretension(wing_structure, mesh, support, &fe);
  const DofPartition part = makeDofPartition(fe.active, wingBoundaryDofs(mesh, support));
  if (options.kinematics == StrainKinematics::kCoRotational) {
    const CoRotationalTerms terms(wing_structure, mesh, fe.stiffness, options.skin_membrane,
                                  options.film);
    return solveNonlinearStatic(fe.stiffness, terms, part, load, options);
  }
  const VonKarmanTerms terms(wing_structure, mesh, MemberStretch::kBothTransverse,
                            options.skin_membrane, options.film);
  return solveNonlinearStatic(fe.stiffness, terms, part, load, options);
}

}  // namespace orni::structure
