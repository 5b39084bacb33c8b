// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The labelled cloud's file, in either encoding.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcd_segment {

/// The bytes of the PCD file of `cloud` (pcl::PointXYZL or pcl::PointXYZRGBL): binary
/// compressed, or text with `ascii`, for floodplane::io::AtomicFileGroup to write with the
/// input's other outputs. Built in memory rather than by PCL's writers, which open the file
/// themselves and do not check every write (PCL's writeASCII left a truncated file on a full
/// disk) nor say the system's reason.
template <typename PointT>
std::string labelPcdBytes(const pcl::PointCloud<PointT>& cloud, bool ascii);

/// The ASCII PCD text of `cloud` (9 significant digits, which round-trip every float).
template <typename PointT>
std::string asciiPcd(const pcl::PointCloud<PointT>& cloud);

}  // namespace pcd_segment
