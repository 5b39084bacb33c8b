#pragma once

#include <Eigen/Core>

#include "floodplane/point_grid.h"

namespace floodplane {

/// A least-squares plane n . P + d = 0 through a set of points.
struct PlaneFit {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, towards the sensor origin
  double offset = 0.0;                                ///< d
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< population covariance (1/N)
  double mean_squared_error = 0.0;  ///< smallest eigenvalue: mean squared distance to the plane
  double curvature = 0.0;           ///< lambda_0 / (lambda_0 + lambda_1 + lambda_2), as PCL
  bool valid = false;               ///< false with fewer than 3 points or a degenerate spread
};

/// Running sums of a point set (count, sum of P, sum of P P^T) in double precision. Adding,
/// removing and merging are O(1), and so is the plane fit: the paper's merge step needs
/// inlier-weighted centroids and normals (Sec. III-D); the sums give the exact least-squares
/// plane of the union instead of a weighted average of two normals (PEAC, CAPE).
struct PlaneSums {
  double count = 0.0;
  double sx = 0.0, sy = 0.0, sz = 0.0;
  double sxx = 0.0, sxy = 0.0, sxz = 0.0, syy = 0.0, syz = 0.0, szz = 0.0;

  void add(const Vec3& p) {
    const double x = p.x, y = p.y, z = p.z;
    count += 1.0;
    sx += x; sy += y; sz += z;
    sxx += x * x; sxy += x * y; sxz += x * z;
    syy += y * y; syz += y * z; szz += z * z;
  }
  void remove(const Vec3& p) {
    const double x = p.x, y = p.y, z = p.z;
    count -= 1.0;
    sx -= x; sy -= y; sz -= z;
    sxx -= x * x; sxy -= x * y; sxz -= x * z;
    syy -= y * y; syz -= y * z; szz -= z * z;
  }
  void merge(const PlaneSums& o) {
    count += o.count;
    sx += o.sx; sy += o.sy; sz += o.sz;
    sxx += o.sxx; sxy += o.sxy; sxz += o.sxz;
    syy += o.syy; syz += o.syz; szz += o.szz;
  }

  Eigen::Vector3d centroid() const {
    if (count <= 0.0) return Eigen::Vector3d::Zero();
    return Eigen::Vector3d(sx, sy, sz) / count;
  }

  /// The least-squares plane: centroid, and the eigenvector of the covariance with the
  /// smallest eigenvalue as normal, turned to face the sensor at the origin.
  PlaneFit fit() const;
};

}  // namespace floodplane
