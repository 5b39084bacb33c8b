// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The noise estimation alone (noise_estimator.h) on the real frames and on one scene at every
// frame size of floodplane/s1/size. It fits about a thousand patches whatever the frame's size
// (kPatchesPerFrame), so it is a fixed cost per call: this measures how large.
#include <benchmark/benchmark.h>

#include "bench_frames.h"
#include "frame/noise_estimator.h"
#include "methods.h"

namespace floodplane::bench {

namespace {

void runNoiseEstimation(benchmark::State& state, const Frame& frame) {
  const PointGrid grid = gridOf(frame);
  NoiseEstimator estimator;
  NoiseModel model;
  for (auto _ : state) {
    model = estimator.estimate(grid);
    benchmark::DoNotOptimize(model);
  }
  state.counters["patches"] = static_cast<double>(model.patches);
}

void add(const std::string& name, FrameSource frame) {
  benchmark::RegisterBenchmark(name.c_str(), [frame](benchmark::State& state) {
    runNoiseEstimation(state, frame());
  })->Unit(benchmark::kMillisecond);
}

}  // namespace

void registerNoiseEstimation() {
  for (const Frame& frame : realFrames()) add("noise/real:" + frame.name, real(frame));
  for (const auto& [w, h] : kFrameSizes)
    add("noise/size:" + std::to_string(w) + "x" + std::to_string(h), rendered("boxes_on_floor", w, h));
}

}  // namespace floodplane::bench
