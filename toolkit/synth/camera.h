// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The pinhole camera of the scene renderer.
//
// Camera frame: the frame of a Kinect cloud in PCL, x right, y down, z forward (metres).
// Pixel (u, v) is column u, row v; the centre of a pixel has integer coordinates, so the
// centre of a 640x480 image is (319.5, 239.5).

#include <Eigen/Geometry>

namespace floodplane::synth {

struct CameraIntrinsics {
  int width = 640;    ///< image width in pixels
  int height = 480;   ///< image height in pixels
  double fx = 525.0;  ///< focal length along x, pixels
  double fy = 525.0;  ///< focal length along y, pixels
  double cx = 319.5;  ///< principal point, column (pixels)
  double cy = 239.5;  ///< principal point, row (pixels)

  /// The ray through the centre of pixel (u, v), scaled so its z component is 1: a point at
  /// parameter t along it has depth z = t.
  Eigen::Vector3d rayThroughPixel(int u, int v) const { return {(u - cx) / fx, (v - cy) / fy, 1.0}; }

  /// The same camera at another resolution, seeing the same field of view: fx and cx scale
  /// with new_width / width, fy and cy with new_height / height. The principal point is
  /// scaled about the image corner (cx' = (cx + 0.5) s - 0.5) because pixel centres sit at
  /// integer coordinates, so it stays at the same place in the image: 319.5 at 640 becomes
  /// 159.5 at 320 and 639.5 at 1280. Throws std::invalid_argument for a size below 1.
  CameraIntrinsics scaledTo(int new_width, int new_height) const;
};

/// The pose of a camera at `position` looking at `target`, with `up` (a world direction)
/// pointing up in the image: the transform from camera to world coordinates.
/// Throws std::invalid_argument if target equals position or up is parallel to the
/// viewing direction.
Eigen::Isometry3d lookAt(const Eigen::Vector3d& position, const Eigen::Vector3d& target, const Eigen::Vector3d& up);

}  // namespace floodplane::synth
