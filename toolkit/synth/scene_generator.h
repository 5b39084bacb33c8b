// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Random scenes with ground truth, one pair per seed: a room for the depth camera (sensor
// models none and kinect) and a table of polyhedral blocks for the structured-light scanner;
// and a second family for the depth camera, boards 2 cm thick in a bare room (thin faces).
// Each scene depends on its seed alone (no global state), so seeds 1-100 and 101-200 are
// fixed sets and any one scene can be made again by itself. data/scenes/README.md lists the
// scene kinds and their parameter ranges.

#include <cstdint>
#include <string>

#include "synth/scene.h"

namespace floodplane::synth {

/// "random_0007": the name of the scenes of `seed` (at least 4 digits).
std::string randomSceneName(std::uint64_t seed);

/// A room seen by a Kinect-like camera (640 x 480, f = 525 px) from 0.5-6 m: floor, walls,
/// sometimes a ceiling, doors and recesses, and furniture of one of three kinds (office, hall,
/// storage). The camera looks at an object and sees at least four planes covering most of the
/// image. Throws std::runtime_error in the unlikely case that no camera pose fits after many
/// layouts (reported with the seed).
Scene generateRoomScene(std::uint64_t seed);

/// Polyhedral blocks (boxes, wedges, roof, arch and chamfered blocks, many-sided prisms,
/// cylinders; faces down to 2 cm, meeting at 10-30 degrees) on a table, seen from about 1 m
/// by the structured-light scanner (scannerIntrinsics()).
Scene generateBlocksScene(std::uint64_t seed);

/// The boards family (thin faces): the thickness of every board, metres.
inline constexpr double kBoardThickness = 0.02;

/// "boards_0007": the name of the boards scene of `seed` (at least 4 digits), so that it can
/// sit next to the room of the same seed.
std::string boardsSceneName(std::uint64_t seed);

/// A bare room (3-6 x 3-6 m, 2.4-3 m high, a ceiling one time in two) with 2-5 boards 2 cm
/// thick: standing on the floor flat against a wall, hung on a wall, leaning on a wall at 5-25
/// degrees, lying on the floor, or sticking out of a wall as a shelf. Each board is a box
/// primitive named "<kind> board <n>" ("leaning board 2") whose own y is its thickness, so its
/// faces +y and -y are the broad ones and +x, -x, +z, -z its 2 cm edges (isBoardEdgeFace).
/// Seen by a Kinect-like camera (640 x 480, f = 525 px) from 0.8-3.5 m, at 15-70 degrees to the
/// wall of the board it looks at, so that edges show obliquely: a pose is kept only if a 320 x
/// 240 render shows at least one edge with 77 pixels (about 308 in the frame, pcd_segment's
/// smallest plane). Three boards in five that stand at a wall stand at one main wall. Throws
/// std::runtime_error if no pose fits after many layouts (reported with the seed).
Scene generateBoardsScene(std::uint64_t seed);

/// Whether the face `face` ("+x" ... "-z", a ground-truth plane's face) of the primitive named
/// `primitive` is a 2 cm edge of a board of generateBoardsScene: the primitive is named
/// "<kind> board <n>" and the face is +x, -x, +z or -z.
bool isBoardEdgeFace(const std::string& primitive, const std::string& face);

}  // namespace floodplane::synth
