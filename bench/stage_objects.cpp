// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The objects on the planes (floodplane/object_segmentation.h) against the planes they start
// from, interleaved: each iteration segments the frame's planes (Segmenter, the defaults) and
// then its objects, timing both, so that the ratio objects / planes (issue 59: at most 0.25)
// is measured under the same load. On the real frames and, when the mOSD learn frames are
// there (../shared/data/osd-learn), on the first of each kind (boxes, stacked, occluded,
// cylinders).
#include <benchmark/benchmark.h>

#include <pcl/io/pcd_io.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_frames.h"
#include "floodplane/object_segmentation.h"
#include "floodplane/segmenter.h"
#include "methods.h"

namespace floodplane::bench {

namespace {

void runObjects(benchmark::State& state, const Frame& frame) {
  const PointGrid grid = gridOf(frame);
  Segmenter segmenter;
  double planes_ms = 0.0;
  double objects_ms = 0.0;
  std::size_t objects = 0;
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const Clock::time_point start = Clock::now();
    const Segmentation& planes = segmenter.segment(grid);
    const Clock::time_point middle = Clock::now();
    const ObjectSegmentation found = segmentObjects(grid, planes);
    const Clock::time_point end = Clock::now();
    benchmark::DoNotOptimize(found.labels.data());
    planes_ms += std::chrono::duration<double, std::milli>(middle - start).count();
    objects_ms += std::chrono::duration<double, std::milli>(end - middle).count();
    objects = found.objects.size();
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["planes_ms"] = planes_ms / n;
  state.counters["objects_ms"] = objects_ms / n;
  state.counters["ratio"] = planes_ms > 0.0 ? objects_ms / planes_ms : 0.0;
  state.counters["objects"] = static_cast<double>(objects);
}

// The mOSD learn frames named, read once (empty when the data is not there).
const std::vector<Frame>& osdFrames() {
  static const std::vector<Frame> frames = [] {
    std::vector<Frame> out;
    const std::filesystem::path dir = std::filesystem::path(FLOODPLANE_REAL_DATA_DIR).parent_path() / "osd-learn";
    for (const char* name : {"learn0", "learn17", "learn25", "learn33"}) {
      const std::filesystem::path path = dir / (std::string(name) + ".pcd");
      if (!std::filesystem::exists(path)) continue;
      Frame frame{name, pcl::PointCloud<pcl::PointXYZ>::Ptr(new pcl::PointCloud<pcl::PointXYZ>)};
      if (pcl::io::loadPCDFile(path.string(), *frame.cloud) == 0 && frame.cloud->isOrganized()) out.push_back(frame);
    }
    return out;
  }();
  return frames;
}

void add(const std::string& name, const Frame& frame) {
  benchmark::RegisterBenchmark(name.c_str(), [&frame](benchmark::State& state) {
    runObjects(state, frame);
  })->Unit(benchmark::kMillisecond);
}

}  // namespace

void registerObjects() {
  for (const Frame& frame : realFrames()) add("objects/real:" + frame.name, frame);
  for (const Frame& frame : osdFrames()) add("objects/osd:" + frame.name, frame);
}

}  // namespace floodplane::bench
