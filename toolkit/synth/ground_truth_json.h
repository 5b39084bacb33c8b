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
/// metres), pixel count and whether it faces the camera.
std::string groundTruthJson(const RenderedFrame& frame);

}  // namespace floodplane::synth
