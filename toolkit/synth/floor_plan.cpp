// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/floor_plan.h"

#include <algorithm>
#include <cmath>

namespace floodplane::synth {
namespace {

Eigen::Vector2d axisOf(double yaw, int which) {
  return which == 0 ? Eigen::Vector2d(std::cos(yaw), std::sin(yaw)) : Eigen::Vector2d(-std::sin(yaw), std::cos(yaw));
}

// Half the length of the footprint's shadow on the unit direction `axis`.
double projectedRadius(const Footprint& footprint, const Eigen::Vector2d& axis) {
  return footprint.half_size.x() * std::abs(axisOf(footprint.yaw, 0).dot(axis)) +
         footprint.half_size.y() * std::abs(axisOf(footprint.yaw, 1).dot(axis));
}

}  // namespace

bool footprintsOverlap(const Footprint& a, const Footprint& b, double gap) {
  // Two convex shapes are apart exactly when some edge normal separates them; for rectangles
  // the four axes suffice. Along a separating axis they are `separation` apart.
  const Eigen::Vector2d offset = b.center - a.center;
  for (const Footprint* owner : {&a, &b}) {
    for (int which = 0; which < 2; ++which) {
      const Eigen::Vector2d axis = axisOf(owner->yaw, which);
      const double separation = std::abs(offset.dot(axis)) - projectedRadius(a, axis) - projectedRadius(b, axis);
      if (separation >= gap) {
        return false;
      }
    }
  }
  return true;
}

std::vector<Eigen::Vector2d> footprintCorners(const Footprint& footprint) {
  const Eigen::Vector2d x = footprint.half_size.x() * axisOf(footprint.yaw, 0);
  const Eigen::Vector2d y = footprint.half_size.y() * axisOf(footprint.yaw, 1);
  return {footprint.center - x - y, footprint.center + x - y, footprint.center + x + y, footprint.center - x + y};
}

bool FloorPlan::fits(const Footprint& footprint, double gap, double margin) const {
  for (const Eigen::Vector2d& corner : footprintCorners(footprint)) {
    if ((corner.array() < low_.array() + margin).any() || (corner.array() > high_.array() - margin).any()) {
      return false;
    }
  }
  return std::none_of(placed_.begin(), placed_.end(),
                      [&](const Footprint& other) { return footprintsOverlap(footprint, other, gap); });
}

}  // namespace floodplane::synth
