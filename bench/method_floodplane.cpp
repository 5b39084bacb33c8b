// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// floodplane: FloodFillPlaneSegmentation::segmentAndRefine with the paper's defaults, one
// segmenter reused across iterations as in a camera loop (its buffers are allocated once).
#include <benchmark/benchmark.h>

#include <chrono>
#include <sstream>

#include "bench_frames.h"
#include "floodplane/flood_fill_plane_segmentation.h"
#include "floodplane/io/params_json.h"
#include "methods.h"

namespace floodplane::bench {

namespace {

using Segmentation = FloodFillPlaneSegmentation<pcl::PointXYZ>;

void runFloodplane(benchmark::State& state, const Frame& frame, int subsampling, bool phases) {
  Segmentation seg;
  seg.setSubsampling(subsampling);
  seg.setMeasurePhases(phases);
  seg.setInputCloud(frame.cloud);
  Segmentation::Regions regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers, label_indices, boundaries;
  pcl::PointCloud<pcl::Label>::Ptr labels(new pcl::PointCloud<pcl::Label>);
  // One call before the clock: it allocates the segmenter's buffers (on a 3840x2160 frame the
  // first call takes about 3x a later one, most of it page faults), which a camera loop pays once.
  seg.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);
  PhaseTimes sum;
  double calls_ms = 0.0;  // the calls' own clock, for the time outside every phase
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    seg.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);
    benchmark::DoNotOptimize(regions.data());
    if (phases) {
      calls_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      const PhaseTimes& t = seg.getLastPhases();
      sum.preparation += t.preparation;
      sum.seed_selection += t.seed_selection;
      sum.flood_fill += t.flood_fill;
      sum.relabelling += t.relabelling;
      sum.merging += t.merging;
      sum.region_output += t.region_output;
      sum.pcl_conversion += t.pcl_conversion;
    }
  }
  state.counters["planes"] = static_cast<double>(regions.size());
  state.counters["Mpx/s"] = benchmark::Counter(static_cast<double>(frame.cloud->size()) * 1e-6,
                                               benchmark::Counter::kIsIterationInvariantRate);
  if (phases) {
    const double n = static_cast<double>(state.iterations());
    state.counters["prep_ms"] = sum.preparation / n;
    state.counters["seed_ms"] = sum.seed_selection / n;
    state.counters["flood_ms"] = sum.flood_fill / n;
    state.counters["relabel_ms"] = sum.relabelling / n;
    state.counters["merge_ms"] = sum.merging / n;
    state.counters["output_ms"] = sum.region_output / n;
    state.counters["pcl_ms"] = sum.pcl_conversion / n;
    // "Phases add up" (issue 16): what of the call no phase accounts for.
    const double phases_ms = sum.preparation + sum.seed_selection + sum.flood_fill + sum.relabelling + sum.merging +
                             sum.region_output + sum.pcl_conversion;
    state.counters["outside_ms"] = (calls_ms - phases_ms) / n;
    // The flood's work: floods, the segments they leave after relabelling (issue 25: at most
    // 100 on a real frame), and the merges that join them again.
    const SegmentationStats& stats = seg.getLastSegmentation().stats;
    state.counters["seeds"] = static_cast<double>(stats.seeds);
    state.counters["segments"] = static_cast<double>(stats.segments);
    state.counters["merges"] = static_cast<double>(stats.merges);
  }
}

// `frame` is called when the benchmark runs, so that a filtered run renders only its scenes.
void add(const std::string& name, FrameSource frame, int subsampling, bool phases = false) {
  benchmark::RegisterBenchmark(name.c_str(), [frame, subsampling, phases](benchmark::State& state) {
    runFloodplane(state, frame(), subsampling, phases);
  })->Unit(benchmark::kMillisecond);
}

}  // namespace

std::string floodplaneConfiguration() {
  return "floodplane: segmentAndRefine, " + floodplane::io::describeParams(Params());
}

void registerFloodplane() {
  // Target 1 (issue 8): full resolution, pixel-accurate, real frames and scenes.
  for (const Frame& frame : realFrames()) add("floodplane/s1/real:" + frame.name, real(frame), 1);
  for (const std::string& scene : sceneNames()) add("floodplane/s1/scene:" + scene, rendered(scene, 640, 480), 1);
  // Target 2: sub-sampling 2 (and Table III's 4 and 8), labels at full resolution.
  for (int s : {2, 4, 8}) {
    for (const Frame& frame : realFrames())
      add("floodplane/s" + std::to_string(s) + "/real:" + frame.name, real(frame), s);
  }
  for (const std::string& scene : sceneNames()) add("floodplane/s2/scene:" + scene, rendered(scene, 640, 480), 2);
  // Target 3: cost linear in the pixel count; 3840x2160 for the memory figure (issue 7).
  for (const auto& [w, h] : kFrameSizes) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    add("floodplane/s1/size:" + size, rendered("boxes_on_floor", w, h), 1);
  }
  // Fig. 5: time per phase (measuring adds a few clock reads per seed): floodplane/phases<s>/<set>,
  // s = 1 without a number; the real frames, the bundled scenes with Kinect noise (scene) and
  // exact (exact). The phase table of bench/README.md (update_figures.py --phases) reads s = 1
  // and 4.
  for (const Frame& frame : realFrames()) add("floodplane/phases/real:" + frame.name, real(frame), 1, true);
  for (int s : {2, 4})
    for (const Frame& frame : realFrames())
      add("floodplane/phases" + std::to_string(s) + "/real:" + frame.name, real(frame), s, true);
  for (int s : {1, 4}) {
    const std::string prefix = "floodplane/phases" + (s == 1 ? std::string() : std::to_string(s));
    for (const std::string& scene : sceneNames()) {
      add(prefix + "/scene:" + scene, rendered(scene, 640, 480), s, true);
      add(prefix + "/exact:" + scene, rendered(scene, 640, 480, true), s, true);
    }
  }
}

}  // namespace floodplane::bench
