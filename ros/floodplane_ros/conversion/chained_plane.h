// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a node publishes for PCL's ROS filters to chain on, without ROS types: one plane as
// pcl_ros's SACSegmentation nodelet publishes its model, its inliers as indices into the input
// cloud (pcl_msgs/PointIndices) and its coefficients (pcl_msgs/ModelCoefficients), so that
// ExtractIndices and ProjectInliers take floodplane's output where they took SACSegmentation's.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "floodplane/segmenter.h"

namespace floodplane::conversion {

/// One plane in pcl_msgs' terms; both empty for a frame without a plane, as SACSegmentation
/// publishes a frame where it finds no model.
struct ChainedPlane {
  /// Its pixels as row-major indices (v * width + u) into the grid the frame was segmented
  /// from, ascending: indices into the input cloud, or into the cloud a depth image makes.
  std::vector<std::int32_t> indices;
  /// a b c d of a x + b y + c z + d = 0 (PCL's SACMODEL_PLANE), (a b c) the unit normal facing
  /// the sensor, in the frame's coordinates.
  std::vector<float> coefficients;
};

/// The plane a frame's chained outputs carry: SACSegmentation finds one plane, the largest,
/// and so does this: segmentation.planes[0] (they are largest first). One place decides, so
/// that a choice by kind of surface (the floor) can replace it.
ChainedPlane chainedPlane(const Segmentation& segmentation);

/// The pixels of segmentation.planes[plane] (labels equal to plane + 1) as row-major indices,
/// ascending. Throws std::invalid_argument for a plane index out of range, or a grid whose
/// indices do not fit PointIndices' int32.
std::vector<std::int32_t> planeIndices(const Segmentation& segmentation, std::size_t plane);

}  // namespace floodplane::conversion
