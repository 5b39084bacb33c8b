// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The label cloud a node publishes, without ROS types: the input's grid with each point's
// plane label and that label's colour, as an organized sensor_msgs/PointCloud2 whose fields
// PCL (pcl::PointXYZRGBL) and rviz (colour by rgb or by label) both read.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cloud_points.h"
#include "floodplane/point_grid.h"

namespace floodplane::conversion {

/// Bytes a point of the label cloud takes: x y z rgb (float32; rgb packed as PCL packs it)
/// and label (uint32).
inline constexpr std::uint32_t kLabelCloudPointStep = 20;

/// The label cloud's fields: x, y, z, rgb, label at offsets 0, 4, 8, 12, 16.
std::vector<PointField> labelCloudFields();

/// Writes grid.size() points of kLabelCloudPointStep bytes each to `out`, row-major: the
/// grid's x y z (NaN kept), and for labels[i] = k > 0 the label plane_labels[k - 1] with its
/// io::labelColor; for k = 0 label 0 and that colour. `labels` is a Segmentation's label image
/// of the grid, `plane_labels` the published label of each of its planes (1..K, or track
/// ids). Throws std::invalid_argument when labels does not fill the grid or names a plane
/// plane_labels lacks.
void writeLabelCloud(const PointGrid& grid, const std::vector<std::uint32_t>& labels,
                     const std::vector<std::uint32_t>& plane_labels, std::uint8_t* out);

/// The colour io::labelColor gives `label`, packed as PCL packs rgb (0x00RRGGBB in a float32's
/// bits).
float packedLabelColor(std::uint32_t label);

}  // namespace floodplane::conversion
