// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The planes a node publishes, moved into another frame (~target_frame), without ROS types: a
// rigid transform as tf2 gives it (geometry_msgs/Transform: a translation and a rotation
// quaternion) applied to each plane's coefficients and centroid.

#include <array>

#include "plane_descriptions.h"

namespace floodplane::conversion {

/// p_target = R p_source + t: the pose of the source frame in the target frame, as tf2's
/// lookupTransform(target, source, ...) gives it.
struct RigidTransform {
  std::array<double, 3> translation{};         ///< t [m]
  std::array<double, 4> rotation{0, 0, 0, 1};  ///< R as a quaternion x y z w
};

/// `plane` in the target frame: its normal n' = R n, its offset d' = d - n' . t (so that
/// n' . p' + d' = n . p + d for every point: distances and the side the sensor is on are
/// kept), its centroid R c + t. The rotation is normalized first, as tf2 normalizes it.
/// Throws std::invalid_argument when a value is not finite or the rotation has no length.
PlaneDescription transformPlane(const PlaneDescription& plane, const RigidTransform& transform);

}  // namespace floodplane::conversion
