// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// ROS 1 messages to and from the ROS-free conversion structs (conversion/): field for field,
// the data left in place.

#include <floodplane_ros/Plane.h>
#include <geometry_msgs/Transform.h>
#include <pcl_msgs/ModelCoefficients.h>
#include <pcl_msgs/PointIndices.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include <vector>

#include "chained_plane.h"
#include "cloud_points.h"
#include "depth_image.h"
#include "plane_descriptions.h"
#include "plane_transform.h"

namespace floodplane_ros {

floodplane::conversion::CloudView cloudView(const sensor_msgs::PointCloud2& cloud);
floodplane::conversion::ImageView imageView(const sensor_msgs::Image& image);
floodplane::conversion::CameraInfoView cameraInfoView(const sensor_msgs::CameraInfo& info);

Plane planeMessage(const floodplane::conversion::PlaneDescription& plane);

floodplane::conversion::RigidTransform rigidTransform(const geometry_msgs::Transform& transform);

/// The chained plane as pcl_ros's SACSegmentation publishes its model: its indices and its
/// coefficients, each with `header`.
pcl_msgs::PointIndices pointIndices(const std_msgs::Header& header, const floodplane::conversion::ChainedPlane& plane);
pcl_msgs::ModelCoefficients modelCoefficients(const std_msgs::Header& header,
                                              const floodplane::conversion::ChainedPlane& plane);

/// The label image (32SC1, conversion/label_image.h) of a segmentation's `labels` on a width x
/// height grid, each plane k's pixels plane_labels[k - 1].
sensor_msgs::Image labelImage(const std_msgs::Header& header, int width, int height,
                              const std::vector<std::uint32_t>& labels, const std::vector<std::uint32_t>& plane_labels);

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
