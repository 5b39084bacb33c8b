// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The labelled cloud the tools write for a segmented frame: the input's points (and colour,
// when it has some), grid and sensor pose, with each point's plane label.

#include <pcl/common/io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace floodplane::io {

/// `points` with `labels[i]` (0 no plane, k plane k) as the label of point i. PointOut is
/// pcl::PointXYZL for PointXYZ input, pcl::PointXYZRGBL for PointXYZRGB. Throws
/// std::invalid_argument when there is not one label per point.
template <typename PointOut, typename PointIn>
pcl::PointCloud<PointOut> labelledCloud(const pcl::PointCloud<PointIn>& points,
                                        const std::vector<std::uint32_t>& labels) {
  if (labels.size() != points.size()) {
    throw std::invalid_argument("labelledCloud: " + std::to_string(labels.size()) + " labels for " +
                                std::to_string(points.size()) + " points");
  }
  pcl::PointCloud<PointOut> out;
  pcl::copyPointCloud(points, out);  // keeps the grid, is_dense and the sensor pose
  for (std::size_t i = 0; i < out.size(); ++i) out[i].label = labels[i];
  return out;
}

}  // namespace floodplane::io
