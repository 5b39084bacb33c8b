// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the rostests of the node's chained outputs, its laziness and its target frame share:
// organized clouds as a driver publishes them, and waiting within a bound for what a node does.

#include <ros/master.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud2_iterator.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace floodplane_ros::test {

inline constexpr double kWaitSeconds = 60.0;

/// An organized cloud of x y z float32 (PCL's PointXYZ layout: 16 bytes a point) on a width x
/// height grid, from `xyz` (stride 3, NaN for no return).
inline sensor_msgs::PointCloud2 organizedCloud(int width, int height, const std::vector<float>& xyz,
                                               const std::string& frame_id) {
  sensor_msgs::PointCloud2 cloud;
  cloud.header.frame_id = frame_id;
  sensor_msgs::PointCloud2Modifier modifier(cloud);
  modifier.setPointCloud2FieldsByString(1, "xyz");
  modifier.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  cloud.width = static_cast<std::uint32_t>(width);
  cloud.height = static_cast<std::uint32_t>(height);
  cloud.row_step = cloud.width * cloud.point_step;
  cloud.is_dense = false;
  sensor_msgs::PointCloud2Iterator<float> x(cloud, "x");
  for (std::size_t i = 0; i < xyz.size() / 3; ++i, ++x) {
    x[0] = xyz[3 * i];
    x[1] = xyz[3 * i + 1];
    x[2] = xyz[3 * i + 2];
  }
  return cloud;
}

/// Whether `condition` holds within `seconds`, polled (for what ROS answers without a message:
/// subscriber counts, the master's lists).
inline bool becomes(const std::function<bool()>& condition, double seconds = kWaitSeconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline && ros::ok()) {
    if (condition()) return true;
    ros::WallDuration(0.02).sleep();
  }
  return condition();
}

/// The nodes the master lists as subscribers of `topic` (a nodelet is its manager's node).
inline std::vector<std::string> subscribersOf(const std::string& topic) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  std::vector<std::string> nodes;
  if (!ros::master::execute("getSystemState", request, response, payload, false)) return nodes;
  XmlRpc::XmlRpcValue& subscriptions = payload[1];
  for (int i = 0; i < subscriptions.size(); ++i) {
    if (static_cast<std::string>(subscriptions[i][0]) != topic) continue;
    for (int k = 0; k < subscriptions[i][1].size(); ++k) nodes.push_back(subscriptions[i][1][k]);
  }
  return nodes;
}

/// Messages of one type as they arrive, by stamp, for a test to wait on.
template <typename Message>
class Inbox {
 public:
  Inbox(ros::NodeHandle& nh, const std::string& topic, std::function<ros::Time(const Message&)> stamp_of)
      : stamp_of_(std::move(stamp_of)) {
    const boost::function<void(const boost::shared_ptr<const Message>&)> receive =
        [this](const boost::shared_ptr<const Message>& message) {
          std::lock_guard<std::mutex> lock(mutex_);
          received_.push_back(message);
          arrived_.notify_all();
        };
    subscriber_ = nh.subscribe<Message>(topic, 10, receive);
  }
  explicit Inbox(ros::NodeHandle& nh, const std::string& topic)
      : Inbox(nh, topic, [](const Message& message) { return message.header.stamp; }) {}

  /// The message stamped `stamp`, or null when none came within the wait.
  boost::shared_ptr<const Message> waitFor(const ros::Time& stamp, double seconds = kWaitSeconds) {
    std::unique_lock<std::mutex> lock(mutex_);
    boost::shared_ptr<const Message> found;
    arrived_.wait_for(lock, std::chrono::duration<double>(seconds), [&] {
      for (const auto& message : received_) {
        if (stamp_of_(*message) == stamp) found = message;
      }
      return found || !ros::ok();
    });
    return found;
  }
  std::size_t count() {
    std::lock_guard<std::mutex> lock(mutex_);
    return received_.size();
  }
  ros::Subscriber& subscriber() { return subscriber_; }

 private:
  std::function<ros::Time(const Message&)> stamp_of_;
  ros::Subscriber subscriber_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::vector<boost::shared_ptr<const Message>> received_;
};

}  // namespace floodplane_ros::test
