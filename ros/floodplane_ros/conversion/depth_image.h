// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Depth images into points, by depth_image_proc's convention and without ROS types: 16UC1
// (or mono16) in millimetres or 32FC1 in metres, 0 or NaN for no return, the pinhole
// intrinsics from CameraInfo's K. The back-projection itself is floodplane_io's
// (floodplane/io/depth_camera.h), so a depth image gives the points pcd_segment and the Python module
// give it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "floodplane/io/depth_camera.h"

namespace floodplane::conversion {

/// A sensor_msgs/Image without its header, its data in place (not owned).
struct ImageView {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::string encoding;  ///< sensor_msgs::image_encodings' name: "16UC1", "mono16", "32FC1", ...
  bool is_bigendian = false;
  std::uint32_t step = 0;  ///< bytes from one row to the next
  const std::uint8_t* data = nullptr;
  std::size_t data_size = 0;  ///< bytes at `data`
};

/// What a node takes from sensor_msgs/CameraInfo.
struct CameraInfoView {
  std::uint32_t width = 0;    ///< 0: not given (some drivers leave it)
  std::uint32_t height = 0;   ///< 0: not given
  std::array<double, 9> k{};  ///< K, row-major: fx 0 cx / 0 fy cy / 0 0 1
};

/// The depth units per metre of an encoding: 1000 for 16UC1 and mono16, 1 for 32FC1. Throws
/// std::invalid_argument naming the encodings floodplane reads for any other.
double depthUnitsPerMetre(const std::string& encoding);

/// The camera of `info` for depth images in `encoding`. Throws std::invalid_argument when K
/// has no usable focal length or principal point (an uncalibrated camera's K is all zero),
/// or for an encoding depthUnitsPerMetre does not take.
io::DepthCamera depthCamera(const CameraInfoView& info, const std::string& encoding);

/// Back-projects `image` through `info` into `xyz` (3 floats a pixel, row-major, NaN where
/// there is no return: 0, NaN, infinite or negative depth), resized to fit: empty for an image
/// without pixels (width or height 0). Throws std::invalid_argument with a one-line reason for
/// an encoding other than 16UC1, mono16 or 32FC1, a byte order other than this machine's, a
/// step or data size that does not hold the rows, a K that depthCamera rejects, or a
/// CameraInfo of another size.
void backProjectDepthImage(const ImageView& image, const CameraInfoView& info, std::vector<float>& xyz);

}  // namespace floodplane::conversion
