// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The least any pixel-accurate segmentation of a frame costs on this machine: one pass that
// reads every point and writes a label per pixel, with no other work (issue 16's 1 ms target
// is measured against it). Two ways:
//   floor/real:<frame>  the same frame every call, as floodplane/s1/real runs (a 640x480
//                       frame's 4.9 MB of points stay in a 32 MiB L3 between calls);
//   floor/cold          the next real frame every call, round robin, so the points come from
//                       memory (the seven frames and their labels exceed the L3).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "bench_frames.h"
#include "methods.h"

namespace floodplane::bench {

namespace {

// Label 1 where the point has a finite depth, 0 elsewhere: the point is read, a label written.
void labelFinite(const pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<std::uint32_t>& labels) {
  labels.resize(cloud.size());
  const std::size_t n = cloud.size();
  for (std::size_t i = 0; i < n; ++i) labels[i] = cloud[i].z == cloud[i].z ? 1u : 0u;
}

}  // namespace

void registerMemoryFloor() {
  for (const Frame& frame : realFrames()) {
    const Frame* f = &frame;
    benchmark::RegisterBenchmark(("floor/real:" + frame.name).c_str(), [f](benchmark::State& state) {
      std::vector<std::uint32_t> labels;
      for (auto _ : state) {
        labelFinite(*f->cloud, labels);
        benchmark::DoNotOptimize(labels.data());
        benchmark::ClobberMemory();
      }
    })->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("floor/cold", [](benchmark::State& state) {
    const std::vector<Frame>& frames = realFrames();
    if (frames.empty()) {
      state.SkipWithError("no real frames in " FLOODPLANE_REAL_DATA_DIR);
      return;
    }
    std::vector<std::vector<std::uint32_t>> labels(frames.size());
    std::size_t next = 0;
    for (auto _ : state) {
      labelFinite(*frames[next].cloud, labels[next]);
      benchmark::DoNotOptimize(labels[next].data());
      benchmark::ClobberMemory();
      next = (next + 1) % frames.size();
    }
  })->Unit(benchmark::kMillisecond);
}

}  // namespace floodplane::bench
