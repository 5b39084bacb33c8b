#include "floodplane/plane_sums.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace floodplane {

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
  const Eigen::Vector3d eigenvalues = solver.eigenvalues();  // ascending
  const double trace = eigenvalues.sum();
  if (!(trace > 0.0) || !(eigenvalues(1) > 0.0)) return plane;  // a point or a line
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
