#pragma once
// One organized frame read from an input file, in the point types the apps segment. Every
// input kind (today organized PCD files) is read into this one type, so the apps do not
// depend on where their frames come from.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace floodplane::io {

struct InputFrame {
  /// The points on their image grid (height > 1), NaN where the sensor saw nothing, with the
  /// file's sensor pose.
  pcl::PointCloud<pcl::PointXYZ> xyz;
  /// The same grid and points with the file's colour, when the file has one.
  std::optional<pcl::PointCloud<pcl::PointXYZRGB>> xyzrgb;
  /// The file's per-pixel `label` (ground-truth plane id, 0 = no plane, as pcd_synth writes
  /// it), when the file has one, row-major.
  std::optional<std::vector<std::uint32_t>> labels;
};

/// Reads the frame in `path`. Every input is read as an organized PCD file (readPcdFrame,
/// io/pcd_input.h); other kinds of input are told apart here. Throws std::runtime_error with
/// a one-line reason, without the path, when the file cannot be read as a frame.
InputFrame loadInputFrame(const std::string& path);

}  // namespace floodplane::io
