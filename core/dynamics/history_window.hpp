// Bounded sampled histories: a run keeps only its last whole cycles in memory (the analyses of the
// last cycle and the periodic start need no more) while the whole run streams to an observer
// (tethered_simulation.hpp, free_flight.hpp), so that memory does not grow with the cycle count.
#pragma once

#include <cstddef>
#include <vector>

namespace orni {

/// How many of the oldest samples to drop from a history of `size` samples that starts at a cycle
/// boundary (`samples_per_cycle` samples per cycle, the first sample of the next cycle ending the
/// last whole one) so that it keeps its last `keep_cycles` (>= 1) whole cycles and the samples
/// after them. With `amortised` nothing is dropped until the history holds 2 keep_cycles whole
/// cycles (then keep_cycles are dropped at once: O(1) work per sample, at most twice the memory).
inline std::size_t oldSamplesToDrop(std::size_t size, std::size_t samples_per_cycle,
                                    std::size_t keep_cycles, bool amortised) {
  if (size == 0 || samples_per_cycle == 0) return 0;
  const std::size_t whole = (size - 1) / samples_per_cycle;
  const std::size_t limit = amortised ? 2 * keep_cycles : keep_cycles;
  if (whole <= keep_cycles || whole < limit) return 0;
  return (whole - keep_cycles) * samples_per_cycle;
}

/// Erases the first `n` elements of `v` (n <= v->size()).
template <class T>
void dropFront(std::vector<T>* v, std::size_t n) {
  v->erase(v->begin(), v->begin() + static_cast<std::ptrdiff_t>(n));
}

}  // namespace orni
