// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The structured-light scanner's projector: which surface points it lights. A point seen by
// the camera is lit when it lies inside the projector's field, the surface there faces the
// projector, and nothing lies between the projector and the point; otherwise it returns
// nothing (outside the field, or in the projector's shadow).

#include <Eigen/Geometry>

#include "ray_caster.h"
#include "synth/scanner_model.h"
#include "synth/scene.h"

namespace floodplane::synth {

struct Illumination {
  bool lit = false;
  /// Cosine of the angle between the surface normal and the direction to the projector
  /// (positive when the surface faces the projector).
  double cosine = 0.0;
  /// Whether the point lies inside the projector's field: unlit points inside it are in its
  /// shadow (the surface turned away, or something in between).
  bool in_field = false;
};

class ProjectorView {
 public:
  /// The projector sits params.baseline metres along the camera's x axis, turned about the
  /// camera's y axis to aim at the point params.convergence_distance ahead of the camera, with
  /// the field params.projector_half_width / _half_height (tangents) around that aim.
  /// Throws SceneError if the projector is inside a solid.
  ProjectorView(const Scene& scene, const ScannerParams& params);

  /// How the projector lights the surface point `point` (camera frame) with surface normal
  /// `normal` (unit, turned towards the camera).
  Illumination illuminate(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) const;

 private:
  // Whether the direction `to_point` (camera axes, from the projector) is inside its field.
  bool inField(const Eigen::Vector3d& to_point) const;

  Eigen::Vector3d position_;
  Eigen::Matrix3d projector_from_camera_;  // turns camera axes into the projector's aimed axes
  double half_width_;
  double half_height_;
  RayCaster caster_;  // the scene from the projector's position, in camera axes
};

}  // namespace floodplane::synth
