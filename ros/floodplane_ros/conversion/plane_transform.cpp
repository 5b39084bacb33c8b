// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "plane_transform.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

namespace floodplane::conversion {

PlaneDescription transformPlane(const PlaneDescription& plane, const RigidTransform& transform) {
  for (const double value : transform.translation) {
    if (!std::isfinite(value)) throw std::invalid_argument("transformPlane: the translation is not finite");
  }
  for (const double value : transform.rotation) {
    if (!std::isfinite(value)) throw std::invalid_argument("transformPlane: the rotation is not finite");
  }
  Eigen::Quaterniond rotation(transform.rotation[3], transform.rotation[0], transform.rotation[1],
                              transform.rotation[2]);
  if (rotation.norm() < 1e-9) throw std::invalid_argument("transformPlane: the rotation quaternion is zero");
  rotation.normalize();
  const Eigen::Vector3d translation(transform.translation[0], transform.translation[1], transform.translation[2]);

  const Eigen::Vector3d normal =
      rotation * Eigen::Vector3d(plane.coefficients[0], plane.coefficients[1], plane.coefficients[2]);
  const Eigen::Vector3d centroid =
      rotation * Eigen::Vector3d(plane.centroid[0], plane.centroid[1], plane.centroid[2]) + translation;
  PlaneDescription moved = plane;
  moved.coefficients = {normal.x(), normal.y(), normal.z(), plane.coefficients[3] - normal.dot(translation)};
  moved.centroid = {centroid.x(), centroid.y(), centroid.z()};
  return moved;
}

}  // namespace floodplane::conversion
