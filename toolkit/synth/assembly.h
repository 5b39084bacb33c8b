// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An object of a generated scene built in its own frame (z up, standing on z = 0, its
// footprint centred on the origin): its primitives, footprint, the surfaces other objects can
// stand on, and the points worth pointing a camera at. Objects are built, then placed.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "synth/scene.h"

namespace floodplane::synth {

/// A flat, upward-facing rectangle of an object where smaller objects can stand: a table top,
/// a shelf board.
struct SupportSurface {
  Eigen::Vector2d low = Eigen::Vector2d::Zero();  ///< corners of the usable area, object frame
  Eigen::Vector2d high = Eigen::Vector2d::Zero();
  double height = 0.0;      ///< z of the surface
  double clearance = 10.0;  ///< free height above it (under the next shelf board)
};

struct Assembly {
  std::vector<Primitive> parts;
  Eigen::Vector2d half_size = Eigen::Vector2d::Zero();  ///< footprint: [-half_size, half_size]
  double height = 0.0;                                  ///< top of the highest part
  std::vector<SupportSurface> supports;
  std::vector<Eigen::Vector3d> interest;  ///< points a camera may look at

  void add(const std::string& name, const Shape& shape) { parts.push_back({name, shape}); }

  /// Adds every part of `other` moved by `pose`, named "<prefix> <part name>" (or `prefix`
  /// alone for an unnamed part), with its points of interest; supports are not carried over.
  void merge(const Assembly& other, const Eigen::Isometry3d& pose, const std::string& prefix);
};

/// The pose of an object standing at (x, y, z) turned by `yaw` radians about the vertical.
Eigen::Isometry3d standingPose(double x, double y, double z, double yaw);

}  // namespace floodplane::synth
