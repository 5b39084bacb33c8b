#pragma once
// Reading any organized PCD file with x y z fields into the point types pcd_segment uses.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcd_segment {

struct LoadedCloud {
  pcl::PointCloud<pcl::PointXYZ> xyz;
  /// Filled (same grid, same points) when the file has an rgb or rgba field.
  pcl::PointCloud<pcl::PointXYZRGB> xyzrgb;
  bool has_color = false;
};

/// Reads `path`. Throws std::runtime_error with a one-line reason (without the path) when the
/// file is empty, not a PCD file, truncated or corrupt, has no x y z fields, or is not
/// organized. A cloud whose points are all NaN loads normally.
LoadedCloud loadOrganizedCloud(const std::string& path);

}  // namespace pcd_segment
