// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The rostest of the node's chained outputs (extract_indices_chain.test): floodplane's inliers
// go into pcl_ros's ExtractIndices nodelet, in the same nodelet manager, as SACSegmentation's
// would, and what comes out is the largest plane's points: as many as its inliers, each the
// input's point at its index, all on the plane floodplane published for it.

#include <floodplane_ros/Planes.h>
#include <pcl_msgs/PointIndices.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud2_iterator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "ros_test_support.h"
#include "synth/room_walk.h"

namespace {

using floodplane_ros::test::becomes;
using floodplane_ros::test::Inbox;
using floodplane_ros::test::kWaitSeconds;

struct Chain {
  ros::NodeHandle nh{"/camera"};
  ros::Publisher points = nh.advertise<sensor_msgs::PointCloud2>("depth/points", 2);
  Inbox<floodplane_ros::Planes> planes{nh, "planes"};
  Inbox<pcl_msgs::PointIndices> inliers{nh, "inliers"};
  Inbox<sensor_msgs::PointCloud2> extracted{nh, "largest_plane/output"};
};

// The frames of a rendered walk through a room (Kinect noise): floor, walls and furniture.
std::vector<sensor_msgs::PointCloud2> walkFrames() {
  std::vector<sensor_msgs::PointCloud2> clouds;
  for (const auto& frame : floodplane::synth::renderRoomWalk(11, 3, floodplane::synth::SensorModel::kinect)) {
    std::vector<float> xyz;
    for (const auto& p : frame.points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    clouds.push_back(floodplane_ros::test::organizedCloud(frame.intrinsics.width, frame.intrinsics.height, xyz,
                                                          "camera_depth_optical_frame"));
  }
  return clouds;
}

TEST(ExtractIndicesChain, GivesTheLargestPlanesPointsOfEachFrame) {
  Chain chain;
  // ExtractIndices subscribes its input and indices (the master lists its manager on the
  // inliers) once its output has a subscriber, ours; floodplane its input once an output has
  // one. Nodelets of one manager share its connection to the input.
  ASSERT_TRUE(becomes([&] {
    const auto inliers = floodplane_ros::test::subscribersOf("/camera/inliers");
    return chain.points.getNumSubscribers() > 0 && chain.planes.subscriber().getNumPublishers() > 0 &&
           chain.extracted.subscriber().getNumPublishers() > 0 &&
           std::count(inliers.begin(), inliers.end(), "/camera/camera_nodelet_manager") > 0;
  })) << "floodplane and ExtractIndices did not subscribe their inputs within "
      << kWaitSeconds << " s";

  std::uint32_t seconds = 1000;
  for (sensor_msgs::PointCloud2 cloud : walkFrames()) {
    cloud.header.stamp = ros::Time(++seconds, 0);
    chain.points.publish(cloud);
    const auto planes = chain.planes.waitFor(cloud.header.stamp);
    const auto inliers = chain.inliers.waitFor(cloud.header.stamp);
    const auto extracted = chain.extracted.waitFor(cloud.header.stamp);
    ASSERT_TRUE(planes && inliers) << "floodplane published nothing for the frame at " << seconds;
    ASSERT_TRUE(extracted) << "ExtractIndices published nothing for the frame at " << seconds;
    ASSERT_FALSE(planes->planes.empty());
    const auto& largest = planes->planes.front();

    EXPECT_EQ(extracted->header.frame_id, cloud.header.frame_id);
    ASSERT_EQ(static_cast<std::size_t>(extracted->width) * extracted->height, largest.inlier_count);
    ASSERT_EQ(inliers->indices.size(), largest.inlier_count);
    sensor_msgs::PointCloud2ConstIterator<float> in(cloud, "x");
    sensor_msgs::PointCloud2ConstIterator<float> out(*extracted, "x");
    std::size_t moved = 0;
    double squared_distances = 0.0;
    double farthest = 0.0;
    for (std::size_t i = 0; i < inliers->indices.size(); ++i, ++out) {
      sensor_msgs::PointCloud2ConstIterator<float> source = in + inliers->indices[i];
      if (out[0] != source[0] || out[1] != source[1] || out[2] != source[2]) ++moved;
      const double distance = largest.plane.coef[0] * out[0] + largest.plane.coef[1] * out[1] +
                              largest.plane.coef[2] * out[2] + largest.plane.coef[3];
      squared_distances += distance * distance;
      farthest = std::max(farthest, std::abs(distance));
    }
    EXPECT_EQ(moved, 0u) << "points that are not the input's at their index";
    // On the plane: the points' mean squared distance to it is the one floodplane fitted it
    // with (its inliers), and none is farther than the sensor's noise puts it.
    EXPECT_NEAR(squared_distances / static_cast<double>(largest.inlier_count), largest.mean_squared_error,
                1e-3 * largest.mean_squared_error);
    EXPECT_LT(farthest, 0.1);
    std::cout << "[ INFO     ] frame " << seconds << ": " << largest.inlier_count << " points extracted, rms "
              << std::sqrt(largest.mean_squared_error) << " m, farthest " << farthest << " m from the plane\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "extract_indices_chain_test");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
