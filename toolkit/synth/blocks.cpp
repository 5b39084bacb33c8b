// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/blocks.h"

#include <algorithm>
#include <cmath>

namespace floodplane::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kCentimetre = 0.01;

double degrees(double value) { return value * kPi / 180.0; }

// The (y, z) profile's extent: the block's footprint along y and its height.
void fitProfile(Assembly& block, const std::vector<Eigen::Vector2d>& profile, double width) {
  double y_extent = 0.0;
  double top = 0.0;
  for (const auto& point : profile) {
    y_extent = std::max(y_extent, std::abs(point.x()));
    top = std::max(top, point.y());
  }
  block.half_size = Eigen::Vector2d(width / 2.0, y_extent);
  block.height = top;
  block.interest.emplace_back(0.0, 0.0, top / 2.0);
}

Assembly profileBlock(const std::vector<Eigen::Vector2d>& profile, double width) {
  Assembly block;
  block.add("", profilePrism(profile, width));
  fitProfile(block, profile, width);
  return block;
}

Assembly boxBlock(double s, RandomSource& random) {
  Eigen::Vector3d size;
  size.z() = random.uniform(2, 10) * s;
  size.y() = random.uniform(3, 10) * s;
  size.x() = random.uniform(3, 10) * s;
  Assembly block;
  block.add("",
            Box{Eigen::Vector3d(0, 0, size.z() / 2.0) * kCentimetre, size * kCentimetre, Eigen::Matrix3d::Identity()});
  block.half_size = size.head<2>() * kCentimetre / 2.0;
  block.height = size.z() * kCentimetre;
  block.interest.emplace_back(0.0, 0.0, block.height / 2.0);
  // A smaller block fits on top.
  block.supports.push_back({-block.half_size, block.half_size, block.height, 10.0});
  return block;
}

// A slope rising at 10-30 degrees along y from a low front (at least 5 mm tall) to the back.
Assembly wedgeBlock(double s, RandomSource& random) {
  const double length = random.uniform(5, 12) * s * kCentimetre;
  const double front = random.uniform(0.5, 3) * s * kCentimetre;
  const double back = front + length * std::tan(degrees(random.uniform(10, 30)));
  const double width = random.uniform(3, 8) * s * kCentimetre;
  return profileBlock({{-length / 2, 0}, {length / 2, 0}, {length / 2, back}, {-length / 2, front}}, width);
}

// Two roof faces, each 10-30 degrees from the horizontal, meeting at a ridge off the middle.
Assembly roofBlock(double s, RandomSource& random) {
  const double length = random.uniform(5, 12) * s * kCentimetre;
  const double ridge = random.uniform(-0.25, 0.25) * length;
  const double ridge_height = random.uniform(3, 9) * s * kCentimetre;
  const double right = ridge_height - (length / 2 - ridge) * std::tan(degrees(random.uniform(10, 30)));
  const double left = ridge_height - (length / 2 + ridge) * std::tan(degrees(random.uniform(10, 30)));
  const double lowest_wall = 0.8 * s * kCentimetre;
  const double width = random.uniform(3, 8) * s * kCentimetre;
  return profileBlock({{-length / 2, 0},
                       {length / 2, 0},
                       {length / 2, std::max(right, lowest_wall)},
                       {ridge, ridge_height},
                       {-length / 2, std::max(left, lowest_wall)}},
                      width);
}

// A top of 3-5 faces 2-5 cm wide, each turned the same 10-30 degrees from the last: a faceted
// vault, symmetric in its slopes.
Assembly archBlock(double s, RandomSource& random) {
  const int faces = random.integer(3, 5);
  const double turn = degrees(random.uniform(10, 30));
  const double wall = random.uniform(1.5, 4) * s * kCentimetre;
  std::vector<Eigen::Vector2d> top{{0.0, wall}};
  for (int face = 0; face < faces; ++face) {
    const double slope = (0.5 * (faces - 1) - face) * turn;
    const double width = random.uniform(2, 5) * s * kCentimetre;
    top.push_back(top.back() + width * Eigen::Vector2d(std::cos(slope), std::sin(slope)));
  }
  // Faces of unequal width end the arch at another height; keep its last wall at least 8 mm.
  const double lowest = 0.8 * s * kCentimetre;
  if (top.back().y() < lowest) {
    top.back().y() = lowest;
  }
  const double half = top.back().x() / 2.0;
  std::vector<Eigen::Vector2d> profile{{-half, 0.0}, {half, 0.0}};
  for (auto it = top.rbegin(); it != top.rend(); ++it) {
    profile.emplace_back(it->x() - half, it->y());
  }
  return profileBlock(profile, random.uniform(3, 8) * s * kCentimetre);
}

// One top edge cut off by a face 2-5 cm wide at 10-30 degrees from the top.
Assembly chamferedBlock(double s, RandomSource& random) {
  const double length = random.uniform(5, 12) * s * kCentimetre;
  const double height = random.uniform(3, 9) * s * kCentimetre;
  const double cut_width = std::min(random.uniform(2, 5) * s * kCentimetre, 0.7 * length);
  const double cut_height = std::min(cut_width * std::tan(degrees(random.uniform(10, 30))), 0.6 * height);
  return profileBlock({{-length / 2, 0},
                       {length / 2, 0},
                       {length / 2, height - cut_height},
                       {length / 2 - cut_width, height},
                       {-length / 2, height}},
                      random.uniform(3, 8) * s * kCentimetre);
}

// A regular polygon with `sides` sides, one of them flat at the bottom (its lowest edge on
// y = 0 when `flat_bottom`), or centred on the origin.
std::vector<Eigen::Vector2d> regularPolygon(int sides, double circumradius, bool flat_bottom) {
  std::vector<Eigen::Vector2d> outline;
  const double step = 2.0 * kPi / sides;
  const double lift = flat_bottom ? circumradius * std::cos(kPi / sides) : 0.0;
  for (int k = 0; k < sides; ++k) {
    const double angle = -kPi / 2.0 + step / 2.0 + k * step;
    outline.emplace_back(circumradius * std::cos(angle), circumradius * std::sin(angle) + lift);
  }
  return outline;
}

// Sides 2-5 cm wide, the whole no wider than 16 cm (at scale 1).
double prismCircumradius(int sides, double s, RandomSource& random) {
  const double side = random.uniform(2, 5) * s * kCentimetre;
  return std::min(side / (2.0 * std::sin(kPi / sides)), 8.0 * s * kCentimetre);
}

Assembly standingPrismBlock(double s, RandomSource& random) {
  const int sides = random.pick(std::vector<int>{6, 8, 10, 12, 14, 16, 18});
  const double radius = prismCircumradius(sides, s, random);
  const double height = random.uniform(2, 10) * s * kCentimetre;
  Assembly block;
  block.add("", uprightPrism(regularPolygon(sides, radius, false), height));
  block.half_size = Eigen::Vector2d::Constant(radius);
  block.height = height;
  block.interest.emplace_back(0.0, 0.0, height / 2.0);
  return block;
}

Assembly lyingPrismBlock(double s, RandomSource& random) {
  const int sides = random.pick(std::vector<int>{6, 8, 10, 12, 14, 16});
  const double radius = prismCircumradius(sides, s, random);
  return profileBlock(regularPolygon(sides, radius, true), random.uniform(4, 12) * s * kCentimetre);
}

Assembly standingCylinderBlock(double s, RandomSource& random) {
  const double radius = random.uniform(1.5, 4) * s * kCentimetre;
  const double height = random.uniform(3, 10) * s * kCentimetre;
  Assembly block;
  block.add("", Cylinder{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), radius, height});
  block.half_size = Eigen::Vector2d::Constant(radius);
  block.height = height;
  block.interest.emplace_back(0.0, 0.0, height / 2.0);
  return block;
}

Assembly lyingCylinderBlock(double s, RandomSource& random) {
  const double radius = random.uniform(1.5, 3) * s * kCentimetre;
  const double length = random.uniform(4, 12) * s * kCentimetre;
  Assembly block;
  block.add("", Cylinder{Eigen::Vector3d(-length / 2, 0, radius), Eigen::Vector3d::UnitX(), radius, length});
  block.half_size = Eigen::Vector2d(length / 2, radius);
  block.height = 2.0 * radius;
  block.interest.emplace_back(0.0, 0.0, radius);
  return block;
}

}  // namespace

const std::vector<BlockKind>& allBlockKinds() {
  static const std::vector<BlockKind> kinds{
      BlockKind::box,           BlockKind::wedge,          BlockKind::roof,        BlockKind::arch,
      BlockKind::chamfered_box, BlockKind::standing_prism, BlockKind::lying_prism, BlockKind::standing_cylinder,
      BlockKind::lying_cylinder};
  return kinds;
}

Assembly makeBlock(BlockKind kind, double scale, RandomSource& random) {
  switch (kind) {
    case BlockKind::box:
      return boxBlock(scale, random);
    case BlockKind::wedge:
      return wedgeBlock(scale, random);
    case BlockKind::roof:
      return roofBlock(scale, random);
    case BlockKind::arch:
      return archBlock(scale, random);
    case BlockKind::chamfered_box:
      return chamferedBlock(scale, random);
    case BlockKind::standing_prism:
      return standingPrismBlock(scale, random);
    case BlockKind::lying_prism:
      return lyingPrismBlock(scale, random);
    case BlockKind::standing_cylinder:
      return standingCylinderBlock(scale, random);
    case BlockKind::lying_cylinder:
      return lyingCylinderBlock(scale, random);
  }
  return boxBlock(scale, random);
}

Prism profilePrism(const std::vector<Eigen::Vector2d>& profile, double width) {
  Prism prism;
  for (const auto& point : profile) {
    prism.base.emplace_back(-width / 2.0, point.x(), point.y());
  }
  prism.extrusion = Eigen::Vector3d(width, 0.0, 0.0);
  return prism;
}

Prism uprightPrism(const std::vector<Eigen::Vector2d>& outline, double height) {
  Prism prism;
  for (const auto& point : outline) {
    prism.base.emplace_back(point.x(), point.y(), 0.0);
  }
  prism.extrusion = Eigen::Vector3d(0.0, 0.0, height);
  return prism;
}

}  // namespace floodplane::synth
