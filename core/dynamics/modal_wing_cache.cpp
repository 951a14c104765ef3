#include "core/dynamics/modal_wing_cache.hpp"

#include <stdexcept>
#include <utility>

#include "core/structure/wing_mesh.hpp"

namespace orni {

namespace {

void appendBytes(std::string* key, const void* p, std::size_t n) {
  key->append(static_cast<const char*>(p), n);
}
void appendDouble(std::string* key, double v) { appendBytes(key, &v, sizeof v); }

}  // namespace

std::string modalWingKey(const structure::WingStructure& wing_structure) {
  std::string k;
  const WingModel& w = wing_structure.wing;
  const int planform = static_cast<int>(w.planform);
  appendBytes(&k, &planform, sizeof planform);
  for (double d : {w.semispan_m, w.root_chord_m, w.p3_aft_of_le_m, w.skin.thickness_m,
                   w.skin.pretension_N_per_m,
                   w.fe.element_size_m, w.fe.cutoff_hz, w.fe.damping_ratio})
    appendDouble(&k, d);
  appendBytes(&k, &w.strip_count, sizeof w.strip_count);  // the mesh samples every strip
  appendDouble(&k, w.member_diameter_scale);
  appendBytes(&k, &w.fe.max_modes, sizeof w.fe.max_modes);
  k.push_back(w.fe.p3_cross_axis_normal ? 'n' : 's');
  k.push_back(static_cast<char>('0' + static_cast<int>(w.fe.p3_joint)));
  k.push_back(w.fe.root_edge_pinned ? 'r' : '-');
  k.push_back(w.fe.nonlinear ? 'N' : 'L');
  const std::size_t shapes = w.fe.static_shapes_pa.size();
  appendBytes(&k, &shapes, sizeof shapes);
  for (double p : w.fe.static_shapes_pa) appendDouble(&k, p);
  k += w.skin.material + '\0';
  for (const WingMember& m : w.members) {
    k += m.name + '\0' + m.material + '\0';
    for (double d : {m.diameter_m, m.start_x_W_m, m.start_y_W_m, m.end_x_W_m, m.end_y_W_m})
      appendDouble(&k, d);
  }
  for (const Material& m : wing_structure.materials) {
    k += m.name + '\0';
    for (double d : {m.youngs_modulus_pa, m.poisson_ratio, m.density_kgpm3}) appendDouble(&k, d);
  }
  return k;
}

std::shared_ptr<const structure::ModalWing> buildModalWingOf(
    const structure::WingStructure& wing_structure) {
  const WingFeSettings& fe = wing_structure.wing.fe;
  const structure::WingMesh mesh = structure::buildWingMesh(wing_structure, fe.element_size_m);
  return std::make_shared<const structure::ModalWing>(
      structure::buildModalWing(wing_structure, mesh, structure::modalWingOptionsOf(fe)));
}

ModalWingCache::ModalWingCache(std::size_t capacity) : capacity_(capacity) {
  if (capacity_ == 0) throw std::invalid_argument("ModalWingCache: capacity must be >= 1");
}

std::shared_ptr<const structure::ModalWing> ModalWingCache::get(
    const structure::WingStructure& wing_structure) {
  const std::string key = modalWingKey(wing_structure);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = entries_.find(key);
    if (it != entries_.end()) {
      recency_.splice(recency_.begin(), recency_, it->second.recency);
      return it->second.wing;
    }
  }
  std::shared_ptr<const structure::ModalWing> built = buildModalWingOf(wing_structure);
  std::lock_guard<std::mutex> lock(mutex_);
  ++builds_;
  return keepLocked(key, std::move(built));
}

void ModalWingCache::insert(const structure::WingStructure& wing_structure,
                            std::shared_ptr<const structure::ModalWing> wing) {
  const std::string key = modalWingKey(wing_structure);
  std::lock_guard<std::mutex> lock(mutex_);
  keepLocked(key, std::move(wing));
}

std::shared_ptr<const structure::ModalWing> ModalWingCache::keepLocked(
    const std::string& key, std::shared_ptr<const structure::ModalWing> wing) {
  auto it = entries_.find(key);  // another thread may have built it meanwhile: keep the first
  if (it != entries_.end()) {
    recency_.splice(recency_.begin(), recency_, it->second.recency);
    return it->second.wing;
  }
  recency_.push_front(key);
  entries_.emplace(key, Entry{wing, recency_.begin()});
  while (entries_.size() > capacity_) {
    entries_.erase(recency_.back());
    recency_.pop_back();
  }
  return wing;
}

std::size_t ModalWingCache::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

long ModalWingCache::buildCount() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return builds_;
}

}  // namespace orni
