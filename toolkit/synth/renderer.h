// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Rendering a scene into an organized frame by casting one ray through every pixel centre.

#include <cstdint>

#include "synth/depth_warp.h"
#include "synth/rendered_frame.h"
#include "synth/scanner_model.h"
#include "synth/scene.h"
#include "synth/sensor_model.h"

namespace floodplane::synth {

struct RenderSettings {
  SensorModel sensor = SensorModel::none;
  std::uint64_t seed = 1;  ///< the noise of kinect and scanner; the same seed gives the same frame
  KinectParams kinect;     ///< used when sensor == SensorModel::kinect
  ScannerParams scanner;   ///< used when sensor == SensorModel::scanner
  /// The calibration warp of the kinect and scanner models (off by default; none is exact).
  /// Its own seed, not `seed`: a sequence keeps one calibration while its noise changes.
  DepthWarpParams warp;
};

/// Renders `scene` through its camera (scene.intrinsics, scene.world_from_camera). The scanner
/// model renders through the scene's camera too (generated scanner scenes use
/// scannerIntrinsics()), with its projector at the camera's right.
/// Deterministic: the same scene and settings give an identical frame, bit for bit.
/// Throws SceneError for invalid intrinsics or geometry (see RayCaster), and
/// std::invalid_argument for a negative or non-finite warp amplitude.
RenderedFrame renderScene(const Scene& scene, const RenderSettings& settings);

}  // namespace floodplane::synth
