// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "label_pcd.h"

#include <pcl/io/pcd_io.h>

#include <cinttypes>
#include <cstdio>
#include <type_traits>

#include "floodplane/io/pcd_file.h"

namespace pcd_segment {

template <typename PointT>
std::string asciiPcd(const pcl::PointCloud<PointT>& cloud) {
  std::string text = pcl::PCDWriter::generateHeader<PointT>(cloud) + "DATA ascii\n";
  text.reserve(text.size() + cloud.size() * 48);
  char line[160];
  for (const PointT& p : cloud) {
    int length = 0;
    if constexpr (std::is_same_v<PointT, pcl::PointXYZRGBL>) {
      // PointXYZRGBL's colour field is "rgba", an unsigned integer: written as one.
      length = std::snprintf(line, sizeof(line), "%.9g %.9g %.9g %" PRIu32 " %" PRIu32 "\n", p.x, p.y, p.z,
                             static_cast<std::uint32_t>(p.rgba), static_cast<std::uint32_t>(p.label));
    } else {
      length = std::snprintf(line, sizeof(line), "%.9g %.9g %.9g %" PRIu32 "\n", p.x, p.y, p.z,
                             static_cast<std::uint32_t>(p.label));
    }
    text.append(line, static_cast<std::size_t>(length));
  }
  return text;
}

template <typename PointT>
std::string labelPcdBytes(const pcl::PointCloud<PointT>& cloud, bool ascii) {
  return ascii ? asciiPcd(cloud) : floodplane::io::encodePcd(cloud, floodplane::io::PcdEncoding::binary_compressed);
}

template std::string asciiPcd(const pcl::PointCloud<pcl::PointXYZL>&);
template std::string asciiPcd(const pcl::PointCloud<pcl::PointXYZRGBL>&);
template std::string labelPcdBytes(const pcl::PointCloud<pcl::PointXYZL>&, bool);
template std::string labelPcdBytes(const pcl::PointCloud<pcl::PointXYZRGBL>&, bool);

}  // namespace pcd_segment
