// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What each ground-truth plane of a rendered scene is (floor, wall, table top, ...), derived
// from the scene's exact geometry and its up direction, for the tests of describePlanes. No
// names are read and nothing is said per scene: the rules are those a person would apply to
// the scene file, on the exact planes, with no tolerance but rounding.

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "floodplane/plane_classes.h"
#include "synth/rendered_frame.h"

namespace floodplane::test {

/// One ground-truth plane's expected class, or none where the rules leave it open.
struct ExpectedClass {
  std::optional<PlaneClass> plane_class;
  double from_horizontal = 0.0;  ///< its exact angle from horizontal [rad]
  double from_vertical = 0.0;    ///< and from vertical [rad]
};

/// A ground-truth plane's level: the height along `camera_up` (unit, in the camera's frame)
/// of its point nearest the camera, above the camera [m].
inline double levelOf(const synth::GroundTruthPlane& plane, const Eigen::Vector3d& camera_up) {
  return (-plane.d * plane.normal).dot(camera_up);
}

/// Whether a ground-truth plane is exactly horizontal and faces up (its normal faces the
/// camera, so the camera is above it). "Exactly": within a microradian, the rounding of the
/// scene's rotations.
inline bool facesUpExactly(const synth::GroundTruthPlane& plane, const Eigen::Vector3d& camera_up) {
  return plane.normal.dot(camera_up) > 0.0 && plane.normal.cross(camera_up).norm() < 1e-6;
}

/// The level of the scene's floor: the lowest exactly horizontal up-facing plane that faces
/// the camera (seen or not); infinity when there is none.
inline double groundLevel(const synth::RenderedFrame& frame, const Eigen::Vector3d& camera_up) {
  double ground = std::numeric_limits<double>::infinity();
  for (const synth::GroundTruthPlane& plane : frame.planes) {
    if (plane.faces_camera && facesUpExactly(plane, camera_up)) ground = std::min(ground, levelOf(plane, camera_up));
  }
  return ground;
}

/// The expected class of every ground-truth plane of `frame` (indexed by id - 1), the world's
/// up direction seen from the camera as `camera_up` (unit):
///  - exactly horizontal, facing up, at the floor's level (groundLevel): floor; higher (or
///    lower): a horizontal surface;
///  - exactly vertical: wall;
///  - tilted from both horizontal and vertical by more than the options' tolerance plus
///    `margin`: other;
///  - left open: planes facing down (a ceiling or the underside of something: describePlanes
///    tells them by size, which the exact geometry of a partly seen face does not give), and
///    planes tilted by less than the tolerance plus `margin` but not exactly level or upright
///    (the fit's error may take them either way).
inline std::vector<ExpectedClass> expectedClasses(const synth::RenderedFrame& frame, const Eigen::Vector3d& camera_up,
                                                  const PlaneClassOptions& options, double margin) {
  const double ground = groundLevel(frame, camera_up);
  std::vector<ExpectedClass> expected(frame.planes.size());
  for (std::size_t i = 0; i < frame.planes.size(); ++i) {
    const synth::GroundTruthPlane& plane = frame.planes[i];
    ExpectedClass& e = expected[i];
    e.from_horizontal = std::atan2(plane.normal.cross(camera_up).norm(), std::abs(plane.normal.dot(camera_up)));
    e.from_vertical = M_PI / 2 - e.from_horizontal;
    if (facesUpExactly(plane, camera_up)) {
      e.plane_class = levelOf(plane, camera_up) < ground + 1e-6 ? PlaneClass::kFloor : PlaneClass::kHorizontalSurface;
    } else if (e.from_vertical < 1e-6) {
      e.plane_class = PlaneClass::kWall;
    } else if (e.from_horizontal > options.horizontal_tolerance_rad + margin &&
               e.from_vertical > options.vertical_tolerance_rad + margin) {
      e.plane_class = PlaneClass::kOther;
    }
  }
  return expected;
}

}  // namespace floodplane::test
