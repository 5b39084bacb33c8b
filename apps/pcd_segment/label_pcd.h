// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writing the labelled cloud, atomically, in either encoding.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcd_segment {

/// Saves `cloud` (pcl::PointXYZL or pcl::PointXYZRGBL) to `path` through
/// floodplane::io::writeFileAtomically: binary compressed, or text with `ascii`.
///
/// The text form is built in memory and written with writeBytesAtomically, which checks the
/// stream: PCL's writeASCII does not, so a failed write (disk full, file size limit) left a
/// truncated file that savePcd then renamed over the previous output.
template <typename PointT>
void writeLabelPcd(const std::string& path, const pcl::PointCloud<PointT>& cloud, bool ascii);

/// The ASCII PCD text of `cloud` (9 significant digits, which round-trip every float).
template <typename PointT>
std::string asciiPcd(const pcl::PointCloud<PointT>& cloud);

}  // namespace pcd_segment
