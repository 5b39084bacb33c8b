// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The side file that lists a rendered frame's ground-truth planes.

#include <string>

#include "synth/rendered_frame.h"

namespace floodplane::synth {

/// The frame's plane listing as JSON text (format in data/scenes/README.md): the scene,
/// sensor model, seed (noisy sensors only) and camera intrinsics, then one entry per plane with its
/// id, primitive, face, unit normal (towards the camera), d (n . P + d = 0, camera frame,
/// metres), pixel count and whether it faces the camera. "up": the world's up (its z) in the
/// camera frame, unit (cameraUp), what pcd_segment --up takes.
std::string groundTruthJson(const RenderedFrame& frame);

/// The up direction (against gravity) in the frame's camera frame: the world's z turned by the
/// inverse of the camera's orientation; (0, -1, 0) for a level camera.
Eigen::Vector3d cameraUp(const RenderedFrame& frame);

}  // namespace floodplane::synth
