// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A depth camera's pinhole intrinsics in every form Python users hold them: four numbers
// fx, fy, cx, cy; a 3 x 3 matrix K (OpenCV, RealSense) or its nine values row by row (ROS's
// CameraInfo.k); or any object
// with an `intrinsic_matrix` (Open3D's PinholeCameraIntrinsic), whose width and height, when
// it has them, must then be the image's.

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "floodplane/io/depth_camera.h"

namespace floodplane::python {

struct Intrinsics {
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  /// The image size the intrinsics were made for (Open3D's width and height), when known.
  std::optional<int> width;
  std::optional<int> height;

  /// The camera with `depth_scale` units per metre; raises ValueError naming `function`
  /// for a value it cannot use (io::DepthCamera::problem()).
  io::DepthCamera camera(double depth_scale, const std::string& function) const;
  /// Raises ValueError when the intrinsics were made for another image size than
  /// width x height.
  void checkImageSize(long long width, long long height, const std::string& function) const;
};

/// The intrinsics given as `intrinsics` and, when it is fx, the three numbers after it
/// (`fy`, `cx`, `cy`, all None otherwise). Raises TypeError for a form it does not know,
/// ValueError for a matrix that is not a pinhole K (skew, a bottom row other than 0 0 1).
/// `function` names the caller in messages.
Intrinsics intrinsicsFrom(pybind11::handle intrinsics, pybind11::handle fy, pybind11::handle cx, pybind11::handle cy,
                          const std::string& function);

/// The form every other accepts: one argument, four numbers, a K or an Open3D intrinsic.
Intrinsics intrinsicsFrom(pybind11::handle intrinsics, const std::string& function);

}  // namespace floodplane::python
