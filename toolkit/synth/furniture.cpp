// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/furniture.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "synth/blocks.h"

namespace floodplane::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;

double degrees(double value) { return value * kPi / 180.0; }

Box uprightBox(const Eigen::Vector3d& center, const Eigen::Vector3d& size) {
  return Box{center, size, Eigen::Matrix3d::Identity()};
}

// A box turned by `yaw` about the vertical.
Box turnedBox(const Eigen::Vector3d& center, const Eigen::Vector3d& size, double yaw) {
  return Box{center, size, Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix()};
}

// A vertical rectangle in the plane y = `y`, spanning x in [x0, x1] and z in [z0, z1].
Rectangle rectangleAcross(double y, double x0, double x1, double z0, double z1) {
  return Rectangle{Eigen::Vector3d((x0 + x1) / 2, y, (z0 + z1) / 2), Eigen::Vector3d(x1 - x0, 0, 0),
                   Eigen::Vector3d(0, 0, z1 - z0)};
}

// A horizontal rectangle at height z spanning x in [x0, x1] and y in [y0, y1].
Rectangle rectangleLevel(double z, double x0, double x1, double y0, double y1) {
  return Rectangle{Eigen::Vector3d((x0 + x1) / 2, (y0 + y1) / 2, z), Eigen::Vector3d(x1 - x0, 0, 0),
                   Eigen::Vector3d(0, y1 - y0, 0)};
}

}  // namespace

Assembly makeTable(double height, RandomSource& random) {
  const double length = random.uniform(0.8, 1.8);
  const double width = random.uniform(0.5, std::min(1.0, length));
  const double thickness = random.uniform(0.02, 0.05);
  const double leg = random.uniform(0.04, 0.08);
  const double inset = random.uniform(0.02, 0.1);
  Assembly table;
  table.add("top", uprightBox({0, 0, height - thickness / 2}, {length, width, thickness}));
  const double leg_height = height - thickness;
  int number = 1;
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      const Eigen::Vector3d center(sx * (length / 2 - inset - leg / 2), sy * (width / 2 - inset - leg / 2),
                                   leg_height / 2);
      table.add("leg " + std::to_string(number++), uprightBox(center, {leg, leg, leg_height}));
    }
  }
  table.half_size = Eigen::Vector2d(length / 2, width / 2);
  table.height = height;
  table.supports.push_back({-table.half_size, table.half_size, height, 10.0});
  table.interest.emplace_back(0.0, 0.0, height);
  return table;
}

Assembly makeBoxStack(RandomSource& random) {
  Assembly stack;
  Eigen::Vector3d size;
  size.z() = random.uniform(0.2, 0.9);
  size.y() = random.uniform(0.3, 1.0);
  size.x() = random.uniform(0.3, 1.0);
  stack.add("", uprightBox({0, 0, size.z() / 2}, size));
  stack.half_size = size.head<2>() / 2.0;
  double base = size.z();
  double yaw = 0.0;
  const int extra = random.chance(0.5) ? random.integer(1, 2) : 0;
  for (int level = 1; level <= extra; ++level) {
    // A box no wider than 0.7 of the smaller side below, turned up to 25 degrees, stays on the
    // box below: its half diagonal is under half that side.
    const double room = std::min(size.x(), size.y());
    Eigen::Vector3d upper;
    upper.z() = random.uniform(0.15, 0.5);
    upper.y() = random.uniform(0.35, 0.7) * room;
    upper.x() = random.uniform(0.35, 0.7) * room;
    yaw += random.uniform(-degrees(25), degrees(25));
    stack.add("on top " + std::to_string(level), turnedBox({0, 0, base + upper.z() / 2}, upper, yaw));
    base += upper.z();
    size = upper;
  }
  stack.height = base;
  stack.interest.emplace_back(0.0, 0.0, base / 2);
  stack.interest.emplace_back(0.0, 0.0, base);
  return stack;
}

Assembly makeShelf(double max_height, RandomSource& random) {
  const double width = random.uniform(0.6, 1.6);
  const double depth = random.uniform(0.25, 0.45);
  const double height = random.uniform(0.8, std::max(0.85, std::min(2.0, max_height)));
  const double board = random.uniform(0.015, 0.03);
  const int shelves = random.integer(2, 5);
  Assembly shelf;
  const double back = -depth / 2;
  shelf.add("back", uprightBox({0, back + board / 2, height / 2}, {width - 2 * board, board, height}));
  shelf.add("left side", uprightBox({-(width - board) / 2, 0, height / 2}, {board, depth, height}));
  shelf.add("right side", uprightBox({(width - board) / 2, 0, height / 2}, {board, depth, height}));
  shelf.add("top", uprightBox({0, 0, height + board / 2}, {width, depth, board}));
  // Shelves from just above the floor, evenly spaced below the top.
  const double lowest = random.uniform(0.04, 0.12);
  const double spacing = (height - lowest) / shelves;
  const Eigen::Vector2d inner_low(-width / 2 + board, back + board);
  const Eigen::Vector2d inner_high(width / 2 - board, depth / 2);
  for (int k = 0; k < shelves; ++k) {
    const double z = lowest + k * spacing;
    shelf.add("shelf " + std::to_string(k + 1), uprightBox({0, (back + board + depth / 2) / 2, z + board / 2},
                                                           {width - 2 * board, depth / 2 - back - board, board}));
    shelf.supports.push_back({inner_low, inner_high, z + board, spacing - board});
  }
  shelf.half_size = Eigen::Vector2d(width / 2, depth / 2);
  shelf.height = height + board;
  shelf.interest.emplace_back(0.0, 0.0, height / 2);
  return shelf;
}

Assembly makeStairs(double max_height, RandomSource& random) {
  const double rise = random.uniform(0.15, 0.2);
  const int steps = std::min(random.integer(3, 8), std::max(2, static_cast<int>(max_height / rise)));
  const double run = random.uniform(0.25, 0.32);
  const double width = random.uniform(0.8, 1.4);
  const double landing = random.uniform(0.3, 0.8);
  const double depth = (steps - 1) * run + landing;
  const double front = depth / 2;
  Assembly stairs;
  std::vector<Eigen::Vector2d> side{{front, 0.0}};  // (y, z), from the front at the floor
  for (int i = 0; i < steps; ++i) {
    const double y = front - i * run;
    const double next_y = i + 1 < steps ? y - run : -front;
    stairs.add("riser " + std::to_string(i + 1), rectangleAcross(y, -width / 2, width / 2, i * rise, (i + 1) * rise));
    stairs.add("tread " + std::to_string(i + 1), rectangleLevel((i + 1) * rise, -width / 2, width / 2, next_y, y));
    side.emplace_back(y, (i + 1) * rise);
    side.emplace_back(next_y, (i + 1) * rise);
  }
  side.emplace_back(-front, 0.0);
  for (const double x : {-width / 2, width / 2}) {
    Polygon outline;
    for (const auto& point : side) outline.vertices.emplace_back(x, point.x(), point.y());
    stairs.add(x < 0 ? "left side" : "right side", outline);
  }
  stairs.half_size = Eigen::Vector2d(width / 2, depth / 2);
  stairs.height = steps * rise;
  // Three points (foot, middle, landing): a camera in a hall looks at the stairs more often
  // than at any one other object.
  stairs.interest.emplace_back(0.0, front - run, rise);
  stairs.interest.emplace_back(0.0, 0.0, stairs.height / 2);
  stairs.interest.emplace_back(0.0, -front + landing / 2, stairs.height);
  return stairs;
}

Assembly makeRamp(RandomSource& random) {
  const double length = random.uniform(1.0, 3.0);
  const double rise = length * std::tan(degrees(random.uniform(4, 15)));
  const double width = random.uniform(0.8, 1.5);
  const bool platform = random.chance(0.6);
  const double platform_depth = platform ? random.uniform(0.8, 2.0) : 0.0;
  const double platform_width = width + (random.chance(0.5) ? random.uniform(0.2, 0.8) : 0.0);
  const double total = length + platform_depth;
  const double start = -total / 2;
  Assembly ramp;
  ramp.add("", profilePrism({{start, 0}, {start + length, 0}, {start + length, rise}}, width));
  if (platform) {
    ramp.add("platform",
             uprightBox({0, start + length + platform_depth / 2, rise / 2}, {platform_width, platform_depth, rise}));
  }
  ramp.half_size = Eigen::Vector2d(std::max(width, platform ? platform_width : 0.0) / 2, total / 2);
  ramp.height = rise;
  ramp.interest.emplace_back(0.0, start + length / 2, rise / 2);
  return ramp;
}

Assembly makePlatform(RandomSource& random) {
  Eigen::Vector3d size;
  size.z() = random.uniform(0.1, 0.45);
  size.y() = random.uniform(0.8, 2.0);
  size.x() = random.uniform(1.0, 2.5);
  Assembly platform;
  platform.add("", uprightBox({0, 0, size.z() / 2}, size));
  platform.half_size = size.head<2>() / 2;
  platform.height = size.z();
  platform.supports.push_back({-platform.half_size, platform.half_size, size.z(), 10.0});
  platform.interest.emplace_back(0.0, 0.0, size.z());
  return platform;
}

Assembly makeWallBoard(double wall_height, RandomSource& random) {
  const double thickness = random.uniform(0.01, 0.03);
  const double width = random.uniform(0.3, 1.6);
  const double height = random.uniform(0.3, std::min(1.2, wall_height - 0.6));
  const double bottom = random.uniform(0.3, std::max(0.31, wall_height - height - 0.2));
  Assembly board;
  board.add("", uprightBox({0, 0, bottom + height / 2}, {width, thickness, height}));
  board.half_size = Eigen::Vector2d(width / 2, thickness / 2);
  board.height = bottom + height;
  board.interest.emplace_back(0.0, thickness / 2, bottom + height / 2);
  return board;
}

// The board's back face rests on the floor at distance L sin(lean) from the wall and on the
// wall at height L cos(lean); the board lies on the room's side of that line.
Assembly makeLeaningBoard(double wall_height, RandomSource& random) {
  const double thickness = random.uniform(0.01, 0.03);
  const double width = random.uniform(0.3, 1.2);
  const double length = random.uniform(0.8, std::min(2.2, wall_height - 0.2));
  const double lean = degrees(random.uniform(8, 25));
  const Eigen::Vector3d up_board(0, -std::sin(lean), std::cos(lean));  // along the board, upwards
  const Eigen::Vector3d out_board(0, std::cos(lean), std::sin(lean));  // out of its face, into the room
  const double depth = length * std::sin(lean) + thickness * std::cos(lean);
  const Eigen::Vector3d foot(0, -depth / 2 + length * std::sin(lean), 0);  // back edge on the floor
  Eigen::Matrix3d rotation;
  rotation << Eigen::Vector3d::UnitX(), out_board, up_board;
  Assembly board;
  board.add("", Box{foot + length / 2 * up_board + thickness / 2 * out_board, {width, thickness, length}, rotation});
  board.half_size = Eigen::Vector2d(width / 2, depth / 2);
  board.height = length * std::cos(lean) + thickness * std::sin(lean);
  board.interest.emplace_back(0.0, 0.0, board.height / 2);
  return board;
}

Assembly makeColumn(double height, RandomSource& random) {
  Eigen::Vector3d size;
  size.z() = height;
  size.y() = random.uniform(0.25, 0.6);
  size.x() = random.uniform(0.25, 0.6);
  Assembly column;
  column.add("", uprightBox({0, 0, height / 2}, size));
  column.half_size = size.head<2>() / 2;
  column.height = height;
  column.interest.emplace_back(0.0, 0.0, 1.2);
  return column;
}

Assembly makeCurvedObject(RandomSource& random) {
  Assembly object;
  const int kind = random.integer(0, 2);
  if (kind == 0) {
    const double radius = random.uniform(0.1, 0.35);
    const double height = random.uniform(0.3, 1.1);
    object.add("", Cylinder{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), radius, height});
    object.half_size = Eigen::Vector2d::Constant(radius);
    object.height = height;
  } else if (kind == 1) {
    const double radius = random.uniform(0.08, 0.3);
    const double length = random.uniform(0.4, 1.5);
    object.add("", Cylinder{Eigen::Vector3d(-length / 2, 0, radius), Eigen::Vector3d::UnitX(), radius, length});
    object.half_size = Eigen::Vector2d(length / 2, radius);
    object.height = 2 * radius;
  } else {
    const double radius = random.uniform(0.1, 0.4);
    object.add("", Sphere{Eigen::Vector3d(0, 0, radius), radius});
    object.half_size = Eigen::Vector2d::Constant(radius);
    object.height = 2 * radius;
  }
  object.interest.emplace_back(0.0, 0.0, object.height / 2);
  return object;
}

Assembly makeTableItem(double max_height, RandomSource& random) {
  for (int attempt = 0; attempt < 8; ++attempt) {
    Assembly item;
    const int kind = random.integer(0, 5);
    if (kind == 0) {
      Eigen::Vector3d size;
      size.z() = random.uniform(0.04, 0.3);
      size.y() = random.uniform(0.06, 0.35);
      size.x() = random.uniform(0.06, 0.35);
      item.add("", uprightBox({0, 0, size.z() / 2}, size));
      item.half_size = size.head<2>() / 2;
      item.height = size.z();
    } else if (kind == 1) {
      const double radius = random.uniform(0.03, 0.1);
      const double height = random.uniform(0.06, 0.3);
      item.add("", Cylinder{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), radius, height});
      item.half_size = Eigen::Vector2d::Constant(radius);
      item.height = height;
    } else if (kind == 2) {
      const double radius = random.uniform(0.04, 0.14);
      item.add("", Sphere{Eigen::Vector3d(0, 0, radius), radius});
      item.half_size = Eigen::Vector2d::Constant(radius);
      item.height = 2 * radius;
    } else {
      const double scale = random.uniform(2.0, 3.0);
      const BlockKind block_kind = random.pick(allBlockKinds());
      item = makeBlock(block_kind, scale, random);
    }
    item.interest = {Eigen::Vector3d(0.0, 0.0, item.height / 2)};
    if (item.height <= max_height) {
      return item;
    }
  }
  return {};  // nothing fits under a low shelf
}

}  // namespace floodplane::synth
