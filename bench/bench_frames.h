// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The frames every benchmark runs on: the real 640x480 frames in ../shared/data/real (when
// present) and the project's scenes rendered at any resolution.
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "floodplane/point_grid.h"

namespace floodplane::bench {

struct Frame {
  std::string name;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
};

/// The real frames, sorted by name; empty when the folder is absent.
const std::vector<Frame>& realFrames();

/// Scene `scene` (a file stem in data/scenes) rendered with the Kinect noise model (`exact`:
/// without noise, pcd_synth's sensor none) at width x height (the intrinsics scaled with the
/// image), cached.
const Frame& renderedFrame(const std::string& scene, int width, int height, bool exact = false);

/// A frame produced when a benchmark first needs it.
using FrameSource = std::function<const Frame&()>;
inline FrameSource real(const Frame& frame) {
  return [&frame]() -> const Frame& { return frame; };
}
inline FrameSource rendered(const std::string& scene, int width, int height, bool exact = false) {
  return [=]() -> const Frame& { return renderedFrame(scene, width, height, exact); };
}

/// The frame sizes (width, height) of the size series (floodplane/s1/size, noise/size): cost
/// linear in the pixel count, issue 16; bench/targets.py reads the same five.
inline constexpr std::array<std::pair<int, int>, 5> kFrameSizes{
    {{320, 240}, {640, 480}, {1280, 960}, {1920, 1080}, {3840, 2160}}};

/// The sizes of the resolution sweep (resolution_sweep.cpp): 320x240 to 2560x1920.
inline constexpr std::array<std::pair<int, int>, 4> kSweepSizes{{{320, 240}, {640, 480}, {1280, 960}, {2560, 1920}}};

/// The core's view of a frame's points (no copy), for the benchmarks of single stages.
PointGrid gridOf(const Frame& frame);

/// The stems of data/scenes/*.json, sorted.
const std::vector<std::string>& sceneNames();

}  // namespace floodplane::bench
