#include "core/grid/sweep_grid.hpp"

#include <stdexcept>

namespace orni {

std::size_t SweepGrid::size() const {
  std::size_t n = 1;
  for (const std::size_t k : sizes) n *= k;
  return n;
}

std::vector<std::size_t> SweepGrid::axisIndices(std::size_t index) const {
  std::vector<std::size_t> i(sizes.size(), 0);
  for (std::size_t k = sizes.size(); k-- > 0;) {
    i[k] = index % sizes[k];
    index /= sizes[k];
  }
  return i;
}

std::size_t SweepGrid::pointIndex(const std::vector<std::size_t>& axis_indices) const {
  if (axis_indices.size() != sizes.size())
    throw std::invalid_argument("SweepGrid::pointIndex: one index per axis expected");
  std::size_t index = 0;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    if (axis_indices[k] >= sizes[k])
      throw std::invalid_argument("SweepGrid::pointIndex: axis index out of range");
    index = index * sizes[k] + axis_indices[k];
  }
  return index;
}

bool SweepGrid::IsValid(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (sizes.empty()) return fail("a sweep needs at least one axis");
  if (sizes.size() > kMaxSweepAxes)
    return fail("a sweep has at most " + std::to_string(kMaxSweepAxes) + " axes");
  std::size_t n = 1;
  for (const std::size_t k : sizes) {
    if (k == 0) return fail("every axis needs at least one value");
    if (k > kMaxSweepPoints / n)
      return fail("the sweep has more than " + std::to_string(kMaxSweepPoints) + " points");
    n *= k;
  }
  return true;
}

}  // namespace orni
