// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "flood/plane_flood.h"
#include "floodplane/point_grid.h"
#include "util/label_borders.h"

namespace floodplane {

/// Where two segments touch: the pairs of neighbouring pixels, one on either side, as their
/// count, the sum of the points on the side of the segment with the smaller label (`low`) and
/// the sum of the differences across the border (high side minus low side). Sums, so that
/// the mean step across the border along any normal is O(1) and two borders add.
struct SegmentBorder {
  double count = 0.0;
  double lx = 0.0, ly = 0.0, lz = 0.0;  // sum of the low side's points
  double dx = 0.0, dy = 0.0, dz = 0.0;  // sum of (high side's point - low side's point)

  void add(const Vec3& low, const Vec3& high) {
    count += 1.0;
    lx += low.x;
    ly += low.y;
    lz += low.z;
    dx += high.x - low.x;
    dy += high.y - low.y;
    dz += high.z - low.z;
  }
  /// Adds border `o`; `flipped` when o's low side is this border's high side.
  void merge(const SegmentBorder& o, bool flipped) {
    count += o.count;
    if (!flipped) {
      lx += o.lx, ly += o.ly, lz += o.lz;
      dx += o.dx, dy += o.dy, dz += o.dz;
    } else {
      lx += o.lx + o.dx, ly += o.ly + o.dy, lz += o.lz + o.dz;
      dx -= o.dx, dy -= o.dy, dz -= o.dz;
    }
  }
  /// The mean of the border's points (both sides).
  Eigen::Vector3d meanPoint() const {
    if (count <= 0.0) return Eigen::Vector3d::Zero();
    return Eigen::Vector3d(lx + 0.5 * dx, ly + 0.5 * dy, lz + 0.5 * dz) / count;
  }
  /// The mean difference across the border, high side minus low side.
  Eigen::Vector3d meanStep() const {
    if (count <= 0.0) return Eigen::Vector3d::Zero();
    return Eigen::Vector3d(dx, dy, dz) / count;
  }
};

using SegmentBorderMap = std::unordered_map<std::uint64_t, SegmentBorder>;

/// The borders between segments after the floods and the relabelling, in one pass over the
/// segment image: every pair of 4-neighbouring pixels of two different segments whose points
/// are 3-D neighbours (Eq. 3 under the first segment's criterion).
///
/// A real plane that bends out of one flood's band is cut into segments that meet without a
/// step; two parallel surfaces (a board on a wall, a door in its frame) meet with one. The
/// merge test (MergeCriterion::continuous) tells them apart here, at the border, where the
/// centroids of Eq. 9 and the least-squares fit of the union cannot: a bend moves both as
/// much as a step does.
class SegmentBorders {
 public:
  void collect(const PointGrid& grid, const std::vector<std::int32_t>& labels, const std::vector<Segment>& segments);
  const SegmentBorderMap& borders() const { return borders_; }
  /// For the merger, which adds up the borders of the segments it merges.
  SegmentBorderMap& mutableBorders() { return borders_; }

 private:
  SegmentBorderMap borders_;
};

}  // namespace floodplane
