#pragma once
// Random scenes with ground truth, one pair per seed: a room for the depth camera (sensor
// models none and kinect) and a table of polyhedral blocks for the structured-light scanner.
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

}  // namespace floodplane::synth
