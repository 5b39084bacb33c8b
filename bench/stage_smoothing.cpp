// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The depth smoothing alone (depth_smoothing.h), four points at a time (SSE2) against the
// widest loop the CPU runs (eight, AVX), on the real frames with the noise the segmenter
// measures on each. The two give the same floats (DepthSmoothing tests); this is their speed.
#include <benchmark/benchmark.h>

#include "bench_frames.h"
#include "frame/depth_smoothing.h"
#include "frame/noise_estimator.h"
#include "methods.h"
#include "util/simd.h"

namespace floodplane::bench {

namespace {

void runSmoothing(benchmark::State& state, const Frame& frame, DepthSmoothing::VectorWidth width) {
  const PointGrid grid = gridOf(frame);
  NoiseEstimator estimator;
  const NoiseModel noise = estimator.estimate(grid);
  DepthSmoothing smoothing(width);
  for (auto _ : state) benchmark::DoNotOptimize(smoothing.smooth(grid, noise).data);
}

}  // namespace

void registerSmoothing() {
  for (const Frame& frame : realFrames()) {
    const Frame* f = &frame;
    benchmark::RegisterBenchmark(("smoothing/sse2/real:" + frame.name).c_str(), [f](benchmark::State& state) {
      runSmoothing(state, *f, DepthSmoothing::VectorWidth::kSse2);
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("smoothing/widest/real:" + frame.name).c_str(), [f](benchmark::State& state) {
      if (!cpuHasAvx()) state.SkipWithError("no AVX on this CPU: the widest loop is the SSE2 one");
      runSmoothing(state, *f, DepthSmoothing::VectorWidth::kWidest);
    })->Unit(benchmark::kMillisecond);
  }
}

}  // namespace floodplane::bench
