// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The rostest of ~up (up_parameter.test): the camera of target_frame.test sees a floor, a wall
// and a table top, and the node, given up in the camera's optical frame and no target frame,
// publishes its planes in the camera's frame classed FLOOR, WALL and HORIZONTAL_SURFACE with
// their heights above the floor, and its markers in their classes' colours. A node whose ~up
// is zero stays up and publishes the same planes unclassed: OTHER, NaN heights, markers in
// their labels' colours.

#include <floodplane_ros/Planes.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <visualization_msgs/MarkerArray.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "plane_descriptions.h"
#include "ros_test_support.h"
#include "tilted_camera.h"

namespace {

using floodplane_ros::Plane;
using floodplane_ros::test::becomes;
using floodplane_ros::test::Inbox;
using floodplane_ros::test::kTableHeight;
using floodplane_ros::test::kWaitSeconds;
using floodplane_ros::test::roomCloud;
namespace conv = floodplane::conversion;

// A marker array's stamp: its first marker's (the DELETEALL that leads every array).
ros::Time markersStamp(const visualization_msgs::MarkerArray& array) {
  return array.markers.empty() ? ros::Time() : array.markers.front().header.stamp;
}

struct Camera {
  explicit Camera(const std::string& name) : nh("/" + name) {}
  ros::NodeHandle nh;
  ros::Publisher points = nh.advertise<sensor_msgs::PointCloud2>("depth/points", 2);
  Inbox<floodplane_ros::Planes> planes{nh, "planes"};
  Inbox<visualization_msgs::MarkerArray> markers{nh, "plane_markers", markersStamp};
  std::uint32_t seconds = 5000;
  ros::Time send(sensor_msgs::PointCloud2 cloud) {
    cloud.header.stamp = ros::Time(++seconds, 0);
    points.publish(cloud);
    return cloud.header.stamp;
  }
  bool ready() {
    return becomes([&] {
      return points.getNumSubscribers() > 0 && planes.subscriber().getNumPublishers() > 0 &&
             markers.subscriber().getNumPublishers() > 0;
    });
  }
};

// Each plane's outline (marker 1 + 2k) and normal (2 + 2k) in `color`.
void expectMarkerColors(const visualization_msgs::MarkerArray& markers, std::size_t plane,
                        const std::array<float, 3>& color) {
  ASSERT_GT(markers.markers.size(), 2 + 2 * plane);
  for (const std::size_t index : {1 + 2 * plane, 2 + 2 * plane}) {
    const auto& marker = markers.markers[index];
    EXPECT_EQ(marker.color.r, color[0]) << "plane " << plane << ", marker " << marker.ns;
    EXPECT_EQ(marker.color.g, color[1]) << "plane " << plane << ", marker " << marker.ns;
    EXPECT_EQ(marker.color.b, color[2]) << "plane " << plane << ", marker " << marker.ns;
  }
}

TEST(UpParameter, ClassesThePlanesInTheCamerasFrame) {
  Camera camera("camera");
  ASSERT_TRUE(camera.ready()) << "the node did not connect within " << kWaitSeconds << " s";
  const ros::Time stamp = camera.send(roomCloud("camera_depth_optical_frame"));
  const auto planes = camera.planes.waitFor(stamp);
  const auto markers = camera.markers.waitFor(stamp);
  ASSERT_TRUE(planes && markers) << "no planes and markers within " << kWaitSeconds << " s";
  EXPECT_EQ(planes->header.frame_id, "camera_depth_optical_frame");
  ASSERT_EQ(planes->planes.size(), 3u);  // floor, wall, table top
  int floors = 0, walls = 0, tables = 0;
  const Eigen::Vector3d up = floodplane_ros::test::upInOptical();
  for (std::size_t k = 0; k < planes->planes.size(); ++k) {
    const Plane& plane = planes->planes[k];
    const Eigen::Vector3d normal(plane.plane.coef[0], plane.plane.coef[1], plane.plane.coef[2]);
    if (plane.plane_class == Plane::FLOOR) {
      ++floors;
      EXPECT_NEAR(normal.dot(up), 1.0, 1e-4);
      EXPECT_NEAR(plane.plane.coef[3], 1.2, 1e-3);  // the camera's height above it
      EXPECT_NEAR(plane.height_above_floor, 0.0, 1e-3);
    } else if (plane.plane_class == Plane::WALL) {
      ++walls;
      EXPECT_NEAR(normal.dot(up), 0.0, 1e-4);
      EXPECT_GT(plane.height_above_floor, 0.1);
      EXPECT_LT(plane.height_above_floor, 0.83);
    } else if (plane.plane_class == Plane::HORIZONTAL_SURFACE) {
      ++tables;
      EXPECT_NEAR(normal.dot(up), 1.0, 1e-4);
      EXPECT_NEAR(plane.height_above_floor, kTableHeight, 1e-3);
    } else {
      ADD_FAILURE() << "plane " << k << " of class " << int{plane.plane_class};
    }
    // rviz draws it in its class's colour.
    expectMarkerColors(*markers, k, conv::planeClassColor(static_cast<floodplane::PlaneClass>(plane.plane_class)));
  }
  EXPECT_EQ(floors, 1);
  EXPECT_EQ(walls, 1);
  EXPECT_EQ(tables, 1);
}

TEST(UpParameter, ABadOneLeavesThePlanesUnclassed) {
  Camera camera("bad_up_camera");
  ASSERT_TRUE(camera.ready()) << "the node with a bad ~up did not connect within " << kWaitSeconds << " s";
  const ros::Time stamp = camera.send(roomCloud("camera_depth_optical_frame"));
  const auto planes = camera.planes.waitFor(stamp);
  const auto markers = camera.markers.waitFor(stamp);
  ASSERT_TRUE(planes && markers) << "no planes and markers within " << kWaitSeconds << " s";
  ASSERT_EQ(planes->planes.size(), 3u);
  for (std::size_t k = 0; k < planes->planes.size(); ++k) {
    const Plane& plane = planes->planes[k];
    EXPECT_EQ(plane.plane_class, Plane::OTHER) << "plane " << k;
    EXPECT_TRUE(std::isnan(plane.height_above_floor)) << "plane " << k;
    // rviz draws it in its label's colour, as the label cloud.
    conv::PlaneDescription description;
    description.label = plane.label;
    expectMarkerColors(*markers, k, conv::markerColor(description, false));
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "up_parameter_test");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
