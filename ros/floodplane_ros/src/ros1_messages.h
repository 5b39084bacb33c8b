// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// ROS 1 messages to and from the ROS-free conversion structs (conversion/): field for field,
// the data left in place.

#include <floodplane_ros/Plane.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include <vector>

#include "cloud_points.h"
#include "depth_image.h"
#include "plane_descriptions.h"

namespace floodplane_ros {

floodplane::conversion::CloudView cloudView(const sensor_msgs::PointCloud2& cloud);
floodplane::conversion::ImageView imageView(const sensor_msgs::Image& image);
floodplane::conversion::CameraInfoView cameraInfoView(const sensor_msgs::CameraInfo& info);

Plane planeMessage(const floodplane::conversion::PlaneDescription& plane);

/// An organized cloud of `fields` and point_step whose data is sized for width x height
/// points, to be filled in place.
sensor_msgs::PointCloud2 organizedCloud(const std_msgs::Header& header, int width, int height,
                                        const std::vector<floodplane::conversion::PointField>& fields,
                                        std::uint32_t point_step);

/// rviz markers of a frame's planes: a DELETEALL (the last frame's markers go), then per plane
/// its outline (namespace "outlines", a line strip) and its normal (namespace "normals", an
/// arrow), with the plane's index as id.
visualization_msgs::MarkerArray planeMarkers(const std_msgs::Header& header,
                                             const std::vector<floodplane::conversion::PlaneOutline>& outlines,
                                             double line_width);

}  // namespace floodplane_ros
