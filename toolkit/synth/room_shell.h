// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The shell of a generated room: a floor of width x depth (x from 0 to width, y from 0 to
// depth, z up), four walls of the room's height, sometimes a ceiling, and openings in the
// walls: doors (a door leaf set back in the wall, its jambs and head) and recesses (a niche
// with back, sides, top and, above the floor, a sill). A wall with openings is one polygon with
// holes, and a floor running into door and floor-level recess openings is one polygon: one face,
// one ground-truth plane.

#include <array>
#include <vector>

#include "synth/assembly.h"

namespace floodplane::synth {

/// A wall seen from inside the room: it runs from `origin` (on the floor) along `along` for
/// `length`; `inward` points into the room. Walls go round the room counter-clockwise seen from
/// above: 0 at y = 0, 1 at x = width, 2 at y = depth, 3 at x = 0.
struct Wall {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d along = Eigen::Vector3d::UnitX();
  Eigen::Vector3d inward = Eigen::Vector3d::UnitY();
  double length = 0.0;

  /// The pose of an object against this wall at `offset` along it, its origin `distance` from
  /// the wall, its +y pointing into the room (furniture.h's convention).
  Eigen::Isometry3d poseAt(double offset, double distance) const;
};

/// An opening in a wall from `start` to `end` along it and from `bottom` to `top` above the
/// floor, `depth` deep behind the wall. A door has a leaf at the back; a recess a back face.
struct Opening {
  double start = 0.0;
  double end = 0.0;
  double bottom = 0.0;
  double top = 0.0;
  double depth = 0.0;
  bool door = false;
};

struct RoomShell {
  double width = 0.0;
  double depth = 0.0;
  double height = 0.0;
  bool ceiling = false;
  std::array<Wall, 4> walls;
  std::array<std::vector<Opening>, 4> openings;
};

/// A shell without openings.
RoomShell makeRoomShell(double width, double depth, double height, bool ceiling);

/// Adds the shell's surfaces (floor, walls, opening faces, ceiling) to `room`.
void addShellSurfaces(const RoomShell& shell, Assembly& room);

}  // namespace floodplane::synth
