// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/camera.h"

#include <stdexcept>
#include <string>

namespace floodplane::synth {

CameraIntrinsics CameraIntrinsics::scaledTo(int new_width, int new_height) const {
  if (new_width < 1 || new_height < 1) {
    throw std::invalid_argument("CameraIntrinsics::scaledTo: size " + std::to_string(new_width) + "x" +
                                std::to_string(new_height) + " is not positive");
  }
  const double scale_x = static_cast<double>(new_width) / width;
  const double scale_y = static_cast<double>(new_height) / height;
  CameraIntrinsics scaled;
  scaled.width = new_width;
  scaled.height = new_height;
  scaled.fx = fx * scale_x;
  scaled.fy = fy * scale_y;
  scaled.cx = (cx + 0.5) * scale_x - 0.5;
  scaled.cy = (cy + 0.5) * scale_y - 0.5;
  return scaled;
}

Eigen::Isometry3d lookAt(const Eigen::Vector3d& position, const Eigen::Vector3d& target, const Eigen::Vector3d& up) {
  const Eigen::Vector3d forward = target - position;
  if (forward.norm() < 1e-9) {
    throw std::invalid_argument("lookAt: the target is the camera position");
  }
  const Eigen::Vector3d z_axis = forward.normalized();
  const Eigen::Vector3d right = z_axis.cross(up);
  if (right.norm() < 1e-9 * up.norm() || up.norm() < 1e-9) {
    throw std::invalid_argument("lookAt: 'up' is zero or parallel to the viewing direction");
  }
  const Eigen::Vector3d x_axis = right.normalized();
  // y points down in the image, and x, y, z form a right-handed frame.
  const Eigen::Vector3d y_axis = z_axis.cross(x_axis);
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  world_from_camera.linear().col(0) = x_axis;
  world_from_camera.linear().col(1) = y_axis;
  world_from_camera.linear().col(2) = z_axis;
  world_from_camera.translation() = position;
  return world_from_camera;
}

}  // namespace floodplane::synth
