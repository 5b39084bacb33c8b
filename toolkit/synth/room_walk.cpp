// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/room_walk.h"

#include "synth/camera_path.h"
#include "synth/renderer.h"
#include "synth/scene_generator.h"

namespace floodplane::synth {

std::uint64_t sequenceFrameSeed(std::uint64_t seed, int frame) {
  return seed + static_cast<std::uint64_t>(frame) * 0x9E3779B97F4A7C15ULL;
}

std::vector<RenderedFrame> renderRoomWalk(std::uint64_t seed, int frames, SensorModel sensor) {
  const Scene scene = generateRoomScene(seed);
  const std::vector<Eigen::Isometry3d> poses = walkingCameraPath(scene, frames, seed);
  std::vector<RenderedFrame> walk;
  walk.reserve(poses.size());
  for (std::size_t k = 0; k < poses.size(); ++k) {
    Scene view = scene;
    view.world_from_camera = poses[k];
    RenderSettings settings;
    settings.sensor = sensor;
    settings.seed = sequenceFrameSeed(seed, static_cast<int>(k));
    walk.push_back(renderScene(view, settings));
  }
  return walk;
}

}  // namespace floodplane::synth
