// The co-rotational wing (corotational.hpp, docs/theory.md 4.7 "Large rotations").
#include "core/structure/corotational.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>

#include "core/structure/beam_element.hpp"
#include "core/structure/dual_number.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/shell_element.hpp"

namespace orni::structure {
namespace {

template <class T> using V3 = Eigen::Matrix<T, 3, 1>;
template <class T> using M3 = Eigen::Matrix<T, 3, 3>;
using Triplet = Eigen::Triplet<double, int>;
using std::atan2;  // the element functions take doubles and dual numbers alike
using std::cos;
using std::sin;
using std::sqrt;

// Below this squared angle (rad^2) the rotation's functions take their series: exact to round-off
// there (the next terms are ~1e-30) and smooth at zero, where the closed forms divide 0 by 0.
constexpr double kSeriesBelow = 1e-10;
// The central-difference step of the tangent, relative (translations: times the element size).
// Forward differences were not enough: their error 1/2 h d3U couples a film's membrane (E t =
// 4e6 N/m) into its bending (D ~ 6e-4 N m) at ~1e-3 of the bending diagonal.
constexpr double kTangentStep = 1e-6;

template <class T>
M3<T> skew(const V3<T>& w) {
  M3<T> s;
  s << T(0.0), -w(2), w(1), w(2), T(0.0), -w(0), -w(1), w(0), T(0.0);
  return s;
}

// R = exp([psi]x) (Rodrigues).
template <class T>
M3<T> rotationOf(const V3<T>& psi) {
  const T t2 = psi.squaredNorm();
  T a, b;  // sin t / t, (1 - cos t) / t^2
  if (valueOf(t2) < kSeriesBelow) {
    a = 1.0 - t2 / 6.0 + t2 * t2 / 120.0;
    b = 0.5 - t2 / 24.0 + t2 * t2 / 720.0;
  } else {
    const T t = sqrt(t2);
    a = sin(t) / t;
    b = (1.0 - cos(t)) / t2;
  }
  const M3<T> s = skew(psi);
  return M3<T>::Identity() + a * s + b * (s * s);
}

// asin(s) / s for s = sqrt(s2) (the angle of a rotation whose sine is s, per sine), given the
// cosine c (>= 0 in the series: deformational rotations are small).
template <class T>
T angleOverSine(const T& s2, const T& c) {
  if (valueOf(s2) < kSeriesBelow) return 1.0 + s2 / 6.0 + 0.075 * s2 * s2;
  const T s = sqrt(s2);
  return atan2(s, c) / s;
}

// The rotation vector of R (|angle| < pi): log.
template <class T>
V3<T> logOf(const M3<T>& r) {
  const V3<T> w(0.5 * (r(2, 1) - r(1, 2)), 0.5 * (r(0, 2) - r(2, 0)), 0.5 * (r(1, 0) - r(0, 1)));
  const T c = 0.5 * (r.trace() - 1.0);
  return angleOverSine(T(w.squaredNorm()), c) * w;
}

struct SkinLaw {
  SkinMembrane membrane = SkinMembrane::kElastic;
  Mat3 c = Mat3::Zero();
  double et = 0.0, nu = 0.0;
  FilmLaw film;
};

// The skin's membrane energy per area at the Green strain e (Voigt, 2 E_12), with its exact
// derivatives through the law's stress for dual numbers.
template <class T>
T membraneDensity(const V3<T>& e, const SkinLaw& law) {
  if (law.membrane == SkinMembrane::kElastic) {
    const V3<T> n = law.c.cast<T>() * e;
    return 0.5 * e.dot(n);
  }
  const Vec3 ev(valueOf(e(0)), valueOf(e(1)), valueOf(e(2)));
  const RelaxedMembrane r =
      relaxedMembrane(ev, law.et, law.nu, law.film, FilmOutput::kEnergyAndStress);
  if constexpr (std::is_same_v<T, double>) {
    return r.energy_j_per_m2;
  } else {
    T out(r.energy_j_per_m2);
    out.v = r.stress_n_per_m(0) * e(0).v + r.stress_n_per_m(1) * e(1).v +
            r.stress_n_per_m(2) * e(2).v;
    return out;
  }
}

// The facet's current G = dx / d(xi, eta) and Green strain (Voigt, 2 E_12).
template <class T>
Eigen::Matrix<T, 3, 2> facetGradient(const CoRotationalTerms::Facet& f, const std::array<V3<T>, 3>& x) {
  Eigen::Matrix<T, 3, 2> g;
  for (int k = 0; k < 2; ++k) g.col(k) = x[0] * f.grad(k, 0) + x[1] * f.grad(k, 1) + x[2] * f.grad(k, 2);
  return g;
}
template <class T>
V3<T> greenStrain(const Eigen::Matrix<T, 2, 2>& c) {
  return V3<T>(0.5 * (c(0, 0) - 1.0), 0.5 * (c(1, 1) - 1.0), c(0, 1));
}

// A facet's deformation: its membrane Green strain and the DKT's nodal rotations in its current
// triad.
template <class T>
struct FacetStrains {
  V3<T> green;                     ///< (E_11, E_22, 2 E_12) in the initial local axes
  Eigen::Matrix<T, 6, 1> bending;  ///< (theta_x, theta_y) per node, current triad
};

template <class T>
FacetStrains<T> facetStrains(const CoRotationalTerms::Facet& f, const std::array<V3<T>, 3>& x,
                             const std::array<V3<T>, 3>& psi) {
  // G = dx / d(xi, eta), the current positions' gradient in the initial local coordinates.
  const Eigen::Matrix<T, 3, 2> g = facetGradient(f, x);
  const Eigen::Matrix<T, 2, 2> c = g.transpose() * g;
  FacetStrains<T> out;
  out.green = greenStrain(c);
  // Polar decomposition G = R U: U = sqrt(C) = (C + s I) / t, s = sqrt(det C), t = sqrt(tr C + 2 s);
  // U^-1 = adj(C + s I) / (s t).
  const T s = sqrt(T(c(0, 0) * c(1, 1) - c(0, 1) * c(1, 0)));
  const T t = sqrt(T(c(0, 0) + c(1, 1) + 2.0 * s));
  Eigen::Matrix<T, 2, 2> u_inv;
  u_inv << c(1, 1) + s, -c(0, 1), -c(1, 0), c(0, 0) + s;
  const Eigen::Matrix<T, 3, 2> r = g * u_inv / (s * t);
  const V3<T> e1 = r.col(0), e2 = r.col(1);
  const V3<T> n = e1.cross(e2);
  for (int i = 0; i < 3; ++i) {
    const V3<T> d = rotationOf(psi[static_cast<std::size_t>(i)]) * f.normal0.cast<T>();
    const T dx = e1.dot(d), dy = e2.dot(d), dz = n.dot(d);
    const T scale = angleOverSine(T(dx * dx + dy * dy), dz);
    out.bending(2 * i) = -dy * scale;    // theta_x
    out.bending(2 * i + 1) = dx * scale;  // theta_y
  }
  return out;
}

template <class T>
T facetEnergy(const CoRotationalTerms::Facet& f, const std::array<V3<T>, 3>& x,
              const std::array<V3<T>, 3>& psi, const SkinLaw& law) {
  const FacetStrains<T> s = facetStrains(f, x, psi);
  const Eigen::Matrix<T, 6, 1> kb = f.bending.cast<T>() * s.bending;
  return f.area_m2 * membraneDensity(s.green, law) + 0.5 * s.bending.dot(kb);
}

template <class T>
T memberEnergy(const CoRotationalTerms::Member& m, const std::array<V3<T>, 2>& x,
               const std::array<V3<T>, 2>& psi) {
  const V3<T> chord = x[1] - x[0];
  const T l = sqrt(T(chord.squaredNorm()));
  const V3<T> e1 = chord / l;
  const M3<T> r1 = rotationOf(psi[0]), r2 = rotationOf(psi[1]);
  const V3<T> z0 = m.triad0.row(2).transpose().cast<T>();
  V3<T> z = 0.5 * (r1 * z0 + r2 * z0);
  z -= z.dot(e1) * e1;
  z /= sqrt(T(z.squaredNorm()));
  const V3<T> y = z.cross(e1);
  M3<T> lambda;
  lambda.row(0) = e1.transpose();
  lambda.row(1) = y.transpose();
  lambda.row(2) = z.transpose();
  const M3<T> lambda0_t = m.triad0.transpose().cast<T>();
  Eigen::Matrix<T, 7, 1> d;
  d.template head<3>() = logOf(M3<T>(lambda * r1 * lambda0_t));
  d(3) = l - m.length_m;
  d.template tail<3>() = logOf(M3<T>(lambda * r2 * lambda0_t));
  const Eigen::Matrix<T, 7, 1> kd = m.stiffness.cast<T>() * d;
  return 0.5 * d.dot(kd);
}

// The element's nodal unknowns (u, psi per node, 6 K) as numbers of type T; with dual numbers the
// independent variables, shifted by `step` along `direction` (>= 0) for the tangent's differences.
template <class T, std::size_t K>
void gather(const std::array<int, K>& nodes, const std::vector<Vec3>& x0, const Eigen::VectorXd& u,
            std::array<V3<T>, K>* x, std::array<V3<T>, K>* psi, int direction = -1,
            double step = 0.0) {
  for (std::size_t a = 0; a < K; ++a) {
    const int node = nodes[a];
    for (int j = 0; j < 3; ++j) {
      const int kx = 6 * static_cast<int>(a) + j, kr = kx + 3;
      const double xv = x0[static_cast<std::size_t>(node)](j) + u(globalDof(node, j)) +
                        (kx == direction ? step : 0.0);
      const double rv = u(globalDof(node, 3 + j)) + (kr == direction ? step : 0.0);
      if constexpr (std::is_same_v<T, double>) {
        (*x)[a](j) = xv;
        (*psi)[a](j) = rv;
      } else {
        (*x)[a](j) = T::variable(xv, kx);
        (*psi)[a](j) = T::variable(rv, kr);
      }
    }
  }
}

template <int N, class Element, class EnergyOf, std::size_t K>
Eigen::Matrix<double, N, 1> elementGradient(const Element& e, const std::array<int, K>& nodes,
                                            const std::vector<Vec3>& x0, const Eigen::VectorXd& u,
                                            const EnergyOf& energy_of, int direction = -1,
                                            double step = 0.0) {
  std::array<V3<Dual<N>>, K> x, psi;
  gather(nodes, x0, u, &x, &psi, direction, step);
  return energy_of(e, x, psi).v;
}

// FacetTangent::kMembraneExact: A (J_E^T W'' J_E + sum_k N_k d2E_k) + J_b^T K_b J_b from one
// dual-number pass; d2E is constant (E is quadratic in the positions): for the node pair (a, b)
// [N_11 g_a1 g_b1 + N_22 g_a2 g_b2 + N_12 (g_a1 g_b2 + g_a2 g_b1)] I_3 with g = f.grad.
template <class Lookup>
void facetMembraneExactTangentOf(const CoRotationalTerms::Facet& f, const Lookup& gather_dual,
                                 const SkinLaw& law, Mat18* k) {
  std::array<V3<Dual<18>>, 3> x, psi;
  gather_dual(&x, &psi);
  const FacetStrains<Dual<18>> s = facetStrains(f, x, psi);
  Eigen::Matrix<double, 3, 18> je;
  Eigen::Matrix<double, 6, 18> jb;
  Vec3 e;
  for (int r = 0; r < 3; ++r) {
    je.row(r) = s.green(r).v.transpose();
    e(r) = s.green(r).a;
  }
  for (int r = 0; r < 6; ++r) jb.row(r) = s.bending(r).v.transpose();
  Mat3 tangent;
  Vec3 stress;
  if (law.membrane == SkinMembrane::kElastic) {
    tangent = law.c;
    stress = law.c * e;
  } else {
    const RelaxedMembrane r = relaxedMembrane(e, law.et, law.nu, law.film, FilmOutput::kWithTangent);
    tangent = r.tangent_n_per_m;
    stress = r.stress_n_per_m;
  }
  k->noalias() = f.area_m2 * (je.transpose() * tangent * je);
  k->noalias() += jb.transpose() * f.bending * jb;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double g = f.area_m2 * (stress(0) * f.grad(0, a) * f.grad(0, b) +
                                    stress(1) * f.grad(1, a) * f.grad(1, b) +
                                    stress(2) * (f.grad(0, a) * f.grad(1, b) + f.grad(1, a) * f.grad(0, b)));
      for (int i = 0; i < 3; ++i) (*k)(6 * a + i, 6 * b + i) += g;
    }
}

// f(begin, end) over the elements [0, count) in contiguous blocks, one per thread (the first on
// this one; at most 4, the machine's cores). Every element's result is the same arithmetic on any
// thread and the callers sum them in element order, so the bits do not depend on the count.
template <class F>
void forElementBlocks(std::size_t count, const F& f) {
  const std::size_t threads =
      std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 4);
  const std::size_t blocks = std::max<std::size_t>(1, std::min(threads, count / 64));
  const std::size_t per = (count + blocks - 1) / std::max<std::size_t>(blocks, 1);
  std::vector<std::thread> pool;
  std::vector<std::exception_ptr> errors(blocks);
  for (std::size_t b = 1; b < blocks; ++b)
    pool.emplace_back([&f, &errors, b, per, count] {
      try {
        f(std::min(count, b * per), std::min(count, (b + 1) * per));
      } catch (...) {
        errors[b] = std::current_exception();
      }
    });
  try {
    f(std::size_t{0}, std::min(count, per));
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

template <std::size_t K, class Matrix>
void scatterBlock(const Matrix& ke, const std::array<int, K>& nodes, std::vector<Triplet>* out) {
  for (std::size_t b = 0; b < K; ++b)
    for (int j = 0; j < kDofsPerNode; ++j)
      for (std::size_t a = 0; a < K; ++a)
        for (int i = 0; i < kDofsPerNode; ++i)
          out->emplace_back(globalDof(nodes[a], i), globalDof(nodes[b], j),
                            ke(kDofsPerNode * static_cast<int>(a) + i,
                               kDofsPerNode * static_cast<int>(b) + j));
}

}  // namespace

CoRotationalTerms::CoRotationalTerms(const WingStructure& wing_structure, const WingMesh& mesh,
                                     const SparseMatrix& linear_stiffness,
                                     SkinMembrane skin_membrane, const FilmLaw& film,
                                     FacetTangent facet_tangent)
    : dof_count_(kDofsPerNode * mesh.nodeCount()),
      linear_stiffness_(linear_stiffness),
      skin_membrane_(skin_membrane),
      film_(film),
      facet_tangent_(facet_tangent) {
  if (wing_structure.wing.skin.pretension_N_per_m != 0.0)
    throw std::invalid_argument(
        "co-rotational wing: a skin pretension is not built (its prestressed K belongs to the "
        "linear wing); set wing.skin.pretension_N_per_m = 0");
  std::string why;
  if (skin_membrane == SkinMembrane::kTensionField && !film.IsValid(&why))
    throw std::invalid_argument("co-rotational wing: " + why);
  if (linear_stiffness.rows() != dof_count_ || linear_stiffness.cols() != dof_count_)
    throw std::invalid_argument("co-rotational wing: K and the mesh differ in size");
  x0_ = mesh.nodes_W_m;

  if (!mesh.triangles.empty()) {
    const ShellProperties skin = skinShellProperties(wing_structure);
    const double nu = skin.poisson_ratio;
    skin_et_n_per_m_ = skin.youngs_modulus_pa * skin.thickness_m;
    skin_nu_ = nu;
    membrane_c_ << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
    membrane_c_ *= skin_et_n_per_m_ / (1.0 - nu * nu);
    facets_.reserve(mesh.triangles.size());
    for (const auto& tri : mesh.triangles) {
      std::array<Vec3, 3> x;
      for (int a = 0; a < 3; ++a) x[static_cast<std::size_t>(a)] = x0_[static_cast<std::size_t>(tri[static_cast<std::size_t>(a)])];
      const Mat3 triad = shellTriad(x);
      std::array<Eigen::Vector2d, 3> xy;
      for (int a = 0; a < 3; ++a) {
        const Vec3 d = x[static_cast<std::size_t>(a)] - x[0];
        xy[static_cast<std::size_t>(a)] = Eigen::Vector2d(triad.row(0).dot(d), triad.row(1).dot(d));
      }
      Facet f;
      f.nodes = tri;
      f.normal0 = triad.row(2).transpose();
      const Mat3x6 bm = cstStrainMatrix(xy);
      for (int a = 0; a < 3; ++a) {
        f.grad(0, a) = bm(0, 2 * a);
        f.grad(1, a) = bm(1, 2 * a + 1);
      }
      f.area_m2 = triangleArea(x);
      f.size_m = std::max({(x[1] - x[0]).norm(), (x[2] - x[1]).norm(), (x[0] - x[2]).norm()});
      const Mat9 kb = dktStiffness(xy, skin);
      constexpr int kRot[6] = {1, 2, 4, 5, 7, 8};
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) f.bending(i, j) = kb(kRot[i], kRot[j]);
      facets_.push_back(f);
    }
  }
  const std::vector<BeamProperties> props = memberBeamProperties(wing_structure);
  members_.reserve(mesh.beams.size());
  for (const BeamElement& b : mesh.beams) {
    if (b.member < 0 || b.member >= static_cast<int>(props.size()))
      throw std::invalid_argument("co-rotational wing: beam member index out of range");
    const Vec3& x1 = x0_[static_cast<std::size_t>(b.nodes[0])];
    const Vec3& x2 = x0_[static_cast<std::size_t>(b.nodes[1])];
    Member m;
    m.nodes = b.nodes;
    m.triad0 = beamTriad(x1, x2, Vec3::UnitZ());  // the assembly's orientation (fe_assembly.hpp)
    m.length_m = (x2 - x1).norm();
    const Mat12 k_local = beamStiffness(Vec3::Zero(), Vec3(m.length_m, 0.0, 0.0), Vec3::UnitZ(),
                                        props[static_cast<std::size_t>(b.member)]);
    constexpr int kDef[7] = {3, 4, 5, 6, 9, 10, 11};
    for (int i = 0; i < 7; ++i)
      for (int j = 0; j < 7; ++j) m.stiffness(i, j) = k_local(kDef[i], kDef[j]);
    members_.push_back(m);
  }
}

double CoRotationalTerms::strainEnergy(const Eigen::VectorXd& u) const {
  if (u.size() != dof_count_) throw std::invalid_argument("co-rotational wing: displacement size");
  const SkinLaw law{skin_membrane_, membrane_c_, skin_et_n_per_m_, skin_nu_, film_};
  std::vector<double> facet(facets_.size()), member(members_.size());
  forElementBlocks(facets_.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      std::array<V3<double>, 3> x, psi;
      gather(facets_[i].nodes, x0_, u, &x, &psi);
      facet[i] = facetEnergy(facets_[i], x, psi, law);
    }
  });
  for (std::size_t i = 0; i < members_.size(); ++i) {
    std::array<V3<double>, 2> x, psi;
    gather(members_[i].nodes, x0_, u, &x, &psi);
    member[i] = memberEnergy(members_[i], x, psi);
  }
  double total = 0.0;
  for (const double e : facet) total += e;
  for (const double e : member) total += e;
  return total;
}

Eigen::VectorXd CoRotationalTerms::strainForce(const Eigen::VectorXd& u) const {
  if (u.size() != dof_count_) throw std::invalid_argument("co-rotational wing: displacement size");
  const SkinLaw law{skin_membrane_, membrane_c_, skin_et_n_per_m_, skin_nu_, film_};
  const auto facet_energy = [&law](const Facet& f, const auto& x, const auto& psi) {
    return facetEnergy(f, x, psi, law);
  };
  const auto member_energy = [](const Member& m, const auto& x, const auto& psi) {
    return memberEnergy(m, x, psi);
  };
  std::vector<Eigen::Matrix<double, 18, 1>> facet(facets_.size());
  forElementBlocks(facets_.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      facet[i] = elementGradient<18>(facets_[i], facets_[i].nodes, x0_, u, facet_energy);
  });
  Eigen::VectorXd force = Eigen::VectorXd::Zero(dof_count_);
  for (std::size_t i = 0; i < facets_.size(); ++i)
    for (int a = 0; a < 3; ++a)
      force.segment<6>(globalDof(facets_[i].nodes[static_cast<std::size_t>(a)], 0)) +=
          facet[i].segment<6>(6 * a);
  for (const Member& m : members_) {
    const Eigen::Matrix<double, 12, 1> g = elementGradient<12>(m, m.nodes, x0_, u, member_energy);
    for (int a = 0; a < 2; ++a)
      force.segment<6>(globalDof(m.nodes[static_cast<std::size_t>(a)], 0)) += g.segment<6>(6 * a);
  }
  return force;
}

SparseMatrix CoRotationalTerms::strainTangent(const Eigen::VectorXd& u) const {
  if (u.size() != dof_count_) throw std::invalid_argument("co-rotational wing: displacement size");
  const SkinLaw law{skin_membrane_, membrane_c_, skin_et_n_per_m_, skin_nu_, film_};
  const auto facet_energy = [&law](const Facet& f, const auto& x, const auto& psi) {
    return facetEnergy(f, x, psi, law);
  };
  const auto member_energy = [](const Member& m, const auto& x, const auto& psi) {
    return memberEnergy(m, x, psi);
  };
  // Central differences of the exact gradient, symmetrised; translations step by kTangentStep
  // times the element's size, rotations by kTangentStep rad.
  const auto differences = [&](const auto& e, const auto& nodes, double size, const auto& energy_of,
                               auto* block) {
    constexpr int n = std::remove_pointer_t<decltype(block)>::RowsAtCompileTime;
    for (int k = 0; k < n; ++k) {
      const double h = (k % 6 < 3 ? size : 1.0) * kTangentStep;
      block->col(k) = (elementGradient<n>(e, nodes, x0_, u, energy_of, k, h) -
                       elementGradient<n>(e, nodes, x0_, u, energy_of, k, -h)) /
                      (2.0 * h);
    }
    *block = 0.5 * (*block + block->transpose()).eval();
  };
  const auto facetMembraneExactTangent = [this](const Facet& f, const Eigen::VectorXd& at,
                                                 const SkinLaw& skin, Mat18* k) {
    facetMembraneExactTangentOf(
        f, [&](auto* x, auto* psi) { gather(f.nodes, x0_, at, x, psi); }, skin, k);
  };
  std::vector<Triplet> triplets;
  triplets.reserve(324 * facets_.size() + 144 * members_.size());
  std::vector<Mat18> facet(facets_.size());
  forElementBlocks(facets_.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (facet_tangent_ == FacetTangent::kDifferences)
        differences(facets_[i], facets_[i].nodes, facets_[i].size_m, facet_energy, &facet[i]);
      else
        facetMembraneExactTangent(facets_[i], u, law, &facet[i]);
    }
  });
  std::vector<Mat12> member(members_.size());
  forElementBlocks(members_.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      differences(members_[i], members_[i].nodes, members_[i].length_m, member_energy, &member[i]);
  });
  for (std::size_t i = 0; i < facets_.size(); ++i) scatterBlock(facet[i], facets_[i].nodes, &triplets);
  for (std::size_t i = 0; i < members_.size(); ++i)
    scatterBlock(member[i], members_[i].nodes, &triplets);
  SparseMatrix k(dof_count_, dof_count_);
  k.setFromTriplets(triplets.begin(), triplets.end());
  return k;
}

std::vector<FilmState> CoRotationalTerms::facetStates(const Eigen::VectorXd& u) const {
  if (u.size() != dof_count_) throw std::invalid_argument("co-rotational wing: displacement size");
  std::vector<FilmState> states(facets_.size(), FilmState::kTaut);
  if (skin_membrane_ != SkinMembrane::kTensionField) return states;
  for (std::size_t i = 0; i < facets_.size(); ++i) {
    std::array<V3<double>, 3> x, psi;
    gather(facets_[i].nodes, x0_, u, &x, &psi);
    const Eigen::Matrix<double, 3, 2> g = facetGradient(facets_[i], x);
    states[i] = relaxedMembrane(greenStrain(Eigen::Matrix2d(g.transpose() * g)), skin_et_n_per_m_,
                                skin_nu_, film_, FilmOutput::kEnergyAndStress)
                    .state;
  }
  return states;
}

double CoRotationalTerms::largestFacetTilt(const Eigen::VectorXd& u) const {
  if (u.size() != dof_count_) throw std::invalid_argument("co-rotational wing: displacement size");
  double largest = 0.0;
  for (const Facet& f : facets_) {
    std::array<V3<double>, 3> x, psi;
    gather(f.nodes, x0_, u, &x, &psi);
    const Eigen::Matrix<double, 3, 2> g = facetGradient(f, x);
    const Vec3 n = g.col(0).cross(g.col(1)).normalized();
    largest = std::max(largest, std::atan2(n.cross(f.normal0).norm(), n.dot(f.normal0)));
  }
  return largest;
}

Eigen::VectorXd CoRotationalTerms::internalForce(const Eigen::VectorXd& u) const {
  return strainForce(u) - linear_stiffness_ * u;
}

double CoRotationalTerms::energy(const Eigen::VectorXd& u) const {
  return strainEnergy(u) - 0.5 * u.dot(linear_stiffness_ * u);
}

SparseMatrix CoRotationalTerms::tangent(const Eigen::VectorXd& u) const {
  return SparseMatrix(strainTangent(u) - linear_stiffness_);
}

}  // namespace orni::structure
