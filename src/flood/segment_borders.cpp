// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "flood/segment_borders.h"

#include "models/flood_criterion.h"
#include "util/label_borders.h"

namespace floodplane {

void SegmentBorders::collect(const PointGrid& grid, const std::vector<std::int32_t>& labels,
                             const std::vector<Segment>& segments) {
  borders_.clear();
  // Along a border the pair repeats pixel after pixel: one lookup per change of pair (the
  // map's entries stay where they are as it grows).
  std::uint64_t last_key = 0;  // 0: none (label 0 is never part of a pair)
  SegmentBorder* last = nullptr;
  const auto touch = [&](std::int32_t a, std::size_t i, std::int32_t b, std::size_t j) {
    const Vec3 p = Vec3::load(grid.point(i));
    const Vec3 q = Vec3::load(grid.point(j));
    if (!(squaredEuclideanDistance(p, q) < segments[a].criterion.euclideanToleranceSq(noiseRangeSq(p, q)))) return;
    const std::uint64_t key = borderKey(a, b);
    if (key != last_key) {
      last = &borders_[key];
      last_key = key;
    }
    if (a < b)
      last->add(p, q);
    else
      last->add(q, p);
  };
  forEachLabelBorder(grid, labels.data(), [&](std::size_t i, std::size_t j) { touch(labels[i], i, labels[j], j); });
}

}  // namespace floodplane
