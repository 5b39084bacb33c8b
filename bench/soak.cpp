// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Soak run (issue 7): 10 000 segmentations of varied clouds in one process, as a camera loop
// running for minutes. The segmenter reuses its per-frame buffers, so resident memory must
// stay flat once every frame size has been seen; the counters report it at the first and the
// last segmentation, and the largest value in between.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <vector>

#include "bench_frames.h"
#include "floodplane/flood_fill_plane_segmentation.h"
#include "methods.h"

namespace floodplane::bench {

namespace {

constexpr int kSegmentations = 10000;

double residentMegabytes() {
  std::ifstream statm("/proc/self/statm");
  long pages_total = 0, pages_resident = 0;
  statm >> pages_total >> pages_resident;
  return static_cast<double>(pages_resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

void runSoak(benchmark::State& state) {
  // Every scene at two sizes, and the real frames: sizes change from one call to the next,
  // which is the worst case for buffer reuse.
  std::vector<const Frame*> frames;
  for (const std::string& scene : sceneNames()) {
    frames.push_back(&renderedFrame(scene, 640, 480));
    frames.push_back(&renderedFrame(scene, 320, 240));
  }
  for (const Frame& frame : realFrames()) frames.push_back(&frame);

  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers, label_indices, boundaries;
  pcl::PointCloud<pcl::Label>::Ptr labels(new pcl::PointCloud<pcl::Label>);
  double first = 0.0, last = 0.0, peak = 0.0, planes = 0.0;
  for (auto _ : state) {
    for (int i = 0; i < kSegmentations; ++i) {
      const Frame& frame = *frames[static_cast<std::size_t>(i) % frames.size()];
      seg.setSubsampling(i % 7 == 3 ? 2 : 1);  // the sub-sampled path too, now and then
      seg.setInputCloud(frame.cloud);
      seg.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);
      planes += static_cast<double>(regions.size());
      const double rss = residentMegabytes();
      if (i == 0) first = rss;
      last = rss;
      peak = std::max(peak, rss);
    }
  }
  state.counters["segmentations"] = kSegmentations;
  state.counters["frames"] = static_cast<double>(frames.size());
  state.counters["rss_first_MB"] = first;
  state.counters["rss_last_MB"] = last;
  state.counters["rss_peak_MB"] = peak;
  state.counters["planes_per_call"] = planes / kSegmentations;
}

}  // namespace

void registerSoak() {
  benchmark::RegisterBenchmark("floodplane/soak", runSoak)->Iterations(1)->Unit(benchmark::kSecond);
}

}  // namespace floodplane::bench
