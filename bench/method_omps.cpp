// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// PCL OrganizedMultiPlaneSegmentation with IntegralImageNormalEstimation, the settings of the
// paper's Sec. IV, shared with pcd_compare (toolkit/baselines/omps_run.h). Normal estimation is part
// of the timed call, since OMPS cannot run without it.
#include <benchmark/benchmark.h>

#include <pcl/features/integral_image_normal.h>
#include <pcl/segmentation/organized_multi_plane_segmentation.h>

#include <sstream>

#include "baselines/omps_run.h"
#include "bench_frames.h"
#include "methods.h"

namespace floodplane::bench {

namespace {

void runOmps(benchmark::State& state, const Frame& frame) {
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> normals_estimation;
  pcl::OrganizedMultiPlaneSegmentation<pcl::PointXYZ, pcl::Normal, pcl::Label> omps;
  baselines::configureOmps(normals_estimation, omps);
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  baselines::OmpsOutputs<pcl::PointXYZ> outputs;
  for (auto _ : state) {
    normals_estimation.setInputCloud(frame.cloud);
    normals_estimation.compute(*normals);
    omps.setInputCloud(frame.cloud);
    omps.setInputNormals(normals);
    baselines::segmentAndRefineAfresh(omps, outputs);
    benchmark::DoNotOptimize(outputs.regions.data());
  }
  state.counters["planes"] = static_cast<double>(outputs.regions.size());
}

void add(const std::string& name, FrameSource frame) {
  benchmark::RegisterBenchmark(name.c_str(), [frame](benchmark::State& state) {
    runOmps(state, frame());
  })->Unit(benchmark::kMillisecond);
}

}  // namespace

std::string ompsConfiguration() {
  using Settings = baselines::OmpsSettings;
  std::ostringstream text;
  text << "PCL OMPS: IntegralImageNormalEstimation (AVERAGE_3D_GRADIENT, smoothing " << Settings::normal_smoothing_size
       << ", max depth change " << Settings::max_depth_change_factor << ") + OrganizedMultiPlaneSegmentation (angular "
       << Settings::angular_threshold << " rad, distance " << Settings::distance_threshold << " m, min inliers "
       << Settings::min_inliers << "), segmentAndRefine";
  return text.str();
}

void registerOmps() {
  for (const Frame& frame : realFrames()) add("omps/real:" + frame.name, real(frame));
  for (const std::string& scene : sceneNames()) add("omps/scene:" + scene, rendered(scene, 640, 480));
}

}  // namespace floodplane::bench
