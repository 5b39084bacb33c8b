// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/assembly.h"

namespace floodplane::synth {

void Assembly::merge(const Assembly& other, const Eigen::Isometry3d& pose, const std::string& prefix) {
  for (const Primitive& part : other.parts) {
    parts.push_back(
        {part.name.empty() ? prefix : prefix + " " + part.name, transformShape(part.shape, pose), part.albedo});
  }
  for (const Eigen::Vector3d& point : other.interest) {
    interest.push_back(pose * point);
  }
}

Eigen::Isometry3d standingPose(double x, double y, double z, double yaw) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

}  // namespace floodplane::synth
