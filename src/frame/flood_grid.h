// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "floodplane/point_grid.h"
#include "models/tolerances.h"

namespace floodplane {

/// The grid a flood pass segments and what it needs to know of it.
struct FloodGrid {
  PointGrid points;
  Tolerances tolerances;  ///< the depth noise of `points` and every length derived from it
  float pitch = 0.f;      ///< the angle between neighbouring points' viewing rays [rad]
  /// How many pixels of the frame a point stands for along each axis (a block's side; 1: the
  /// pixels themselves): the seed lattice and the smallest pieces count pixels of the frame.
  int factor = 1;
  /// No noise worth the name (exact data): the second seeding pass seeds smaller.
  bool noise_free = false;
};

}  // namespace floodplane
