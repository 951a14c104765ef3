#include "core/dynamics/flexible_wing.hpp"

#include <atomic>
#include <cstring>
#include <list>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "core/aero/mst_strip.hpp"
#include "core/structure/wing_mesh.hpp"

namespace orni {

FlexibleWingModel::FlexibleWingModel(const VehicleModel& vehicle,
                                     std::shared_ptr<const structure::ModalWing> modal_wing,
                                     const std::vector<double>& strip_chords_m,
                                     const std::vector<double>& strip_widths_m)
    : modal(std::move(modal_wing)) {
  const structure::ModalWing& mw = *modal;
  mode_count = mw.modeCount();
  const int M = mode_count;
  const std::size_t ns = mw.mesh.strip_nodes.size();
  if (ns != strip_chords_m.size())
    throw std::invalid_argument("flexible wing: mesh strips do not match the aerodynamic strips");
  const Vec3 n_W = -Vec3::UnitZ();  // upper-surface normal of the flat wing (structure.md 1.1)
  strips.resize(ns);
  apparent_mass_kg.resize(static_cast<Eigen::Index>(ns));
  apparent_rotary_kgm2.resize(static_cast<Eigen::Index>(ns));
  const double rho = vehicle.air.density_kgpm3;
  for (std::size_t j = 0; j < ns; ++j) {
    const structure::StripSampleNodes& sn = mw.mesh.strip_nodes[j];
    FlexibleStrip& s = strips[j];
    s.x_L_W_m = mw.mesh.nodes_W_m[static_cast<std::size_t>(sn.leading_edge)];
    s.x_T_W_m = mw.mesh.nodes_W_m[static_cast<std::size_t>(sn.three_quarter_chord)];
    s.phi_L = mw.phi_W[static_cast<std::size_t>(sn.leading_edge)];
    s.phi_T = mw.phi_W[static_cast<std::size_t>(sn.three_quarter_chord)];
    s.lever_T_m = (s.x_T_W_m - s.x_L_W_m).norm();
    const Eigen::Matrix3Xd dphi = s.phi_T - s.phi_L;
    s.psi_twist = -(n_W.transpose() * dphi) / s.lever_T_m;
    const double c = strip_chords_m[j];
    s.psi_mid = ((s.phi_L + (0.5 * c / s.lever_T_m) * dphi).transpose() * n_W);
    apparent_mass_kg[static_cast<Eigen::Index>(j)] =
        aero::apparentMassPerSpan_kgpm(rho, c) * strip_widths_m[j];
    apparent_rotary_kgm2[static_cast<Eigen::Index>(j)] =
        rho * kPi * c * c * c * c / 128.0 * strip_widths_m[j];
  }
  tip_strip = static_cast<Eigen::Index>(ns) - 1;
  stiffness = mw.stiffnessDiagonal();
  damping = mw.dampingDiagonal();
  const structure::InertiaInvariants& inv = mw.invariants;
  M_qq = inv.generalized_mass;
  // structure.md 3.3: C_1 = P_32 - P_23 (1-based), K_w = sum w_k w_l P_kl - |w|^2 sum_k P_kk,
  // h_w = sum w_k w_l S_kl - |w|^2 sum_k S_kk; here w = w_x e_x (the hinge axis). K_w + K_G:
  // structure/inertial_stiffness.hpp.
  C1 = inv.P(2, 1) - inv.P(1, 2);
  inertial_stiffness = structure::modalInertialStiffness(inv, mw.geometric_stiffness,
                                                        vehicle.wing.fe.inertial_stiffness);
  spin_stiffness_x = inertial_stiffness.spinAbout(0, 0);
  geometric_stiffness_x =
      vehicle.wing.fe.inertial_stiffness == InertialStiffness::kBoth
          ? Eigen::MatrixXd(mw.geometric_stiffness[structure::kLoadSpinXX])
          : Eigen::MatrixXd::Zero(M, M);
  h_x = inv.S(0, 0) - (inv.S(0, 0) + inv.S(1, 1) + inv.S(2, 2));
  H_x = inv.rotational_participation.row(0).transpose();
  if (M_qq.rows() != M) throw std::logic_error("flexible wing: invariant sizes");
  stacked = stackStrips(strips, M, apparent_mass_kg, apparent_rotary_kgm2);
}

StackedStrips stackStrips(const std::vector<FlexibleStrip>& strips, int mode_count,
                          const Eigen::VectorXd& apparent_mass_kg,
                          const Eigen::VectorXd& apparent_rotary_kgm2) {
  const int M = mode_count;
  const auto ns = static_cast<Eigen::Index>(strips.size());
  StackedStrips st;
  st.ns = ns;
  st.points.resize(6 * ns);
  st.shapes.setZero(8 * ns, M);
  st.apparent_const.setZero(M, M);
  st.apparent_per_f.setZero(static_cast<Eigen::Index>(M) * (M + 1) / 2, ns);
  for (Eigen::Index i = 0; i < ns; ++i) {
    const FlexibleStrip& fs = strips[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) {  // component-major: row k ns + i of each block
      st.points[k * ns + i] = fs.x_T_W_m[k];
      st.points[3 * ns + k * ns + i] = fs.x_L_W_m[k];
      if (M > 0) {
        st.shapes.row(k * ns + i) = fs.phi_T.row(k);
        st.shapes.row(3 * ns + k * ns + i) = fs.phi_L.row(k);
      }
    }
    if (M == 0) continue;
    st.shapes.row(6 * ns + i) = fs.psi_twist;
    st.shapes.row(7 * ns + i) = fs.psi_mid.transpose();
    const Eigen::MatrixXd mid = 0.5 * apparent_mass_kg[i] * fs.psi_mid * fs.psi_mid.transpose();
    const Eigen::MatrixXd per_f =
        mid + apparent_rotary_kgm2[i] * fs.psi_twist.transpose() * fs.psi_twist;
    st.apparent_const += mid;
    Eigen::Index r = 0;
    for (int c = 0; c < M; ++c)
      for (int l = c; l < M; ++l) st.apparent_per_f(r++, i) = per_f(l, c);
  }
  return st;
}

Eigen::VectorXd packedLower(const Eigen::MatrixXd& A) {
  const Eigen::Index n = A.rows();
  Eigen::VectorXd p(n * (n + 1) / 2);
  Eigen::Index r = 0;
  for (Eigen::Index c = 0; c < n; ++c)
    for (Eigen::Index l = c; l < n; ++l) p[r++] = A(l, c);
  return p;
}

void addApparentModalMass(const StackedStrips& st, const Eigen::ArrayXd& f, double scale,
                          Eigen::VectorXd* packed, Eigen::Ref<Eigen::MatrixXd> out) {
  const auto M = st.apparent_const.rows();
  if (M == 0) return;
  packed->noalias() = st.apparent_per_f * f.matrix();
  Eigen::Index r = 0;
  for (Eigen::Index c = 0; c < M; ++c)
    for (Eigen::Index l = c; l < M; ++l)
      out(l, c) += scale * (st.apparent_const(l, c) + (*packed)[r++]);
}

void modalFrameInertia(const FlexibleWingModel& flex, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& qd, double phi_dot_radps, double phi_ddot_radps2,
                       Eigen::VectorXd* out) {
  const double wx = phi_dot_radps, ax = phi_ddot_radps2;
  Eigen::VectorXd& g = *out;
  g.noalias() = (2.0 * wx) * (flex.C1 * qd);
  g.noalias() += (wx * wx) * (flex.spin_stiffness_x * q);
  g.noalias() += ax * (flex.C1 * q);
  g += ax * flex.H_x + (wx * wx) * flex.h_x;
}

namespace {

// The cache: at most kModalWingCacheCapacity wings, the least recently used dropped first (a wing
// still in use stays alive through its shared_ptr; dropping it only means a rebuild, with the same
// bits, should it be asked for again). Without a bound an optimisation over the stiffeners would
// keep one wing per design it ever tried.
struct CacheEntry {
  std::shared_ptr<const structure::ModalWing> wing;
  std::list<std::string>::iterator recency;  // position in g_recency (front: most recent)
};
std::mutex g_cache_mutex;
std::map<std::string, CacheEntry> g_cache;
std::list<std::string> g_recency;
std::atomic<long> g_builds{0};

void appendBytes(std::string* key, const void* p, std::size_t n) {
  key->append(static_cast<const char*>(p), n);
}
void appendDouble(std::string* key, double v) { appendBytes(key, &v, sizeof v); }

// Every input the FE model depends on, as exact bytes (no hashing collisions).
std::string structuralKey(const VehicleModel& v) {
  std::string k;
  const WingModel& w = v.wing;
  const int planform = static_cast<int>(w.planform);
  appendBytes(&k, &planform, sizeof planform);
  for (double d : {w.semispan_m, w.root_chord_m, w.p3_aft_of_le_m, w.skin.thickness_m,
                   w.fe.element_size_m, w.fe.cutoff_hz, w.fe.damping_ratio,
                   v.air.density_kgpm3})
    appendDouble(&k, d);
  appendBytes(&k, &w.strip_count, sizeof w.strip_count);
  appendDouble(&k, w.member_diameter_scale);
  appendBytes(&k, &w.fe.mode_count, sizeof w.fe.mode_count);
  k.push_back(w.fe.p3_cross_axis_normal ? 'n' : 's');
  k.push_back(static_cast<char>('0' + static_cast<int>(w.fe.p3_joint)));
  k.push_back(w.fe.root_edge_pinned ? 'r' : '-');
  k += w.skin.material + '\0';
  for (const WingMember& m : w.members) {
    k += m.name + '\0' + m.material + '\0';
    for (double d : {m.diameter_m, m.start_x_W_m, m.start_y_W_m, m.end_x_W_m, m.end_y_W_m})
      appendDouble(&k, d);
  }
  for (const Material& m : v.materials) {
    k += m.name + '\0';
    for (double d : {m.youngs_modulus_pa, m.poisson_ratio, m.density_kgpm3}) appendDouble(&k, d);
  }
  return k;
}

}  // namespace

std::shared_ptr<const structure::ModalWing> cachedModalWing(const VehicleModel& vehicle) {
  const std::string key = structuralKey(vehicle);
  {
    std::lock_guard<std::mutex> lock(g_cache_mutex);
    auto it = g_cache.find(key);
    if (it != g_cache.end()) {
      g_recency.splice(g_recency.begin(), g_recency, it->second.recency);
      return it->second.wing;
    }
  }
  const structure::WingMesh mesh = structure::buildWingMesh(vehicle, vehicle.wing.fe.element_size_m);
  structure::ModalWingOptions opts;
  opts.selection.max_modes = vehicle.wing.fe.mode_count;
  opts.selection.cutoff_hz = vehicle.wing.fe.cutoff_hz;
  opts.damping_ratio = vehicle.wing.fe.damping_ratio;
  opts.support = structure::WingSupport::of(vehicle.wing.fe);
  auto built = std::make_shared<const structure::ModalWing>(
      structure::buildModalWing(vehicle, mesh, opts));
  g_builds.fetch_add(1);
  std::lock_guard<std::mutex> lock(g_cache_mutex);
  auto it = g_cache.find(key);  // another thread may have built it meanwhile: keep the first
  if (it != g_cache.end()) {
    g_recency.splice(g_recency.begin(), g_recency, it->second.recency);
    return it->second.wing;
  }
  g_recency.push_front(key);
  g_cache.emplace(key, CacheEntry{built, g_recency.begin()});
  while (g_cache.size() > kModalWingCacheCapacity) {
    g_cache.erase(g_recency.back());
    g_recency.pop_back();
  }
  return built;
}

long modalWingBuildCount() { return g_builds.load(); }

std::size_t modalWingCacheSize() {
  std::lock_guard<std::mutex> lock(g_cache_mutex);
  return g_cache.size();
}

}  // namespace orni
