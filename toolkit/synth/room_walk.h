// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A camera walking through a generated room, rendered frame by frame: pcd_synth --random 1
// --seed S --sequence N without the files, for the benchmarks and tests of a stream of frames.

#include <cstdint>
#include <vector>

#include "synth/rendered_frame.h"
#include "synth/sensor_model.h"

namespace floodplane::synth {

/// The sensor noise seed of frame `frame` of a sequence whose noise seed is `seed`: `seed` for
/// frame 0 (the frame a single render gives), then spread by golden-ratio increments so that
/// no two frames share a noise pattern.
std::uint64_t sequenceFrameSeed(std::uint64_t seed, int frame);

/// Frames 0 .. frames - 1 of the walk through random room `seed` (generateRoomScene and
/// walkingCameraPath with that seed, noise seeds from sequenceFrameSeed), as `sensor` sees
/// them. Ground-truth ids are each frame's own: pcd_synth also makes coplanar faces merged in
/// any frame one id in all (SequenceSurfaces), which a single frame's scoring does not need.
std::vector<RenderedFrame> renderRoomWalk(std::uint64_t seed, int frames, SensorModel sensor);

}  // namespace floodplane::synth
