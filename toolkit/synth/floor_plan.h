// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Keeping generated objects apart: the footprints of objects on a flat support (the floor, a
// table top) as rectangles turned about the vertical, tested for overlap by the separating
// axis theorem.

#include <Eigen/Core>
#include <vector>

namespace floodplane::synth {

/// A rectangle on the support plane: centre, half extents along its own axes, and its turn
/// (radians, counter-clockwise) from the support's x axis.
struct Footprint {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  Eigen::Vector2d half_size = Eigen::Vector2d::Zero();
  double yaw = 0.0;
};

/// Whether the two footprints come closer than `gap` (metres; 0: whether they overlap).
bool footprintsOverlap(const Footprint& a, const Footprint& b, double gap);

/// The footprint's four corners, counter-clockwise.
std::vector<Eigen::Vector2d> footprintCorners(const Footprint& footprint);

class FloorPlan {
 public:
  /// A support covering [low, high] (both corners of an axis-aligned rectangle).
  FloorPlan(const Eigen::Vector2d& low, const Eigen::Vector2d& high) : low_(low), high_(high) {}

  /// Whether `footprint` lies inside the support, at least `margin` from its border (a negative
  /// margin lets it reach over), and at least `gap` from every footprint placed so far.
  bool fits(const Footprint& footprint, double gap, double margin) const;

  void add(const Footprint& footprint) { placed_.push_back(footprint); }

  const Eigen::Vector2d& low() const { return low_; }
  const Eigen::Vector2d& high() const { return high_; }

 private:
  Eigen::Vector2d low_;
  Eigen::Vector2d high_;
  std::vector<Footprint> placed_;
};

}  // namespace floodplane::synth
