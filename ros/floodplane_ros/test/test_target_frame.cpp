// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The rostest of ~target_frame (target_frame.test): a camera 1.2 m above the floor looking
// forward and 30 degrees down, its pose on tf as static transforms (base_link, 0.3 m above the
// floor, -> camera_link -> camera_depth_optical_frame, as a robot and its camera driver
// publish them), and the node publishing its planes in base_link. The floor it sees must be
// the floor of base_link: normal (0 0 1), d = 0.3, centroid 0.3 m below base_link, classed
// FLOOR (base_link's z is up) at height 0; in a room, the wall ahead must be a WALL and the
// table top a HORIZONTAL_SURFACE at the table's height. A frame whose frame tf does not know
// is skipped with an error in the log, and the node goes on.

#include <floodplane_ros/Planes.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/PointCloud2.h>

#include <gtest/gtest.h>

#include <cmath>
#include <condition_variable>
#include <mutex>
#include <string>
#include <vector>

#include "ros_test_support.h"
#include "tilted_camera.h"

namespace {

using floodplane_ros::Plane;
using floodplane_ros::test::becomes;
using floodplane_ros::test::floorCloud;
using floodplane_ros::test::Inbox;
using floodplane_ros::test::kCameraInBase;
using floodplane_ros::test::kFloorBelowBase;
using floodplane_ros::test::kTableHeight;
using floodplane_ros::test::kWaitSeconds;
using floodplane_ros::test::kWallX;
using floodplane_ros::test::roomCloud;

// The node's errors on /rosout.
class Errors {
 public:
  explicit Errors(ros::NodeHandle& nh) : subscriber_(nh.subscribe("/rosout", 100, &Errors::onLog, this)) {}
  std::size_t count() {
    std::lock_guard<std::mutex> lock(mutex_);
    return errors_.size();
  }
  std::string waitForNext(std::size_t before) {
    std::unique_lock<std::mutex> lock(mutex_);
    const bool logged = arrived_.wait_for(lock, std::chrono::duration<double>(kWaitSeconds),
                                          [&] { return errors_.size() > before || !ros::ok(); });
    return logged ? errors_[before] : std::string();
  }

 private:
  void onLog(const rosgraph_msgs::LogConstPtr& log) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (log->level != rosgraph_msgs::Log::ERROR || log->msg.find("frame skipped") == std::string::npos) return;
    errors_.push_back(log->msg);
    arrived_.notify_all();
  }
  ros::Subscriber subscriber_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::vector<std::string> errors_;
};

struct Camera {
  ros::NodeHandle nh{"/camera"};
  ros::Publisher points = nh.advertise<sensor_msgs::PointCloud2>("depth/points", 2);
  Inbox<floodplane_ros::Planes> planes{nh, "planes"};
  Errors errors{nh};
  std::uint32_t seconds = 3000;
  ros::Time send(sensor_msgs::PointCloud2 cloud) {
    cloud.header.stamp = ros::Time(++seconds, 0);
    points.publish(cloud);
    return cloud.header.stamp;
  }
};

void expectTheFloorOfBaseLink(const floodplane_ros::PlanesConstPtr& planes, const ros::Time& stamp) {
  ASSERT_TRUE(planes) << "no planes within " << kWaitSeconds << " s";
  EXPECT_EQ(planes->header.frame_id, "base_link");
  EXPECT_EQ(planes->header.stamp, stamp);
  ASSERT_EQ(planes->planes.size(), 1u);
  const auto& floor = planes->planes.front();
  EXPECT_NEAR(floor.plane.coef[0], 0.0, 1e-4);
  EXPECT_NEAR(floor.plane.coef[1], 0.0, 1e-4);
  EXPECT_NEAR(floor.plane.coef[2], 1.0, 1e-4);  // up: towards the camera
  EXPECT_NEAR(floor.plane.coef[3], kFloorBelowBase, 1e-3);
  EXPECT_NEAR(floor.centroid.z, -kFloorBelowBase, 1e-3);
  EXPECT_GT(floor.centroid.x, kCameraInBase.x());  // in front of the camera
  EXPECT_EQ(floor.plane_class, Plane::FLOOR);
  EXPECT_NEAR(floor.height_above_floor, 0.0, 1e-3);
}

// The one plane of `planes` of class `plane_class`; fails the test when there is not one.
const Plane* onlyPlaneOfClass(const floodplane_ros::Planes& planes, std::uint8_t plane_class) {
  const Plane* found = nullptr;
  int count = 0;
  for (const Plane& plane : planes.planes) {
    if (plane.plane_class == plane_class) {
      found = &plane;
      ++count;
    }
  }
  EXPECT_EQ(count, 1) << "planes of class " << int{plane_class};
  return count == 1 ? found : nullptr;
}

TEST(TargetFrame, PublishesTheFloorInTheTargetFrame) {
  Camera camera;
  ASSERT_TRUE(becomes([&] { return camera.points.getNumSubscribers() > 0; }))
      << "the node did not subscribe its input within " << kWaitSeconds << " s";
  const ros::Time stamp = camera.send(floorCloud("camera_depth_optical_frame"));
  expectTheFloorOfBaseLink(camera.planes.waitFor(stamp), stamp);
}

TEST(TargetFrame, ClassesTheRoomsPlanesByTheTargetFramesZAxis) {
  Camera camera;
  ASSERT_TRUE(becomes([&] { return camera.points.getNumSubscribers() > 0; }))
      << "the node did not subscribe its input within " << kWaitSeconds << " s";
  const ros::Time stamp = camera.send(roomCloud("camera_depth_optical_frame"));
  const floodplane_ros::PlanesConstPtr planes = camera.planes.waitFor(stamp);
  ASSERT_TRUE(planes) << "no planes within " << kWaitSeconds << " s";
  EXPECT_EQ(planes->header.frame_id, "base_link");
  ASSERT_EQ(planes->planes.size(), 3u);  // floor, wall, table top
  const Plane* floor = onlyPlaneOfClass(*planes, Plane::FLOOR);
  const Plane* wall = onlyPlaneOfClass(*planes, Plane::WALL);
  const Plane* table = onlyPlaneOfClass(*planes, Plane::HORIZONTAL_SURFACE);
  ASSERT_TRUE(floor && wall && table);
  EXPECT_NEAR(floor->plane.coef[2], 1.0, 1e-4);
  EXPECT_NEAR(floor->height_above_floor, 0.0, 1e-3);
  // The wall x = 3 faces the camera (-x); the camera, 1.2 m up and 30 degrees down, sees its
  // lower 0.83 m.
  EXPECT_NEAR(wall->plane.coef[0], -1.0, 1e-4);
  EXPECT_NEAR(wall->plane.coef[3], kWallX, 1e-3);
  EXPECT_GT(wall->height_above_floor, 0.1);
  EXPECT_LT(wall->height_above_floor, 0.83);
  EXPECT_NEAR(wall->height_above_floor, wall->centroid.z + kFloorBelowBase, 1e-3);
  EXPECT_NEAR(table->plane.coef[2], 1.0, 1e-4);
  EXPECT_NEAR(table->height_above_floor, kTableHeight, 1e-3);
  EXPECT_NEAR(table->centroid.z, kTableHeight - kFloorBelowBase, 1e-3);
}

TEST(TargetFrame, SkipsAFrameItCannotTransformAndGoesOn) {
  Camera camera;
  ASSERT_TRUE(becomes([&] { return camera.points.getNumSubscribers() > 0; }));
  const std::size_t errors = camera.errors.count();
  const ros::Time lost = camera.send(floorCloud("nowhere_optical_frame"));
  const std::string error = camera.errors.waitForNext(errors);
  EXPECT_NE(error.find("frame skipped: /camera/depth/points: no transform from 'nowhere_optical_frame' to "
                       "'base_link' within "),
            std::string::npos)
      << error;
  const ros::Time next = camera.send(floorCloud("camera_depth_optical_frame"));
  expectTheFloorOfBaseLink(camera.planes.waitFor(next), next);
  EXPECT_FALSE(camera.planes.waitFor(lost, 0.0)) << "planes published for the frame without a transform";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "target_frame_test");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
