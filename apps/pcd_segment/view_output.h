// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// pcd_segment's 3-D outputs: the snapshot (an image rendered off screen) and the window of
// --view, both drawn by view/plane_view.h from the segmentation's planar regions.

#include <pcl/ModelCoefficients.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "floodplane/flood_fill_plane_segmentation.h"
#include "view/plane_scene.h"

namespace pcd_segment {

using Regions = floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions;

/// How snapshots are taken.
struct SnapshotSettings {
  int width = 800;
  int height = 600;
  floodplane::view::CameraView camera = floodplane::view::CameraView::oblique;
};

/// Parses "WxH" (e.g. "800x600") into a width and a height, each 16..8192; std::nullopt
/// for anything else.
std::optional<std::pair<int, int>> parseImageSize(const std::string& text);

/// The scene of one segmented cloud: points coloured by their label, and per plane k (label
/// k) a marker from regions[k-1] (centroid, size from its covariance, inlier count, contour)
/// and coefficients[k-1] (the normal, towards the sensor). `plane_labels`, when not empty, is
/// the label of each plane instead (track ids, with --track).
floodplane::view::PlaneScene planeScene(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& points,
                                        const pcl::PointCloud<pcl::Label>& labels, const Regions& regions,
                                        const std::vector<pcl::ModelCoefficients>& coefficients,
                                        const std::vector<std::uint32_t>& plane_labels = {});

/// Renders `scene` as the bytes of a PNG file, for floodplane::io::AtomicFileGroup to write
/// with the input's other outputs. Throws std::runtime_error with one line when it cannot (no
/// display, VTK error).
std::string snapshotPng(const floodplane::view::PlaneScene& scene, const SnapshotSettings& settings);

}  // namespace pcd_segment
