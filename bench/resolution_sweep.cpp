// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The resolution sweep: boxes_on_floor rendered with Kinect noise at 320x240 to 2560x1920,
// floodplane's segmentAndRefine at s = 1 and s = 4. Per size: the time of a call, the time per
// pixel, and the memory the segmentation adds to the process (peak resident set during the
// first call and the timed ones, less what was resident before: the cloud, the libraries)
// against the cloud's own size. Run one benchmark per process for the memory figures
// (bench/resolution_sweep.py does): the peak is the process's.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <fstream>
#include <string>

#include "bench_frames.h"
#include "floodplane_run.h"
#include "methods.h"

namespace floodplane::bench {

namespace {

// A field of /proc/self/status in MiB (VmRSS, VmHWM); 0 where there is none.
double statusMiB(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(field + ":", 0) != 0) continue;
    return std::stod(line.substr(field.size() + 1)) / 1024.0;  // kB
  }
  return 0.0;
}

// Resets the peak resident set to the current one (Linux: clear_refs 5).
void resetPeak() { std::ofstream("/proc/self/clear_refs") << "5"; }

void runSize(benchmark::State& state, const Frame& frame, int subsampling) {
  malloc_trim(0);  // the renderer's freed memory goes back: it would hide what the call allocates
  const double before = statusMiB("VmRSS");
  resetPeak();
  FloodplaneRun run(subsampling);
  run(frame);  // allocates
  for (auto _ : state) run(frame);
  const double pixels = static_cast<double>(frame.cloud->size());
  const double cloud = pixels * sizeof(pcl::PointXYZ) / (1024.0 * 1024.0);
  const double added = statusMiB("VmHWM") - before;
  state.counters["planes"] = static_cast<double>(run.regions.size());
  state.counters["ns_per_px"] =
      benchmark::Counter(pixels * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["cloud_MiB"] = cloud;
  state.counters["added_MiB"] = added;
  state.counters["added_per_cloud"] = added / cloud;
}

}  // namespace

void registerResolutionSweep() {
  for (const int s : {1, 4}) {
    for (const auto& [w, h] : kSweepSizes) {
      const std::string name = "resolution/s" + std::to_string(s) + "/" + std::to_string(w) + "x" + std::to_string(h);
      const FrameSource frame = rendered("boxes_on_floor", w, h);
      benchmark::RegisterBenchmark(name.c_str(), [frame, s = s](benchmark::State& state) {
        runSize(state, frame(), s);
      })->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace floodplane::bench
