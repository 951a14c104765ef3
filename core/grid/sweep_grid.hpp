// The points of a sweep (docs/design.md 5: a study of another kind over a grid of vehicle or
// analysis values): the full factorial of its axes, the first axis outermost.
//
// Axis k has sizes[k] values; point `index` takes value axisIndices(index)[k] of axis k, with the
// last axis varying fastest:
//   index = (...((i_0 * n_1 + i_1) * n_2 + i_2) ...) * n_{K-1} + i_{K-1}.
// This is the row order of sweep.csv. No file I/O, no values: the runner holds the axes.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace orni {

/// Largest sweep (points). Every point is a whole run (a trim, a simulation) and the runner keeps
/// one resolved study per point.
constexpr std::size_t kMaxSweepPoints = 10000;

/// Largest number of axes of a sweep.
constexpr std::size_t kMaxSweepAxes = 16;

struct SweepGrid {
  std::vector<std::size_t> sizes;  ///< values per axis, in axis order (first = outermost)

  /// Number of points: the product of the sizes (1 for no axes).
  std::size_t size() const;
  /// Index per axis of point `index` < size().
  std::vector<std::size_t> axisIndices(std::size_t index) const;
  /// The point of the given per-axis indices (inverse of axisIndices).
  std::size_t pointIndex(const std::vector<std::size_t>& axis_indices) const;
  /// True when there are 1..kMaxSweepAxes axes, each with >= 1 value, and at most
  /// kMaxSweepPoints points; otherwise false with the reason in *why.
  bool IsValid(std::string* why) const;
};

}  // namespace orni
