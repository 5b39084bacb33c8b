// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// bench_segmentation: floodplane against PCL's OMPS on the real frames and the project's
// scenes (issue 8's targets). Prints the configuration first; see bench/README.md.
#include <benchmark/benchmark.h>
#include <pcl/pcl_config.h>

#include <iostream>

#include "bench_frames.h"
#include "floodplane/version.h"
#include "methods.h"

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  std::cout << "floodplane " << FLOODPLANE_VERSION_STRING << ", PCL " << PCL_VERSION_PRETTY << ", compiler "
            << __VERSION__
#ifdef NDEBUG
            << ", optimised build"
#else
            << ", DEBUG build: timings are not meaningful"
#endif
            << "\n"
            << floodplane::bench::floodplaneConfiguration() << "\n"
            << floodplane::bench::ompsConfiguration() << "\n"
            << "real frames: " << floodplane::bench::realFrames().size() << " from " << FLOODPLANE_REAL_DATA_DIR
            << "; scenes: " << floodplane::bench::sceneNames().size() << " rendered with Kinect noise\n";
  floodplane::bench::registerFloodplane();
  floodplane::bench::registerOmps();
  floodplane::bench::registerSoak();
  floodplane::bench::registerSmoothing();
  floodplane::bench::registerNoiseEstimation();
  floodplane::bench::registerObjects();
  floodplane::bench::registerTracking();
  floodplane::bench::registerHeadStart();
  floodplane::bench::registerMemoryFloor();
  floodplane::bench::registerInterleavedMethods();
  floodplane::bench::registerResolutionSweep();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
