// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <vector>

#include "floodplane/point_grid.h"
#include "models/depth_noise.h"

namespace floodplane {

/// Beyond the paper: an edge-preserving 3 x 3 mean of the points before segmenting. A depth
/// camera's noise is largely independent from pixel to pixel, so the mean of a point and its
/// neighbours on the same surface is a third as noisy (on the Kinect model; a real Kinect's
/// noise is correlated over a few pixels and loses a quarter). The flood's tolerances follow
/// (the noise is measured again on the smoothed frame), and surfaces a few noise deviations
/// apart, which the raw points cannot tell apart, separate: a board on a wall, a shelf's back
/// in front of the wall, the tread and riser of a stair at 4 m.
///
/// Only neighbours within 3 sqrt(2) noise deviations of a point in depth take part in its mean
/// (a row pass, then a column pass): across a depth step the surfaces keep their own points.
/// Holes stay holes. The output has four floats a point.
class DepthSmoothing {
 public:
  /// How many points at a time where the grid has four floats a point: as many as the CPU
  /// runs (eight with AVX, else four), or four (SSE2) for tests that compare the two.
  enum class VectorWidth { kWidest, kSse2 };

  explicit DepthSmoothing(VectorWidth width = VectorWidth::kWidest) : width_(width) {}

  /// The smoothed `grid` (valid until the next call).
  const PointGrid& smooth(const PointGrid& grid, const NoiseModel& noise);

 private:
  VectorWidth width_;
  std::vector<float> rows_;  // three rows after the row pass
  std::vector<float> result_points_;
  PointGrid result_;
};

}  // namespace floodplane
