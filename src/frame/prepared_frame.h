// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "floodplane/point_grid.h"
#include "frame/block_grid.h"
#include "frame/flood_grid.h"
#include "frame/hole_filling.h"
#include "models/tolerances.h"

namespace floodplane {

/// A frame as every stage after its preparation sees it, in one value: the grid that is
/// segmented at full resolution, its tolerances, and at sub-sampling s > 1 the block grid the
/// coarse pass segments first.
struct PreparedFrame {
  /// The caller's grid.
  PointGrid measured;
  /// The grid the fine pass segments, at full resolution: the measured grid with its small
  /// holes filled and its noise smoothed (the same as `measured` where neither applies).
  PointGrid grid;
  float pitch = 0.f;  ///< the angle between neighbouring pixels' viewing rays [rad]
  /// The depth noise of `grid`'s points and every length derived from it.
  Tolerances tolerances;
  /// The depth noise of the measured pixels (before smoothing) and its lengths.
  Tolerances measured_tolerances;
  /// Which points of `grid` were filled in (never labelled).
  const HoleFilling* holes = nullptr;

  /// Coarse to fine (sub-sampling s > 1): the blocks of s x s pixels, read once, and the grid
  /// of their means that the coarse pass segments (holes filled), with the means' noise.
  /// Null and empty at s = 1.
  int subsampling = 1;
  const BlockGrid* blocks = nullptr;
  FloodGrid coarse;
};

}  // namespace floodplane
