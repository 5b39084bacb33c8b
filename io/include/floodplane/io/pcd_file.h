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

/// Saves `cloud` to `path` atomically, keeping width, height (organized clouds stay
/// organized), is_dense, sensor_origin_ and sensor_orientation_.
/// Throws std::runtime_error naming `path` if the file cannot be written, with the system's
/// reason ("No space left on device"): every encoding is made in memory (encodePcd) and
/// written by writeBytesAtomically, which checks each write.
/// Instantiated for pcl::PointXYZ, PointXYZI, PointXYZL, PointXYZRGB, PointXYZRGBA,
/// PointXYZRGBL and PointNormal.
template <typename PointT>
void savePcd(const std::string& path, const pcl::PointCloud<PointT>& cloud,
             PcdEncoding encoding = PcdEncoding::binary_compressed);

/// The bytes of the PCD file savePcd writes, for writing with others through AtomicFileGroup:
/// the binary encodings as PCL lays them out, ASCII as PCL's writeASCII writes it with 9
/// significant digits (every float read back exactly; NaN as nan, a float rgb field as the
/// integer of its bits). Throws std::runtime_error if PCL cannot encode the cloud.
template <typename PointT>
std::string encodePcd(const pcl::PointCloud<PointT>& cloud, PcdEncoding encoding = PcdEncoding::binary_compressed);

}  // namespace floodplane::io
