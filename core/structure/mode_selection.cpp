// Effective-mass table and mode selection (docs/theory.md 3.4).
#include "core/structure/mode_selection.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/structure/rigid_body_vectors.hpp"

namespace orni::structure {
namespace {

void fractions(const SparseMatrix& mass, const Eigen::MatrixXd& shapes, const Eigen::VectorXd& r,
               double& reference, Eigen::VectorXd& fraction, Eigen::VectorXd& cumulative) {
  const Eigen::VectorXd mr = mass * r;
  reference = 0.0;  // (a plain loop: r.dot(mr) trips a GCC 12 -Wnull-dereference false positive)
  for (Eigen::Index i = 0; i < r.size(); ++i) reference += r(i) * mr(i);
  const Eigen::VectorXd participation = shapes.transpose() * mr;  // L_kj
  fraction = participation.cwiseAbs2() / reference;
  cumulative.resize(fraction.size());
  double sum = 0.0;
  for (Eigen::Index k = 0; k < fraction.size(); ++k) cumulative(k) = (sum += fraction(k));
}

}  // namespace

EffectiveMassTable effectiveMassTable(const SparseMatrix& mass, const Eigen::MatrixXd& shapes,
                                      const std::vector<Vec3>& nodes_W_m,
                                      const Vec3& hinge_point_W_m, const Vec3& hinge_axis_W) {
  if (shapes.rows() != mass.rows())
    throw std::invalid_argument("effectiveMassTable: shapes and M sizes differ");
  EffectiveMassTable t;
  fractions(mass, shapes, rigidRotationVector(nodes_W_m, hinge_point_W_m, hinge_axis_W),
            t.flap_reference_kgm2, t.flap_fraction, t.flap_cumulative);
  fractions(mass, shapes, rigidTranslationVectors(nodes_W_m).col(2), t.heave_reference_kg,
            t.heave_fraction, t.heave_cumulative);
  return t;
}

bool ModeSelectionOptions::IsValid(std::string* why) const {
  auto fail = [why](const std::string& msg) {
    if (why != nullptr) *why = msg;
    return false;
  };
  if (max_modes < 1) return fail("max_modes: expected >= 1, got " + std::to_string(max_modes));
  if (!(cutoff_hz >= 0.0)) return fail("cutoff_hz: expected >= 0");
  if (!(min_effective_mass_fraction >= 0.0 && min_effective_mass_fraction < 1.0))
    return fail("min_effective_mass_fraction: expected in [0, 1)");
  return true;
}

std::string ModeSelection::BriefReport() const {
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%d modes; effective mass: flap %.1f %%, heave %.1f %%%s%s", count,
                100.0 * flap_fraction, 100.0 * heave_fraction,
                effective_mass_met ? "" : " (below the required fraction)",
                cutoff_reached ? "" : " (cut-off frequency not reached)");
  return buf;
}

ModeSelection selectModes(const Eigen::VectorXd& frequencies_hz, const EffectiveMassTable& table,
                          const ModeSelectionOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("mode selection: " + why);
  const int computed = static_cast<int>(frequencies_hz.size());
  if (table.flap_cumulative.size() != computed || table.heave_cumulative.size() != computed)
    throw std::invalid_argument("mode selection: table and frequency sizes differ");
  ModeSelection s;
  int count = std::min(computed, options.max_modes);
  if (options.cutoff_hz > 0.0) {
    int below = 0;
    while (below < count && frequencies_hz(below) <= options.cutoff_hz) ++below;
    s.cutoff_reached = computed > 0 && frequencies_hz(computed - 1) > options.cutoff_hz;
    count = below;
  }
  const double need = options.min_effective_mass_fraction;
  auto met = [&](int c) {
    return c > 0 && table.flap_cumulative(c - 1) >= need && table.heave_cumulative(c - 1) >= need;
  };
  if (need > 0.0)
    while (!met(count) && count < std::min(computed, options.max_modes)) ++count;
  s.count = count;
  s.effective_mass_met = need <= 0.0 || met(count);
  s.flap_fraction = count > 0 ? table.flap_cumulative(count - 1) : 0.0;
  s.heave_fraction = count > 0 ? table.heave_cumulative(count - 1) : 0.0;
  return s;
}

}  // namespace orni::structure
