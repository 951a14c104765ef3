// A cache of modal wings, owned by whoever builds many FlightCoreModels of one wing (the FE build
// dominates their cost): an optimisation over the tail (each design the same wing), a sweep or
// sensitivity study over non-structural keys, a trim that shifts the CG. Keyed by the wing's own
// structural inputs (structure::WingStructure: the wing and its materials, nothing else of the
// vehicle), bounded (least recently used dropped first). A dropped wing is rebuilt with the same bits.
#pragma once

#include <cstddef>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "core/structure/modal_wing.hpp"
#include "core/structure/wing_structure.hpp"

namespace orni {

/// The modal wing of a structure (mesh with wing.fe.element_size_m, modes per wing.fe), built
/// without a cache.
std::shared_ptr<const structure::ModalWing> buildModalWingOf(
    const structure::WingStructure& wing_structure);

/// The exact bytes of every structural input of the wing (no hashing, so no collisions). Written
/// as a list; ModalWingCache.KeyChangesWithEveryFieldThatChangesTheWing moves every wing and
/// material number of the field table (vehicle_fields.hpp) and fails when one changes the built
/// wing but not this key.
std::string modalWingKey(const structure::WingStructure& wing_structure);

class ModalWingCache {
 public:
  /// A multi-start optimisation over the stiffeners needs the current design of each start and
  /// the baseline (tests/unit/dynamics/test_flexible_tethered.cpp prints what a wing costs).
  static constexpr std::size_t kDefaultCapacity = 16;

  explicit ModalWingCache(std::size_t capacity = kDefaultCapacity);
  ModalWingCache(const ModalWingCache&) = delete;
  ModalWingCache& operator=(const ModalWingCache&) = delete;

  /// The wing of `wing_structure`, from the cache or built (then kept). Thread-safe; two threads
  /// asking for one new wing may both build it, the first stored is returned to both.
  std::shared_ptr<const structure::ModalWing> get(const structure::WingStructure& wing_structure);
  /// Keep `wing` as the wing of `wing_structure` (a wing built elsewhere from the same inputs).
  void insert(const structure::WingStructure& wing_structure,
              std::shared_ptr<const structure::ModalWing> wing);

  std::size_t size() const;
  std::size_t capacity() const { return capacity_; }
  /// Wings built by get() (not found in the cache).
  long buildCount() const;

 private:
  struct Entry {
    std::shared_ptr<const structure::ModalWing> wing;
    std::list<std::string>::iterator recency;  // position in recency_ (front: most recent)
  };
  // Under mutex_: keeps `wing` under `key` (or returns the one already there), evicts.
  std::shared_ptr<const structure::ModalWing> keepLocked(
      const std::string& key, std::shared_ptr<const structure::ModalWing> wing);

  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::map<std::string, Entry> entries_;
  std::list<std::string> recency_;
  long builds_ = 0;
};

}  // namespace orni
