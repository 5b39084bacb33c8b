// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The PCL face of a rendered frame.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "synth/rendered_frame.h"

namespace floodplane::synth {

/// The frame as an organized cloud (width x height) of measured points with their ground-truth
/// plane ids in `label`. Points are in the camera frame, so sensor_origin_ is zero;
/// sensor_orientation_ is the camera's orientation in the world (RenderedFrame::world_from_camera,
/// the PCD's VIEWPOINT), from which the up direction in the camera frame follows: the inverse
/// rotation of the world's z (cameraUp); is_dense is false if any point is NaN.
pcl::PointCloud<pcl::PointXYZL> toPointCloud(const RenderedFrame& frame);

}  // namespace floodplane::synth
