// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The labels the library gives a cloud: the reference an app's labelled output is checked
// against.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "floodplane/flood_fill_plane_segmentation.h"
#include "floodplane/params.h"

namespace floodplane::test {

inline std::vector<std::uint32_t> libraryLabels(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                const floodplane::Params& params = {}) {
  floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ> segmentation(params);
  segmentation.setInputCloud(std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(cloud));
  floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers, label_indices, boundaries;
  pcl::PointCloud<pcl::Label>::Ptr labels;
  segmentation.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);
  std::vector<std::uint32_t> out;
  for (const auto& l : *labels) out.push_back(l.label);
  return out;
}

/// The object labels the library gives a cloud (the PCL class's segmentObjects after
/// segmentAndRefine), and one PointIndices per object in `indices` when given.
inline std::vector<std::uint32_t> libraryObjectLabels(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                      std::vector<pcl::PointIndices>* indices = nullptr) {
  floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ> segmentation;
  segmentation.setInputCloud(std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(cloud));
  floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions;
  segmentation.segmentAndRefine(regions);
  pcl::PointCloud<pcl::Label> labels;
  std::vector<pcl::PointIndices> object_indices;
  segmentation.segmentObjects(labels, object_indices);
  if (indices) *indices = object_indices;
  std::vector<std::uint32_t> out;
  for (const auto& l : labels) out.push_back(l.label);
  return out;
}

}  // namespace floodplane::test
