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
/// Throws std::runtime_error naming `path` if the file cannot be written: with the system's
/// reason ("No space left on device") for the binary encodings, which are encoded in memory
/// (encodePcd) and written by writeBytesAtomically; PCL's ASCII writer writes the file itself.
/// Instantiated for pcl::PointXYZ, PointXYZI, PointXYZL, PointXYZRGB, PointXYZRGBA,
/// PointXYZRGBL and PointNormal.
template <typename PointT>
void savePcd(const std::string& path, const pcl::PointCloud<PointT>& cloud,
             PcdEncoding encoding = PcdEncoding::binary_compressed);

/// The bytes of the PCD file savePcd writes in a binary encoding (binary_compressed or
/// binary), for writing with others through AtomicFileGroup. Throws std::invalid_argument for
/// PcdEncoding::ascii, std::runtime_error if PCL cannot encode the cloud.
template <typename PointT>
std::string encodePcd(const pcl::PointCloud<PointT>& cloud, PcdEncoding encoding = PcdEncoding::binary_compressed);

}  // namespace floodplane::io
