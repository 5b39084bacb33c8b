// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "floodplane/object_segmentation.h"
#include "floodplane/segmentation.h"

namespace floodplane {

/// One supporting surface: a large plane with the smaller planes in its plane (its pieces).
struct SupportSurface {
  std::uint32_t label = 0;                            ///< the large plane's label (k for planes[k - 1])
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, towards the sensor
  double offset = 0.0;                                ///< n . P + d = 0
  /// The signed height of a point above the surface, positive on the sensor's side [m].
  double height(const Eigen::Vector3d& point) const { return normal.dot(point) + offset; }
};

/// The planes objects stand on.
struct Supports {
  std::vector<SupportSurface> surfaces;  ///< largest first
  /// Per label (index 0: no plane, false): the plane is a support or a piece of one.
  std::vector<bool> is_support;
};

/// The area a plane's inliers cover [m^2]: that of the rectangle with their spread along the
/// plane, 12 sqrt(lambda_1 lambda_2) from the fit's two larger covariance eigenvalues.
double coveredArea(const PlaneFit& fit);

/// The supports among `planes`: each valid plane at least options.min_support_area_m2 large,
/// and every smaller plane in the plane of one (options.support_piece_angle_rad,
/// support_piece_distance_m) as its piece.
Supports findSupports(const std::vector<SegmentedPlane>& planes, const ObjectOptions& options);

}  // namespace floodplane
