// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// floodplane's segmentAndRefine as the benchmarks call it.
#pragma once

#include <benchmark/benchmark.h>

#include <vector>

#include "bench_frames.h"
#include "floodplane/flood_fill_plane_segmentation.h"

namespace floodplane::bench {

/// floodplane's calls, with their outputs kept between calls as a camera loop keeps them.
struct FloodplaneRun {
  explicit FloodplaneRun(int subsampling) {
    segmentation.setSubsampling(subsampling);
    labels.reset(new pcl::PointCloud<pcl::Label>);
  }
  void operator()(const Frame& frame) {
    segmentation.setInputCloud(frame.cloud);
    segmentation.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);
    benchmark::DoNotOptimize(regions.data());
  }
  FloodFillPlaneSegmentation<pcl::PointXYZ> segmentation;
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers, label_indices, boundaries;
  pcl::PointCloud<pcl::Label>::Ptr labels;
};

}  // namespace floodplane::bench
