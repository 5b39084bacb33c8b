// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The rostest of the node's laziness (lazy_subscription.test, input:=both): while no output has
// a subscriber, the node subscribes none of its inputs (the cloud, the depth image, its
// camera_info: a driver computes them for subscribers only) and says so on /diagnostics; a
// subscriber to any one output makes it subscribe them and segment frames, and when that
// subscriber goes, so do the node's subscriptions. Seen from the publishers of the inputs,
// whose subscriber counts the master's connections make.

#include <diagnostic_msgs/DiagnosticArray.h>
#include <floodplane_ros/Planes.h>
#include <pcl_msgs/ModelCoefficients.h>
#include <pcl_msgs/PointIndices.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <visualization_msgs/MarkerArray.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include "ros_test_support.h"

namespace {

using floodplane_ros::test::becomes;
using floodplane_ros::test::Inbox;
using floodplane_ros::test::kWaitSeconds;

struct Camera {
  ros::NodeHandle nh{"/camera"};
  ros::Publisher points = nh.advertise<sensor_msgs::PointCloud2>("depth/points", 2);
  ros::Publisher image = nh.advertise<sensor_msgs::Image>("depth/image_rect", 2);
  ros::Publisher info = nh.advertise<sensor_msgs::CameraInfo>("depth/camera_info", 2);
  std::uint32_t inputSubscribers() const {
    return points.getNumSubscribers() + image.getNumSubscribers() + info.getNumSubscribers();
  }
  bool everyInputSubscribed() const {
    return points.getNumSubscribers() > 0 && image.getNumSubscribers() > 0 && info.getNumSubscribers() > 0;
  }
};

// Whether the master lists every output of the node as published.
bool outputsAdvertised() {
  ros::master::V_TopicInfo topics;
  if (!ros::master::getTopics(topics)) return false;
  std::size_t found = 0;
  for (const auto& topic : topics) {
    for (const char* name : {"/camera/planes", "/camera/plane_labels", "/camera/plane_label_image",
                             "/camera/plane_markers", "/camera/inliers", "/camera/model"}) {
      if (topic.name == name) ++found;
    }
  }
  return found == 6;
}

// The node's latest report on /diagnostics.
class Diagnostics {
 public:
  explicit Diagnostics(ros::NodeHandle& nh)
      : subscriber_(nh.subscribe("/diagnostics", 10, &Diagnostics::onArray, this)) {}
  diagnostic_msgs::DiagnosticStatus latest() {
    std::lock_guard<std::mutex> lock(mutex_);
    return latest_;
  }

 private:
  void onArray(const diagnostic_msgs::DiagnosticArrayConstPtr& array) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& status : array->status) {
      if (status.name == "camera/floodplane: segmentation") latest_ = status;
    }
  }
  ros::Subscriber subscriber_;
  std::mutex mutex_;
  diagnostic_msgs::DiagnosticStatus latest_;
};

// A subscriber to one output, of its type.
template <typename Message>
std::function<ros::Subscriber(ros::NodeHandle&)> listenerTo(const std::string& topic) {
  return [topic](ros::NodeHandle& nh) {
    const boost::function<void(const boost::shared_ptr<const Message>&)> ignore =
        [](const boost::shared_ptr<const Message>&) {};
    return nh.subscribe<Message>(topic, 1, ignore);
  };
}

TEST(LazySubscription, SubscribesTheInputsOnlyWhileAnOutputIsSubscribed) {
  Camera camera;
  Diagnostics diagnostics(camera.nh);
  ASSERT_TRUE(becomes(outputsAdvertised)) << "the node's outputs were not advertised within " << kWaitSeconds << " s";
  // Up and reporting, and still no subscription of an input.
  ASSERT_TRUE(becomes([&] { return !diagnostics.latest().name.empty(); }));
  ros::WallDuration(1.0).sleep();
  EXPECT_EQ(camera.inputSubscribers(), 0u);
  ASSERT_TRUE(becomes([&] { return diagnostics.latest().message == "idle: no subscriber to its outputs"; }, 5.0))
      << diagnostics.latest().message;
  EXPECT_EQ(diagnostics.latest().level, diagnostic_msgs::DiagnosticStatus::OK);
  EXPECT_EQ(camera.inputSubscribers(), 0u);

  const std::vector<std::pair<std::string, std::function<ros::Subscriber(ros::NodeHandle&)>>> outputs = {
      {"planes", listenerTo<floodplane_ros::Planes>("planes")},
      {"plane_labels", listenerTo<sensor_msgs::PointCloud2>("plane_labels")},
      {"plane_label_image", listenerTo<sensor_msgs::Image>("plane_label_image")},
      {"plane_markers", listenerTo<visualization_msgs::MarkerArray>("plane_markers")},
      {"inliers", listenerTo<pcl_msgs::PointIndices>("inliers")},
      {"model", listenerTo<pcl_msgs::ModelCoefficients>("model")},
  };
  for (const auto& [name, listen] : outputs) {
    ros::Subscriber listener = listen(camera.nh);
    EXPECT_TRUE(becomes([&] { return camera.everyInputSubscribed(); }))
        << "a subscriber to " << name << " did not make the node subscribe its inputs within " << kWaitSeconds << " s";
    listener.shutdown();
    EXPECT_TRUE(becomes([&] { return camera.inputSubscribers() == 0; }))
        << "the node kept its inputs for " << kWaitSeconds << " s after " << name << "'s subscriber left";
  }
}

TEST(LazySubscription, SegmentsFramesOnceAnOutputIsSubscribed) {
  Camera camera;
  Inbox<floodplane_ros::Planes> planes(camera.nh, "planes");
  ASSERT_TRUE(becomes([&] { return camera.points.getNumSubscribers() > 0; }));
  // A plane 1.5 m ahead, tilted: Z - 0.3 Y = 1.5, on every pixel.
  const int width = 64, height = 48;
  std::vector<float> xyz;
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const float x = (static_cast<float>(u) - 31.5f) / 60.0f, y = (static_cast<float>(v) - 23.5f) / 60.0f;
      const float z = 1.5f / (1.0f - 0.3f * y);
      xyz.insert(xyz.end(), {x * z, y * z, z});
    }
  }
  sensor_msgs::PointCloud2 cloud =
      floodplane_ros::test::organizedCloud(width, height, xyz, "camera_depth_optical_frame");
  cloud.header.stamp = ros::Time(2000, 0);
  camera.points.publish(cloud);
  const auto published = planes.waitFor(cloud.header.stamp);
  ASSERT_TRUE(published) << "no planes within " << kWaitSeconds << " s";
  ASSERT_EQ(published->planes.size(), 1u);
  const auto& plane = published->planes.front();
  EXPECT_GT(plane.inlier_count, static_cast<std::uint32_t>(0.9 * width * height));
  // Its normal, facing the sensor: -(0, -0.3, 1) / |(0, -0.3, 1)|, and the sensor 1.5 / |...| from it.
  const double length = std::sqrt(1.0 + 0.09);
  EXPECT_NEAR(plane.plane.coef[0], 0.0, 1e-4);
  EXPECT_NEAR(plane.plane.coef[1], 0.3 / length, 1e-4);
  EXPECT_NEAR(plane.plane.coef[2], -1.0 / length, 1e-4);
  EXPECT_NEAR(plane.plane.coef[3], 1.5 / length, 1e-4);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "lazy_subscription_test");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
