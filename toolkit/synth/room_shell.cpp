// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/room_shell.h"

#include <algorithm>
#include <string>

namespace floodplane::synth {
namespace {

// A point of wall `wall` at `offset` along it, `height` above the floor, `distance` in front
// of it (negative: behind it, inside an opening).
Eigen::Vector3d wallPoint(const Wall& wall, double offset, double height, double distance) {
  return wall.origin + offset * wall.along + distance * wall.inward + height * Eigen::Vector3d::UnitZ();
}

// A rectangle of an opening given by two of its edges from the corner `corner`.
Rectangle rectangleFrom(const Eigen::Vector3d& corner, const Eigen::Vector3d& edge_u, const Eigen::Vector3d& edge_v) {
  return Rectangle{corner + edge_u / 2 + edge_v / 2, edge_u, edge_v};
}

std::vector<Opening> sortedOpenings(std::vector<Opening> openings) {
  std::sort(openings.begin(), openings.end(), [](const Opening& a, const Opening& b) { return a.start < b.start; });
  return openings;
}

void addWall(const RoomShell& shell, int index, Assembly& room) {
  const Wall& wall = shell.walls[static_cast<std::size_t>(index)];
  const std::vector<Opening> openings = sortedOpenings(shell.openings[static_cast<std::size_t>(index)]);
  // The outline runs along the floor, dipping round the openings that reach the floor, then
  // back along the top; openings above the floor are holes.
  Polygon polygon;
  polygon.vertices.push_back(wallPoint(wall, 0, 0, 0));
  for (const Opening& opening : openings) {
    if (opening.bottom > 0.0) {
      polygon.holes.push_back(
          {wallPoint(wall, opening.start, opening.bottom, 0), wallPoint(wall, opening.end, opening.bottom, 0),
           wallPoint(wall, opening.end, opening.top, 0), wallPoint(wall, opening.start, opening.top, 0)});
      continue;
    }
    polygon.vertices.push_back(wallPoint(wall, opening.start, 0, 0));
    polygon.vertices.push_back(wallPoint(wall, opening.start, opening.top, 0));
    polygon.vertices.push_back(wallPoint(wall, opening.end, opening.top, 0));
    polygon.vertices.push_back(wallPoint(wall, opening.end, 0, 0));
  }
  polygon.vertices.push_back(wallPoint(wall, wall.length, 0, 0));
  polygon.vertices.push_back(wallPoint(wall, wall.length, shell.height, 0));
  polygon.vertices.push_back(wallPoint(wall, 0, shell.height, 0));
  const std::string name = "wall " + std::to_string(index + 1);
  room.add(name, polygon);

  int number = 0;
  for (const Opening& opening : openings) {
    const std::string what = name + (opening.door ? " door " : " recess ") + std::to_string(++number);
    const Eigen::Vector3d back = -opening.depth * wall.inward;
    const Eigen::Vector3d across = (opening.end - opening.start) * wall.along;
    const Eigen::Vector3d up = (opening.top - opening.bottom) * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d low_start = wallPoint(wall, opening.start, opening.bottom, 0);
    const Eigen::Vector3d low_end = wallPoint(wall, opening.end, opening.bottom, 0);
    const Eigen::Vector3d high_start = wallPoint(wall, opening.start, opening.top, 0);
    room.add(what + (opening.door ? " leaf" : " back"), rectangleFrom(low_start + back, across, up));
    room.add(what + " left side", rectangleFrom(low_start, back, up));
    room.add(what + " right side", rectangleFrom(low_end, back, up));
    room.add(what + " top", rectangleFrom(high_start, across, back));
    if (opening.bottom > 0.0) {
      room.add(what + " sill", rectangleFrom(low_start, across, back));
    }
  }
}

// The floor: the room's rectangle, reaching into every opening that starts at the floor.
void addFloor(const RoomShell& shell, Assembly& room) {
  Polygon floor;
  for (std::size_t index = 0; index < shell.walls.size(); ++index) {
    const Wall& wall = shell.walls[index];
    floor.vertices.push_back(wallPoint(wall, 0, 0, 0));
    for (const Opening& opening : sortedOpenings(shell.openings[index])) {
      if (opening.bottom > 0.0) {
        continue;
      }
      floor.vertices.push_back(wallPoint(wall, opening.start, 0, 0));
      floor.vertices.push_back(wallPoint(wall, opening.start, 0, -opening.depth));
      floor.vertices.push_back(wallPoint(wall, opening.end, 0, -opening.depth));
      floor.vertices.push_back(wallPoint(wall, opening.end, 0, 0));
    }
  }
  room.add("floor", floor);
}

}  // namespace

Eigen::Isometry3d Wall::poseAt(double offset, double distance) const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() << along, inward, Eigen::Vector3d::UnitZ();
  pose.translation() = wallPoint(*this, offset, 0, distance);
  return pose;
}

RoomShell makeRoomShell(double width, double depth, double height, bool ceiling) {
  RoomShell shell;
  shell.width = width;
  shell.depth = depth;
  shell.height = height;
  shell.ceiling = ceiling;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d y = Eigen::Vector3d::UnitY();
  shell.walls = {Wall{Eigen::Vector3d(0, 0, 0), x, y, width}, Wall{Eigen::Vector3d(width, 0, 0), y, -x, depth},
                 Wall{Eigen::Vector3d(width, depth, 0), -x, -y, width},
                 Wall{Eigen::Vector3d(0, depth, 0), -y, x, depth}};
  return shell;
}

void addShellSurfaces(const RoomShell& shell, Assembly& room) {
  addFloor(shell, room);
  for (int index = 0; index < 4; ++index) {
    addWall(shell, index, room);
  }
  if (shell.ceiling) {
    room.add("ceiling", Rectangle{Eigen::Vector3d(shell.width / 2, shell.depth / 2, shell.height),
                                  Eigen::Vector3d(shell.width, 0, 0), Eigen::Vector3d(0, shell.depth, 0)});
  }
}

}  // namespace floodplane::synth
