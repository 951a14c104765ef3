// The modal-wing cache (core/dynamics/modal_wing_cache.hpp, issue 15 item 9): owned by its user,
// keyed by the wing's own structural inputs (nothing else of the vehicle), bounded, and a dropped
// wing rebuilt with the same bits.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/modal_wing_cache.hpp"
#include "core/model/vehicle_fields.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni {
namespace {

VehicleModel efw() {
  VehicleModel v =
      studies::loadVehicleFile(std::string(ORNI_SOURCE_DIR) + "/studies/vehicles/efw_magpie.toml")
          .model;
  v.wing.structure = StructureLevel::kFlexible;
  v.wing.fe.element_size_m = 0.02;  // a coarse mesh: quick builds, same cache logic
  v.wing.fe.max_modes = 6;
  return v;
}

/// Resident memory of this process (kB), from /proc/self/statm (0 where there is none).
long residentKb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) return 0;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

TEST(ModalWingCache, BuildsOncePerStructure) {
  ModalWingCache cache;
  const VehicleModel v = efw();
  const auto a = cache.get(v);
  EXPECT_EQ(cache.buildCount(), 1);
  EXPECT_EQ(cache.get(v).get(), a.get());
  EXPECT_EQ(cache.buildCount(), 1);
  // What the FE model is not built from does not change the key: the inertial-stiffness model
  // (applied in the dynamics), the air, the tail, the body, the flapping. (The design point is
  // not part of the model: VehicleDefinition.)
  VehicleModel same_wing = v;
  same_wing.wing.fe.inertial_stiffness = InertialStiffness::kNone;
  same_wing.air.density_kgpm3 *= 0.9;
  same_wing.tail.arm_m *= 1.1;
  same_wing.body.mass_kg *= 1.1;
  same_wing.flapping.hinge_x_B_m += 0.01;
  EXPECT_EQ(modalWingKey(same_wing), modalWingKey(v));
  EXPECT_EQ(cache.get(same_wing).get(), a.get());
  // Any structural change rebuilds: a material, a member, the skin, the mesh, the modes.
  int builds = 1;
  auto expectRebuild = [&](const VehicleModel& w, const char* what) {
    EXPECT_NE(modalWingKey(w), modalWingKey(v)) << what;
    EXPECT_NE(cache.get(w).get(), a.get()) << what;
    EXPECT_EQ(cache.buildCount(), ++builds) << what;
  };
  VehicleModel w = v;
  w.materials.front().youngs_modulus_pa *= 1.01;
  expectRebuild(w, "a material's Young's modulus");
  w = v;
  w.wing.members.front().diameter_m *= 1.01;
  expectRebuild(w, "a member's diameter");
  w = v;
  w.wing.skin.thickness_m *= 1.01;
  expectRebuild(w, "the skin's thickness");
  w = v;
  w.wing.fe.element_size_m *= 0.9;
  expectRebuild(w, "the element size");
  w = v;
  w.wing.fe.max_modes = 4;
  expectRebuild(w, "the mode count");
}

/// True when two modal wings differ in anything the dynamics reads from them.
bool differ(const structure::ModalWing& a, const structure::ModalWing& b) {
  return a.frequencies_hz.size() != b.frequencies_hz.size() ||
         a.frequencies_hz != b.frequencies_hz || a.damping_ratios != b.damping_ratios ||
         a.mode_shapes.rows() != b.mode_shapes.rows() || a.mode_shapes != b.mode_shapes ||
         a.nodal_mass_kg.size() != b.nodal_mass_kg.size() || a.nodal_mass_kg != b.nodal_mass_kg ||
         a.wing_mass_kg != b.wing_mass_kg || a.mesh.strip_nodes.size() != b.mesh.strip_nodes.size();
}

// The key is written by hand; this proves it complete over the field table: every number of the
// wing and its materials (vehicle_fields.hpp) is moved by 5 % (one step for an integer), the wing
// built again, and whenever the built wing differs the key must differ too (else the cache would
// hand out a stale wing). Numbers that do not change the wing may keep the key (the incidence is
// aerodynamic only). A guard: most of them must change the wing, or the test proves nothing.
TEST(ModalWingCache, KeyChangesWithEveryFieldThatChangesTheWing) {
  const VehicleModel v = efw();
  const auto base = buildModalWingOf(v);
  const std::string base_key = modalWingKey(v);
  int structural = 0, checked = 0;
  for (const VehicleNumber& n : vehicleNumbers()) {
    if (!(n.key.rfind("wing.", 0) == 0 || n.key.rfind("materials.", 0) == 0)) continue;
    const std::size_t last = n.count(v) - 1;
    for (std::size_t index : {std::size_t{0}, last}) {
      const double x = n.get(v, index);
      const bool integer = n.spec().type == FieldType::kInteger;
      const ValueRange r = n.spec().siRange();
      // The first move that is in range and gives a wing that builds (a member's end moved by
      // 5 % may leave the planform or cross another member; 0.2 mm does not; a frequency
      // cut-off of 0, i.e. none, moved to 0.2 mHz keeps no mode, 100 Hz keeps the lowest).
      const std::vector<double> moves =
          integer ? std::vector<double>{x + 1.0, x - 1.0}
                  : std::vector<double>{1.05 * x, 0.95 * x, 1.01 * x, 0.99 * x, x + 2e-4, x - 2e-4,
                                                x + 100.0};
      VehicleModel w = v;
      std::shared_ptr<const structure::ModalWing> built;
      std::string why = "no move in range";
      for (double moved : moves) {
        if (moved == x || !r.contains(moved)) continue;
        w = v;
        n.set(w, index, moved);
        if (n.component >= 0) {
          // A member's end point: moved 1 % along the member, towards its other end, so that
          // it stays in the planform and crosses no other member (both components move).
          const WingMember& m0 = v.wing.members[index];
          WingMember& m = w.wing.members[index];
          const bool start = n.key.find("start") != std::string_view::npos;
          const double ax = start ? m0.start_x_W_m : m0.end_x_W_m;
          const double ay = start ? m0.start_y_W_m : m0.end_y_W_m;
          const double bx = start ? m0.end_x_W_m : m0.start_x_W_m;
          const double by = start ? m0.end_y_W_m : m0.start_y_W_m;
          (start ? m.start_x_W_m : m.end_x_W_m) = ax + 0.01 * (bx - ax);
          (start ? m.start_y_W_m : m.end_y_W_m) = ay + 0.01 * (by - ay);
        }
        try {
          built = buildModalWingOf(w);
          break;
        } catch (const std::exception& e) {
          why = e.what();
        }
      }
      if (!built) {
        ADD_FAILURE() << n.key << "[" << index << "] component " << n.component
                      << ": no moved wing builds: " << why;
        continue;
      }
      ++checked;
      if (!differ(*built, *base)) {
        std::printf("modal wing key: %.*s does not change the wing\n",
                    static_cast<int>(n.key.size()), n.key.data());
        continue;
      }
      ++structural;
      EXPECT_NE(modalWingKey(w), base_key)
          << n.key << "[" << index << "] component " << n.component
          << " changes the modal wing but not the cache key";
    }
  }
  std::printf("modal wing key: %d of %d moved wing numbers change the wing\n", structural, checked);
  EXPECT_GE(checked, 30);
  EXPECT_GE(structural, 20);
}

// wing.fe.static_shapes_pa is a list (the loop above moves numbers): its pressures and their
// count are in the key.
TEST(ModalWingCache, KeyChangesWithTheStaticShapes) {
  VehicleModel v = efw();
  v.wing.fe.nonlinear = true;
  const std::string none = modalWingKey(v);
  v.wing.fe.static_shapes_pa = {1.0};
  const std::string one = modalWingKey(v);
  v.wing.fe.static_shapes_pa = {1.5};
  const std::string other = modalWingKey(v);
  v.wing.fe.static_shapes_pa = {1.0, 1.0};
  const std::string two = modalWingKey(v);
  EXPECT_NE(none, one);
  EXPECT_NE(one, other);
  EXPECT_NE(one, two);
  EXPECT_NE(none, two);
}

TEST(ModalWingCache, IsBoundedAndRebuildsTheSameWing) {
  ModalWingCache cache(4);
  const VehicleModel v = efw();
  const auto first = cache.get(v);
  const long rss0 = residentKb();
  // More distinct wings than the cache keeps: the size stays at the bound.
  for (std::size_t k = 1; k <= cache.capacity() + 3; ++k) {
    VehicleModel w = v;
    w.wing.member_diameter_scale = 1.0 + 0.01 * static_cast<double>(k);
    cache.get(w);
    EXPECT_LE(cache.size(), cache.capacity());
  }
  std::printf("modal wing cache: %zu wings, resident memory +%ld kB for %zu coarse wings\n",
              cache.size(), residentKb() - rss0, cache.capacity() + 3);
  EXPECT_EQ(cache.size(), cache.capacity());
  // The first wing was dropped (least recently used): asked again it is built again, with the
  // same data (the build is deterministic), while the copy we hold stays valid.
  const long builds = cache.buildCount();
  const auto again = cache.get(v);
  EXPECT_EQ(cache.buildCount(), builds + 1);
  EXPECT_NE(again.get(), first.get());
  ASSERT_EQ(again->frequencies_hz.size(), first->frequencies_hz.size());
  for (Eigen::Index k = 0; k < first->frequencies_hz.size(); ++k)
    EXPECT_EQ(again->frequencies_hz[k], first->frequencies_hz[k]) << k;
  EXPECT_EQ(again->mode_shapes, first->mode_shapes);
  // The most recent one is kept: no build.
  EXPECT_EQ(cache.get(v).get(), again.get());
  EXPECT_EQ(cache.buildCount(), builds + 1);
  EXPECT_THROW(ModalWingCache(0), std::invalid_argument);
}

TEST(ModalWingCache, FlightCoreModelTakesItsWingFromTheCallersCache) {
  const VehicleModel v = efw();
  ModalWingCache cache;
  const FlightCoreModel a(v, FlightCoreModel::Checks::kRequired, &cache);
  const FlightCoreModel b(v.mainWingAlone(), FlightCoreModel::Checks::kRequired, &cache);
  ASSERT_TRUE(a.flexible && b.flexible);
  EXPECT_EQ(a.flexible->modal.get(), b.flexible->modal.get());
  EXPECT_EQ(cache.buildCount(), 1);
  EXPECT_EQ(a.modal_wing_cache, &cache);
  // Without a cache the model builds its own wing, with the same bits.
  const FlightCoreModel alone(v);
  ASSERT_TRUE(alone.flexible);
  EXPECT_NE(alone.flexible->modal.get(), a.flexible->modal.get());
  EXPECT_EQ(alone.flexible->modal->frequencies_hz, a.flexible->modal->frequencies_hz);
  EXPECT_EQ(alone.modal_wing_cache, nullptr);
}

}  // namespace
}  // namespace orni
