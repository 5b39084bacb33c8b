// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "models/plane_sums.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace floodplane {
namespace {
constexpr double kLineEigenvalueRatio = 1e-6;
}  // namespace

PlaneFit PlaneSums::fit() const {
  PlaneFit plane;
  if (count < 3.0) return plane;
  plane.centroid = centroid();
  const double inv = 1.0 / count;
  const Eigen::Vector3d& c = plane.centroid;
  Eigen::Matrix3d& cov = plane.covariance;
  cov(0, 0) = sxx * inv - c.x() * c.x();
  cov(0, 1) = sxy * inv - c.x() * c.y();
  cov(0, 2) = sxz * inv - c.x() * c.z();
  cov(1, 1) = syy * inv - c.y() * c.y();
  cov(1, 2) = syz * inv - c.y() * c.z();
  cov(2, 2) = szz * inv - c.z() * c.z();
  cov(1, 0) = cov(0, 1);
  cov(2, 0) = cov(0, 2);
  cov(2, 1) = cov(1, 2);

  // The closed-form 3x3 solver: ~20x faster than the iterative one, and the smallest
  // eigenvalue of a plane's scatter is well separated from the other two.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(cov);
  // Ascending. The true eigenvalues of a scatter matrix are >= 0; the closed-form solver
  // returns round-off of either sign (-1e-15 for exactly planar points), and a negative
  // one would make every sqrt of it downstream NaN, which silently fails comparisons.
  const Eigen::Vector3d eigenvalues = solver.eigenvalues().cwiseMax(0.0);
  const double trace = eigenvalues.sum();
  // A point or a line: the middle eigenvalue is round-off next to the largest. The test must
  // be relative: for collinear points computeDirect gives +-1.4e-9 where the largest is 0.5
  // (its accuracy on a repeated eigenvalue is about sqrt(machine epsilon)), which `> 0`
  // accepted. A patch of a real surface has a ratio of its width to length squared, 1e-2 or
  // more; a one-pixel row of a plane is, correctly, a line.
  if (!(trace > 0.0) || !(eigenvalues(1) > kLineEigenvalueRatio * eigenvalues(2))) return plane;
  plane.normal = solver.eigenvectors().col(0).normalized();
  if (plane.normal.dot(c) > 0.0) plane.normal = -plane.normal;  // face the sensor at 0
  plane.offset = -plane.normal.dot(c);
  plane.eigenvalues = eigenvalues;
  plane.mean_squared_error = std::max(eigenvalues(0), 0.0);
  plane.curvature = plane.mean_squared_error / trace;
  plane.valid = plane.normal.allFinite() && std::isfinite(plane.offset);
  return plane;
}

}  // namespace floodplane
