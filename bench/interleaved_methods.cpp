// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The coarse-to-fine targets in one process: per real frame, PCL's OMPS (the paper's settings,
// normals included, as the omps benchmark) and floodplane's segmentAndRefine at sub-sampling 1,
// 2 and 4, called in turn within every iteration (the order rotates), so that the shared
// machine's load hits all four alike. Reports each method's median time and the ratios that the
// targets name: OMPS / s for each s, and s2 / s1, s4 / s1.
#include <benchmark/benchmark.h>

#include <pcl/features/integral_image_normal.h>
#include <pcl/segmentation/organized_multi_plane_segmentation.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "baselines/omps_run.h"
#include "bench_frames.h"
#include "floodplane_run.h"
#include "methods.h"

namespace floodplane::bench {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

struct OmpsRun {
  OmpsRun() { baselines::configureOmps(normal_estimation, omps); }
  void operator()(const Frame& frame) {
    normal_estimation.setInputCloud(frame.cloud);
    normal_estimation.compute(*normals);
    omps.setInputCloud(frame.cloud);
    omps.setInputNormals(normals);
    baselines::segmentAndRefineAfresh(omps, outputs);
    benchmark::DoNotOptimize(outputs.regions.data());
  }
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> normal_estimation;
  pcl::OrganizedMultiPlaneSegmentation<pcl::PointXYZ, pcl::Normal, pcl::Label> omps;
  pcl::PointCloud<pcl::Normal>::Ptr normals{new pcl::PointCloud<pcl::Normal>};
  baselines::OmpsOutputs<pcl::PointXYZ> outputs;
};

void runInterleaved(benchmark::State& state, const Frame& frame) {
  OmpsRun omps;
  FloodplaneRun s1(1), s2(2), s4(4);
  const std::array<std::function<void(const Frame&)>, 4> methods = {std::ref(omps), std::ref(s1), std::ref(s2),
                                                                    std::ref(s4)};
  std::array<std::vector<double>, 4> times;
  for (const auto& method : methods) method(frame);  // the buffers, once, before the clock
  using Clock = std::chrono::steady_clock;
  std::size_t round = 0;
  for (auto _ : state) {
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const std::size_t m = (k + round) % methods.size();
      const Clock::time_point start = Clock::now();
      methods[m](frame);
      times[m].push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    ++round;
  }
  const double omps_ms = median(times[0]), s1_ms = median(times[1]), s2_ms = median(times[2]), s4_ms = median(times[3]);
  state.counters["omps_ms"] = omps_ms;
  state.counters["s1_ms"] = s1_ms;
  state.counters["s2_ms"] = s2_ms;
  state.counters["s4_ms"] = s4_ms;
  state.counters["omps_per_s1"] = omps_ms / s1_ms;
  state.counters["omps_per_s2"] = omps_ms / s2_ms;
  state.counters["omps_per_s4"] = omps_ms / s4_ms;
  state.counters["s2_per_s1"] = s2_ms / s1_ms;
  state.counters["s4_per_s1"] = s4_ms / s1_ms;
}

}  // namespace

void registerInterleavedMethods() {
  for (const Frame& frame : realFrames()) {
    benchmark::RegisterBenchmark(("interleaved/real:" + frame.name).c_str(), [&frame](benchmark::State& state) {
      runInterleaved(state, frame);
    })->Unit(benchmark::kMillisecond);
  }
}

}  // namespace floodplane::bench
