// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The furniture of generated rooms, each built in its own frame (see assembly.h), with its
// parameter ranges in metres. Objects that stand against a wall have their back on the plane
// y = -half_size.y(), facing +y.

#include "synth/assembly.h"
#include "synth/random_source.h"

namespace floodplane::synth {

/// A table: top 0.8-1.8 x 0.5-1.0 m, 2-5 cm thick, at `height`; four legs 4-8 cm square.
/// Its top is a support.
Assembly makeTable(double height, RandomSource& random);

/// A box 0.3-1.0 x 0.3-1.0 x 0.2-0.9 m, with up to two smaller boxes stacked on it, each
/// turned up to 25 degrees from the one below.
Assembly makeBoxStack(RandomSource& random);

/// Against a wall: a shelf unit 0.6-1.6 m wide, 0.25-0.45 m deep, 0.8-2.0 m tall (below
/// `max_height`), 1.5-3 cm boards: sides, back, top and 2-5 shelves, each a support.
Assembly makeShelf(double max_height, RandomSource& random);

/// Against a wall: a flight of 3-8 steps (rise 15-20 cm, run 25-32 cm, 0.8-1.4 m wide) rising
/// towards the wall to a landing 0.3-0.8 m deep that meets it, no higher than `max_height`.
/// Risers, treads and the two stepped sides are separate faces.
Assembly makeStairs(double max_height, RandomSource& random);

/// A ramp 1-3 m long rising at 4-15 degrees, 0.8-1.5 m wide (a wedge prism), up to a
/// platform 0.8-2 m deep as high as the ramp's top (with probability 0.6).
Assembly makeRamp(RandomSource& random);

/// A platform 1-2.5 x 0.8-2 m, 0.1-0.45 m high.
Assembly makePlatform(RandomSource& random);

/// Against a wall: a board 1-3 cm thick, 0.3-1.6 x 0.3-1.2 m, hung flat on the wall with its
/// lower edge 0.3 m or more above the floor, below `wall_height`.
Assembly makeWallBoard(double wall_height, RandomSource& random);

/// Against a wall: a board 1-3 cm thick, 0.3-1.2 m wide, 0.8-2.2 m long, leaning on the wall
/// at 8-25 degrees from the vertical with its lower edge on the floor.
Assembly makeLeaningBoard(double wall_height, RandomSource& random);

/// A column 0.25-0.6 m square from the floor to `height`.
Assembly makeColumn(double height, RandomSource& random);

/// Curved objects: a cylinder standing (radius 0.1-0.35 m, 0.3-1.1 m tall) or lying on its side
/// (radius 0.08-0.3 m, 0.4-1.5 m long), or a ball (radius 0.1-0.4 m).
Assembly makeCurvedObject(RandomSource& random);

/// A small object for a table or shelf no taller than `max_height`: a box, a can, a ball or a
/// polyhedral block at 2-3 times the scanner scale.
Assembly makeTableItem(double max_height, RandomSource& random);

}  // namespace floodplane::synth
