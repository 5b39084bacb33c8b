// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A depth camera's pinhole model: how a depth image's pixels become 3-D points. One function
// does the back-projection for every depth input (pcd_segment's PNG files, the Python
// module's arrays), so they give the same points bit for bit.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

namespace floodplane::io {

struct DepthCamera {
  double fx = 0.0;  ///< focal length along x [pixels]
  double fy = 0.0;  ///< focal length along y [pixels]
  double cx = 0.0;  ///< principal point, column [pixels]; pixel centres have integer coordinates
  double cy = 0.0;  ///< principal point, row [pixels]
  /// Depth units per metre: 1000 for millimetres (Kinect, RealSense), 5000 for the TUM RGB-D
  /// benchmark's PNG files.
  double depth_scale = 1000.0;

  /// The first value that cannot be used, as a sentence naming it ("fx must be a finite
  /// number of pixels > 0, got 0.000000"); empty when all are fine.
  std::string problem() const;
};

/// The point seen at column u, row v with `units` of depth (depth_scale per metre): z =
/// units / depth_scale, x = (u - cx) z / fx, y = (v - cy) z / fy, in the camera frame (x right,
/// y down, z forward). Zero units is no return: NaN. Computed in double, stored as float.
inline void backProjectPixel(int u, int v, double units, const DepthCamera& camera, float* xyz) {
  if (units == 0.0) {
    xyz[0] = xyz[1] = xyz[2] = std::numeric_limits<float>::quiet_NaN();
    return;
  }
  const double z = units / camera.depth_scale;
  xyz[0] = static_cast<float>((u - camera.cx) * z / camera.fx);
  xyz[1] = static_cast<float>((v - camera.cy) * z / camera.fy);
  xyz[2] = static_cast<float>(z);
}

/// Back-projects a row-major width x height depth image of unsigned 16-bit units into `xyz`
/// (3 floats a pixel, row-major). `camera` must have no problem().
void backProjectDepth(const std::uint16_t* depth, int width, int height, const DepthCamera& camera, float* xyz);

}  // namespace floodplane::io
