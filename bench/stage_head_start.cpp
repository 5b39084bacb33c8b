// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Issue 28's head start: each frame of a rendered walk (pcd_synth --sequence, Kinect noise)
// segmented cold and with a head start from the previous frame (Segmenter::Options::head_start),
// the two interleaved frame by frame in one run (which goes first alternates) so that the
// machine's load hits both alike. Reports the median per-frame time of each, their ratio, and
// the mean time per phase of each (c_ cold, w_ warm): where the head start saves.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "floodplane/segmenter.h"
#include "methods.h"
#include "synth/room_walk.h"

namespace floodplane::bench {

namespace {

// The report seeds' first scene (tuned on 1-100, reported on 101-200), walked for two seconds.
constexpr std::uint64_t kSequenceSeed = 101;
constexpr int kSequenceFrames = 60;

// pcd_synth --random 1 --seed S --sequence N --sensor kinect, without the files.
const std::vector<synth::RenderedFrame>& renderedSequence() {
  static const std::vector<synth::RenderedFrame> frames =
      synth::renderRoomWalk(kSequenceSeed, kSequenceFrames, synth::SensorModel::kinect);
  return frames;
}

// A rendered frame's points, read in place (an Eigen::Vector3f is three floats).
PointGrid gridOf(const synth::RenderedFrame& frame) {
  static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float));
  return PointGrid{frame.points.data()->data(), 3, frame.intrinsics.width, frame.intrinsics.height};
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

void runHeadStart(benchmark::State& state) {
  const std::vector<synth::RenderedFrame>& frames = renderedSequence();
  Segmenter cold_segmenter, warm_segmenter;
  Segmenter::Options cold, warm;
  cold.measure_phases = warm.measure_phases = true;
  warm.head_start = true;
  std::vector<double> cold_ms, warm_ms;
  PhaseTimes cold_phases, warm_phases;
  using Clock = std::chrono::steady_clock;
  std::size_t next = 0, round = 0;
  for (auto _ : state) {
    const PointGrid grid = gridOf(frames[next]);
    const auto timeOne = [&](Segmenter& segmenter, const Segmenter::Options& options, std::vector<double>& times,
                             PhaseTimes& phases) {
      const Clock::time_point start = Clock::now();
      const Segmentation& result = segmenter.segment(grid, options);
      times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      phases.preparation += result.phases.preparation;
      phases.seed_selection += result.phases.seed_selection;
      phases.flood_fill += result.phases.flood_fill;
      phases.relabelling += result.phases.relabelling;
      phases.merging += result.phases.merging;
      phases.region_output += result.phases.region_output;
    };
    // Which goes first alternates by frame, and flips on each pass over the sequence.
    if ((round + round / frames.size()) % 2 == 0) {
      timeOne(cold_segmenter, cold, cold_ms, cold_phases);
      timeOne(warm_segmenter, warm, warm_ms, warm_phases);
    } else {
      timeOne(warm_segmenter, warm, warm_ms, warm_phases);
      timeOne(cold_segmenter, cold, cold_ms, cold_phases);
    }
    next = (next + 1) % frames.size();
    ++round;
  }
  const double n = static_cast<double>(cold_ms.size());
  state.counters["cold_ms"] = median(cold_ms);
  state.counters["warm_ms"] = median(warm_ms);
  state.counters["speedup"] = median(cold_ms) / median(warm_ms);
  // Mean milliseconds per frame by phase, cold (c_) and warm (w_): where a head start saves.
  for (const auto& [prefix, phases] : {std::pair{"c_", &cold_phases}, std::pair{"w_", &warm_phases}}) {
    state.counters[std::string(prefix) + "prep"] = phases->preparation / n;
    state.counters[std::string(prefix) + "seed"] = phases->seed_selection / n;
    state.counters[std::string(prefix) + "flood"] = phases->flood_fill / n;
    state.counters[std::string(prefix) + "relabel"] = phases->relabelling / n;
    state.counters[std::string(prefix) + "merge"] = phases->merging / n;
    state.counters[std::string(prefix) + "output"] = phases->region_output / n;
  }
}

}  // namespace

void registerHeadStart() {
  benchmark::RegisterBenchmark("head_start/kinect_walk:random_0101", runHeadStart)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(kSequenceFrames * 3);
}

}  // namespace floodplane::bench
