// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <vector>

#include "floodplane/point_grid.h"
#include "models/tolerances.h"

namespace floodplane {

/// Beyond the paper: small holes in a surface are bridged before segmenting. A structured-
/// light scanner loses a third of its returns on dark or grazing surfaces, pixel by pixel; the
/// survivors then fall below the percolation threshold of a 4-connected grid (59 %), so no
/// flood and no seed cross can cross such a surface although most of it is measured.
///
/// A run of at most kMaxGap missing pixels in a row, then in a column, between two measured
/// points that are 3-D neighbours across the gap (their distance at most what that many pixels
/// of a surface at up to kMaxObliquity can span, plus the noise of both) is filled by linear
/// interpolation between them: on a plane the filled points lie on the plane. The filled grid
/// is a copy with four floats a point; the fourth marks a filled point (1) and is 0 for a
/// measured one. Segmentation sees the filled points; the output never labels them.
///
/// A frame is filled only when it has such holes in numbers (a few percent of its pixels): a
/// Kinect's holes are shadows and far walls, wide regions that this leaves alone, and a copy of
/// the grid would cost more than it brings there.
class HoleFilling {
 public:
  static constexpr int kMaxGap = 5;

  /// `grid` itself when it has few bridgeable holes, otherwise the filled copy (valid until
  /// the next call).
  const PointGrid& fill(const PointGrid& grid, const Tolerances& tolerances);
  /// Whether the last fill() made a copy.
  bool filled() const { return filled_; }
  /// Whether point `index` of the last filled grid was filled in (not measured).
  bool isFilled(std::size_t index) const { return filled_ && points_[4 * index + 3] != 0.f; }

 private:
  // The share of sampled pixels that are bridgeable holes.
  double bridgeableShare(const PointGrid& grid, const Tolerances& tolerances) const;
  // Bridges the gaps of one line of `count` points `step` points apart from `first`.
  void fillLine(std::size_t first, std::ptrdiff_t step, int count, const Tolerances& tolerances);

  std::vector<float> points_;
  PointGrid filled_grid_;
  // The unfilled grid as fill() returns it: a copy, so that the reference fill() returns stays
  // valid when the caller's grid was a temporary (PointGrid is a view, copies are cheap).
  PointGrid source_;
  bool filled_ = false;
};

}  // namespace floodplane
