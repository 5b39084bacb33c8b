#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Installs the optional ROS 1 part's packages from Debian 12 (ROS Noetic's libraries as Debian
# packages them; Debian 12 has no ROS 2): what ros/floodplane_ros needs to build, its nodelet
# and node, dynamic reconfigure, diagnostics and rostest with a master to run its test, and
# what a ROS user works with next to the node (docs/ros.md): catkin_make for a
# workspace, rosrun, the Python messages that `rostopic echo` of the node's topics imports,
# pcd_to_pointcloud to play a PCD file, pcl_ros's filter nodelets to chain onto its inliers
# (its rostest chains ExtractIndices) and rviz to look at the planes. The rest of floodplane
# needs none of them (scripts/install_deps.sh). As root it installs them; otherwise it prints
# the command to run and fails, so nothing half-happens. `--list` prints the packages, one a
# line, and nothing else (scripts/check_ros_commands.py checks each with dpkg -s).
# After it, scripts/check_ros_commands.py finds every executable the ROS page (docs/ros.md) and
# the rostests run: a package missing here fails there, not on a user's machine.
set -euo pipefail

packages=(
  ros-core-dev                               # roscpp, rosbag, rostopic, the C++ std/sensor/shape/visualization messages
  catkin                                     # catkin_make: the package built in a catkin workspace
  libnodeletlib-dev libnodeletlib-tools      # the nodelet and the `nodelet` manager executable
  libimage-transport-dev                     # depth image + CameraInfo subscription (depth_image_proc's way)
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure  # dynamic_reconfigure (C++ and its cfg generator)
  libdiagnostic-updater-dev                  # the node's status on /diagnostics (diagnostic_updater)
  libpcl-msgs-dev python3-pcl-msgs           # pcl_msgs: the inliers and model topics (C++; Python for rostopic echo)
  libnodelet-topic-tools-dev                 # NodeletLazy: the input subscribed only while an output is
  libtf2-ros-dev                             # tf2_ros: ~target_frame (the library)
  tf2-tools                                  # tf2_ros's static_transform_publisher (docs/ros.md, target_frame.test)
  libpcl-ros-dev                             # pcl_ros's nodelets (ExtractIndices, ProjectInliers) chained onto inliers and model
  python3-rostest                            # rostest (roslaunch with a master on a port of its own)
  # The Python messages of the node's topics and of the ones floodplane_ros/Planes contains:
  # `rostopic echo` imports them.
  python3-std-msgs python3-sensor-msgs python3-geometry-msgs python3-shape-msgs
  python3-visualization-msgs python3-diagnostic-msgs
  rosbash                                    # rosrun
  pcl-ros-tools                              # pcd_to_pointcloud: a PCD file played as a PointCloud2 topic
  rviz                                       # the planes seen
)

if [ "${1:-}" = "--list" ]; then
  printf '%s\n' "${packages[@]}"
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_ros_deps: all ${#packages[@]} packages present"
  exit 0
fi

cmd="apt-get install -y --no-install-recommends ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "install_ros_deps: missing packages: ${missing[*]}" >&2
  echo "install_ros_deps: run as root:  apt-get update && $cmd" >&2
  exit 1
fi
echo "install_ros_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
$cmd
