// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>

#include "floodplane/point_grid.h"
#include "util/simd.h"

namespace floodplane {

/// Key of an unordered pair of segment labels.
inline std::uint64_t borderKey(std::int32_t a, std::int32_t b) {
  const std::uint32_t lo = static_cast<std::uint32_t>(a < b ? a : b);
  const std::uint32_t hi = static_cast<std::uint32_t>(a < b ? b : a);
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

/// Calls visit(i, j) for every pair of 4-neighbouring pixels of `labels` (grid.width x
/// grid.height) whose labels differ, neither being 0: j = i + 1 (right) or j = i + width
/// (below), in raster order of i, right before below. The points of `grid` two rows ahead are
/// requested from memory on the way, for a `visit` that reads them: a noisy frame has borders
/// everywhere (some 40,000 pixel pairs on a real Kinect frame).
template <class Label, class Visit>
void forEachLabelBorder(const PointGrid& grid, const Label* labels, Visit&& visit) {
  const std::size_t width = static_cast<std::size_t>(grid.width);
  const std::size_t height = static_cast<std::size_t>(grid.height);
  for (std::size_t y = 0; y < height; ++y) {
    const std::size_t row = y * width;
    const bool has_below = y + 1 < height;
    std::size_t x = 0;
#if FLOODPLANE_SIMD
    // Four pixels at a time: the lanes where a border starts to the right or below, then only
    // those (the right neighbour of the fourth must lie in this row).
    if (has_below) {
      const Label* row_labels = labels + row;
      const bool ahead = y + 2 < height;
      for (; x + 4 < width; x += 4) {
        if (ahead) prefetchRange(grid.point(row + 2 * width + x), grid.point(row + 2 * width + x + 3) + 3);
        const int right = segmentBorderLanes(row_labels + x, row_labels + x + 1);
        const int below = segmentBorderLanes(row_labels + x, row_labels + x + width);
        for (int lanes = right | below; lanes != 0; lanes &= lanes - 1) {
          const int lane = __builtin_ctz(static_cast<unsigned>(lanes));
          const std::size_t i = row + x + static_cast<std::size_t>(lane);
          if (right & (1 << lane)) visit(i, i + 1);
          if (below & (1 << lane)) visit(i, i + width);
        }
      }
    }
#endif
    for (; x < width; ++x) {
      const std::size_t i = row + x;
      const Label a = labels[i];
      if (a == 0) continue;
      if (x + 1 < width && labels[i + 1] != 0 && labels[i + 1] != a) visit(i, i + 1);
      if (has_below && labels[i + width] != 0 && labels[i + width] != a) visit(i, i + width);
    }
  }
}

}  // namespace floodplane
