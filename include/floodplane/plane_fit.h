// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

/// \file
/// floodplane::PlaneFit, a least-squares plane and the spread of its points.

namespace floodplane {

/// A least-squares plane n . P + d = 0 through a set of points (the segmenter's frame: the
/// sensor at the origin).
struct PlaneFit {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();     ///< mean of the points [m]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();      ///< unit, towards the sensor origin
  double offset = 0.0;                                    ///< d
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();   ///< population covariance (1/N)
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();  ///< of the covariance, ascending
  double mean_squared_error = 0.0;                        ///< smallest eigenvalue: mean squared distance to the plane
  double curvature = 0.0;                                 ///< lambda_0 / (lambda_0 + lambda_1 + lambda_2), as PCL
  bool valid = false;                                     ///< false with fewer than 3 points or a degenerate spread
};

}  // namespace floodplane
