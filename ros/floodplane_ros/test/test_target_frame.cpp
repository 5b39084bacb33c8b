// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The rostest of ~target_frame (target_frame.test): a camera 1.2 m above the floor looking
// forward and 30 degrees down, its pose on tf as static transforms (base_link, 0.3 m above the
// floor, -> camera_link -> camera_depth_optical_frame, as a robot and its camera driver
// publish them), and the node publishing its planes in base_link. The floor it sees must be
// the floor of base_link: normal (0 0 1), d = 0.3, centroid 0.3 m below base_link. A frame
// whose frame tf does not know is skipped with an error in the log, and the node goes on.

#include <floodplane_ros/Planes.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/PointCloud2.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <condition_variable>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include "ros_test_support.h"

namespace {

using floodplane_ros::test::becomes;
using floodplane_ros::test::Inbox;
using floodplane_ros::test::kWaitSeconds;

// target_frame.test's transforms: camera_link at (0.1, 0, 0.9) in base_link, pitched down
// 30 degrees; the optical frame turned from it as drivers turn theirs (x right, y down, z
// forward). base_link is 0.3 m above the floor.
constexpr double kPitch = 30.0 * M_PI / 180.0;
constexpr double kFloorBelowBase = 0.3;
const Eigen::Vector3d kCameraInBase(0.1, 0.0, 0.9);

Eigen::Quaterniond opticalInBase() {
  const Eigen::Quaterniond camera_link(Eigen::AngleAxisd(kPitch, Eigen::Vector3d::UnitY()));
  const Eigen::Quaterniond optical =
      Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX());
  return camera_link * optical;
}

// What the camera sees of the floor: a 320 x 240 pinhole grid, each ray's hit on z = -0.3 of
// base_link in the optical frame, NaN where it sees no floor within 6 m.
sensor_msgs::PointCloud2 floorCloud(const std::string& frame_id) {
  const int width = 320, height = 240;
  const double f = 285.0, cx = 159.5, cy = 119.5;
  const Eigen::Quaterniond rotation = opticalInBase();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> xyz;
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const Eigen::Vector3d ray((u - cx) / f, (v - cy) / f, 1.0);
      const Eigen::Vector3d ray_in_base = rotation * ray;
      const double t = (-kFloorBelowBase - kCameraInBase.z()) / ray_in_base.z();
      const Eigen::Vector3d p = t * ray;
      if (ray_in_base.z() < 0.0 && p.norm() < 6.0) {
        xyz.insert(xyz.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
      } else {
        xyz.insert(xyz.end(), {nan, nan, nan});
      }
    }
  }
  return floodplane_ros::test::organizedCloud(width, height, xyz, frame_id);
}

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
}

TEST(TargetFrame, PublishesTheFloorInTheTargetFrame) {
  Camera camera;
  ASSERT_TRUE(becomes([&] { return camera.points.getNumSubscribers() > 0; }))
      << "the node did not subscribe its input within " << kWaitSeconds << " s";
  const ros::Time stamp = camera.send(floorCloud("camera_depth_optical_frame"));
  expectTheFloorOfBaseLink(camera.planes.waitFor(stamp), stamp);
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
