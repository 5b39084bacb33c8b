// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The node: the nodelet (floodplane_ros/SegmentationNodelet) loaded into a process of its own,
// for launch files without a nodelet manager. Same topics and parameters.

#include <nodelet/loader.h>
#include <ros/ros.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "floodplane");
  nodelet::Loader loader;
  const nodelet::M_string remappings = ros::names::getRemappings();
  const nodelet::V_string arguments(argv + 1, argv + argc);
  // Why it did not load is logged: by the loader for a nodelet it cannot find, by the nodelet
  // for a parameter it refuses.
  if (!loader.load(ros::this_node::getName(), "floodplane_ros/SegmentationNodelet", remappings, arguments)) {
    ROS_FATAL("could not load the nodelet floodplane_ros/SegmentationNodelet: see the error above");
    return 1;
  }
  ros::spin();
  return 0;
}
