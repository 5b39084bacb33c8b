// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/point_cloud.h"

#include <cmath>

namespace floodplane::synth {

pcl::PointCloud<pcl::PointXYZL> toPointCloud(const RenderedFrame& frame) {
  pcl::PointCloud<pcl::PointXYZL> cloud(static_cast<std::uint32_t>(frame.intrinsics.width),
                                        static_cast<std::uint32_t>(frame.intrinsics.height));
  bool dense = true;
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    pcl::PointXYZL& point = cloud[i];
    point.x = frame.points[i].x();
    point.y = frame.points[i].y();
    point.z = frame.points[i].z();
    point.label = frame.labels[i];
    dense = dense && std::isfinite(point.z);
  }
  cloud.is_dense = dense;
  cloud.sensor_origin_ = Eigen::Vector4f::Zero();
  cloud.sensor_orientation_ = frame.world_from_camera.cast<float>();
  return cloud;
}

}  // namespace floodplane::synth
