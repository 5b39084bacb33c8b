// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Saving point clouds as PCD files, atomically. The only floodplane file that includes
// pcl/io/pcd_io.h is the matching .cpp, which keeps that heavy header out of every caller.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace floodplane::io {

enum class PcdEncoding {
  binary_compressed,  ///< PCL's LZF-compressed binary format: small, and the default
  binary,             ///< uncompressed binary
  ascii               ///< text, for reading by eye
};

/// Saves `cloud` to `path` through writeFileAtomically, keeping width, height (organized
/// clouds stay organized), is_dense, sensor_origin_ and sensor_orientation_.
/// Throws std::runtime_error naming `path` if the file cannot be written.
/// Instantiated for pcl::PointXYZ, PointXYZI, PointXYZL, PointXYZRGB, PointXYZRGBA,
/// PointXYZRGBL and PointNormal.
template <typename PointT>
void savePcd(const std::string& path, const pcl::PointCloud<PointT>& cloud,
             PcdEncoding encoding = PcdEncoding::binary_compressed);

}  // namespace floodplane::io
