// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The camera of target_frame.test and up_parameter.test, and what it sees, rendered exactly:
// 1.2 m above the floor, looking forward and 30 degrees down, its pose as a robot and its
// camera driver put it on tf (base_link, 0.3 m above the floor, -> camera_link, 0.1 m ahead
// and 0.9 m up, pitched down -> camera_depth_optical_frame: x right, y down, z forward).

#include <sensor_msgs/PointCloud2.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ros_test_support.h"

namespace floodplane_ros::test {

inline constexpr double kPitch = 30.0 * M_PI / 180.0;
inline constexpr double kFloorBelowBase = 0.3;
inline const Eigen::Vector3d kCameraInBase(0.1, 0.0, 0.9);

/// The room's wall, facing the camera: x = kWallX in base_link (2.9 m ahead of the camera),
/// from the floor up.
inline constexpr double kWallX = 3.0;
/// The room's table top: kTableHeight above the floor, x 1.2..1.8, y -0.5..0.3 in base_link
/// (a top alone, without legs or sides).
inline constexpr double kTableHeight = 0.45;

/// The optical frame's orientation in base_link.
inline Eigen::Quaterniond opticalInBase() {
  const Eigen::Quaterniond camera_link(Eigen::AngleAxisd(kPitch, Eigen::Vector3d::UnitY()));
  const Eigen::Quaterniond optical =
      Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX());
  return camera_link * optical;
}

/// Up (base_link's z) in the optical frame: (0, -cos 30, -sin 30), what up_parameter.test
/// gives as ~up.
inline Eigen::Vector3d upInOptical() { return opticalInBase().inverse() * Eigen::Vector3d::UnitZ(); }

/// A rectangle of the scene, perpendicular to one of base_link's axes: `axis` = `value`,
/// within [low, high] along the other two (the bound of `axis` itself is not used).
struct SceneRectangle {
  int axis = 2;
  double value = 0.0;
  Eigen::Vector3d low = Eigen::Vector3d::Constant(-1e9);
  Eigen::Vector3d high = Eigen::Vector3d::Constant(1e9);
};

/// What the camera sees of `scene`: a 320 x 240 pinhole grid (f 285), each ray's nearest hit
/// in the optical frame, NaN where it hits nothing within 6 m.
inline sensor_msgs::PointCloud2 renderScene(const std::vector<SceneRectangle>& scene, const std::string& frame_id) {
  const int width = 320, height = 240;
  const double f = 285.0, cx = 159.5, cy = 119.5;
  const Eigen::Quaterniond rotation = opticalInBase();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> xyz;
  xyz.reserve(3 * static_cast<std::size_t>(width) * height);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const Eigen::Vector3d ray((u - cx) / f, (v - cy) / f, 1.0);
      const Eigen::Vector3d ray_in_base = rotation * ray;
      double nearest = std::numeric_limits<double>::infinity();
      for (const SceneRectangle& rectangle : scene) {
        const double along = ray_in_base[rectangle.axis];
        if (along == 0.0) continue;
        const double t = (rectangle.value - kCameraInBase[rectangle.axis]) / along;
        if (!(t > 0.0) || t >= nearest) continue;
        const Eigen::Vector3d hit = kCameraInBase + t * ray_in_base;
        bool inside = true;
        for (int axis = 0; axis < 3; ++axis) {
          if (axis != rectangle.axis && (hit[axis] < rectangle.low[axis] || hit[axis] > rectangle.high[axis])) {
            inside = false;
          }
        }
        if (inside) nearest = t;
      }
      const Eigen::Vector3d p = nearest * ray;
      if (std::isfinite(nearest) && p.norm() < 6.0) {
        xyz.insert(xyz.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
      } else {
        xyz.insert(xyz.end(), {nan, nan, nan});
      }
    }
  }
  return organizedCloud(width, height, xyz, frame_id);
}

inline SceneRectangle floorRectangle() {
  SceneRectangle floor;
  floor.axis = 2;
  floor.value = -kFloorBelowBase;
  return floor;
}

/// The floor alone.
inline sensor_msgs::PointCloud2 floorCloud(const std::string& frame_id) {
  return renderScene({floorRectangle()}, frame_id);
}

/// The floor, the wall ahead and the table top between.
inline sensor_msgs::PointCloud2 roomCloud(const std::string& frame_id) {
  SceneRectangle wall;
  wall.axis = 0;
  wall.value = kWallX;
  wall.low.z() = -kFloorBelowBase;
  SceneRectangle table;
  table.axis = 2;
  table.value = kTableHeight - kFloorBelowBase;
  table.low = Eigen::Vector3d(1.2, -0.5, 0.0);
  table.high = Eigen::Vector3d(1.8, 0.3, 0.0);
  return renderScene({floorRectangle(), wall, table}, frame_id);
}

}  // namespace floodplane_ros::test
