// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "floodplane/point_grid.h"
#include "stages/block_grid.h"
#include "stages/hole_filling.h"
#include "stages/tolerances.h"

namespace floodplane {

/// A frame as every stage after its preparation sees it, in one value: the grid that is
/// segmented, its tolerances, and how it relates to the caller's pixels.
struct PreparedFrame {
  /// The caller's grid, at full resolution.
  PointGrid measured;
  /// The grid that is segmented. Sub-sampling 1: the measured grid with its small holes
  /// filled and its noise smoothed (the same as `measured` where neither applies). s > 1: the
  /// means of the s x s blocks (`blocks`), holes filled.
  PointGrid grid;
  int subsampling = 1;
  float pitch = 0.f;       ///< the angle between neighbouring points of `grid` [rad]
  float full_pitch = 0.f;  ///< that of `measured`
  /// The depth noise of `grid`'s points and every length derived from it.
  Tolerances tolerances;
  /// The depth noise of the measured pixels and its lengths: the full-resolution write's.
  Tolerances pixel_tolerances;
  /// Which points of `grid` were filled in (never labelled).
  const HoleFilling* holes = nullptr;
  /// s > 1: the blocks `grid` holds the means of; null at s = 1.
  const BlockGrid* blocks = nullptr;
};

}  // namespace floodplane
