// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The tracker alone (floodplane/plane_tracker.h): PlaneTracker::update and relabel on the three
// consecutive real Kinect frames (frame_20121214T14225*), segmented once beforehand and fed
// over and over in order, as a camera loop with tracking on pays them per frame. Issue 28's
// target is tracking under 5 % of a frame's time: compare with floodplane/s1/real:frame_* of
// the same run.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "bench_frames.h"
#include "floodplane/plane_tracker.h"
#include "floodplane/segmenter.h"
#include "methods.h"

namespace floodplane::bench {

namespace {

void runTracking(benchmark::State& state, const std::vector<const Frame*>& frames) {
  std::vector<Segmentation> sequence;
  Segmenter segmenter;
  for (const Frame* frame : frames) sequence.push_back(segmenter.segment(gridOf(*frame)));
  PlaneTracker tracker;
  std::vector<std::uint32_t> track_labels;
  std::size_t next = 0, planes = 0;
  for (auto _ : state) {
    const Segmentation& segmentation = sequence[next];
    benchmark::DoNotOptimize(tracker.update(segmentation).data());
    tracker.relabel(segmentation.labels, track_labels);
    benchmark::DoNotOptimize(track_labels.data());
    planes += segmentation.planes.size();
    next = (next + 1) % sequence.size();
  }
  state.counters["planes"] = static_cast<double>(planes) / static_cast<double>(state.iterations());
  state.counters["tracks"] = static_cast<double>(tracker.tracks().size());
}

}  // namespace

void registerTracking() {
  std::vector<const Frame*> frames;
  for (const Frame& frame : realFrames())
    if (frame.name.rfind("frame_20121214T14225", 0) == 0) frames.push_back(&frame);
  if (frames.empty()) return;  // the real frames' folder is absent
  benchmark::RegisterBenchmark("tracking/real:frame_20121214T14225*", [frames](benchmark::State& state) {
    runTracking(state, frames);
  })->Unit(benchmark::kMillisecond);
}

}  // namespace floodplane::bench
