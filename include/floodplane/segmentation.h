// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The result of one segmentation: a label per pixel and the planes, with the noise it assumed
// and what it measured about itself. Plain types: what Segmenter::segment returns
// (floodplane/segmenter.h) and what the stages after it (tracking, plane classes, objects) read.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "floodplane/noise_model.h"
#include "floodplane/plane_fit.h"
#include "floodplane/segmentation_stats.h"

/// \file
/// floodplane::Segmentation, the result of one segmentation, and its planes.

namespace floodplane {

/// One plane found in the cloud.
struct SegmentedPlane {
  PlaneFit fit;                    ///< least-squares plane of the inliers (sensor frame)
  std::uint32_t inlier_count = 0;  ///< pixels at full resolution
  /// Where its boundary starts: its first pixel in raster order; at sub-sampling s > 1 the left
  /// end of the row through the first pixel of its body (the first block inside it), so
  /// that a stray pixel that fits the plane apart from it does not stand for its boundary.
  std::size_t first_pixel = 0;
};

/// The result: a label per pixel of the full-resolution grid and the planes.
struct Segmentation {
  int width = 0;                       ///< the grid's width (points per row)
  int height = 0;                      ///< the grid's height (rows)
  std::vector<std::uint32_t> labels;   ///< row-major; 0 = no plane, k = planes[k - 1]
  std::vector<SegmentedPlane> planes;  ///< largest first
  NoiseModel noise;                    ///< the depth noise the segmentation assumed
  PhaseTimes phases;                   ///< time per phase, with Segmenter::Options::measure_phases
  SegmentationStats stats;             ///< counts of what happened inside

  /// Appends the outer boundary of planes[plane] to `contour`: linear pixel indices in order,
  /// clockwise on screen (y down), 8-connected, starting at the plane's first pixel; a pixel
  /// on a one-pixel-wide neck appears twice. Costs the boundary's length, not the area.
  /// \param plane        index into planes (label - 1)
  /// \param[out] contour the boundary's pixels are appended to it
  void boundary(std::size_t plane, std::vector<int>& contour) const;
};

}  // namespace floodplane
