// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

#include "floodplane/plane_fit.h"
#include "util/vec3.h"

namespace floodplane {

/// Smallest |cos| of the angle between a plane's normal and the viewing ray to its points.
/// A camera cannot see a surface edge-on; a "plane" beyond 87 degrees of incidence is the
/// fan of viewing rays of a few image rows or columns, which fits any depth noise along
/// those rays (it passes through the sensor: d = 0), not a surface.
constexpr double kMinIncidenceCosine = 0.05;

/// Whether the plane through `point` with unit `normal` faces the sensor at the origin by
/// more than kMinIncidenceCosine.
inline bool facesSensor(const Eigen::Vector3d& normal, const Eigen::Vector3d& point) {
  const double range = point.norm();
  return range > 0.0 && std::abs(normal.dot(point)) >= kMinIncidenceCosine * range;
}

/// The cosine of the angle between a fitted plane's normal and the viewing ray to its
/// centroid (1: seen face-on; 0: edge-on). 1 for a centroid at the sensor, where there is no ray.
inline double viewIncidence(const PlaneFit& fit) {
  const double range = fit.centroid.norm();
  return range > 0.0 ? std::abs(fit.normal.dot(fit.centroid)) / range : 1.0;
}

/// Standard deviation of a fitted normal's direction [rad]: the residual variance over the
/// number of points times their spread along the plane's narrower in-plane axis. Infinite
/// when the points do not span a plane clearly (second eigenvalue under 4x the first: a line,
/// or a strip no wider than the noise), whatever their number.
inline double normalUncertainty(const PlaneFit& fit, double count) {
  if (!fit.valid || !(fit.eigenvalues(1) >= 4.0 * fit.eigenvalues(0)) || !(count > 0.0))
    return std::numeric_limits<double>::infinity();
  return std::sqrt(fit.eigenvalues(0) / (count * fit.eigenvalues(1)));
}

/// Running sums of a point set (count, sum of P, sum of P P^T) in double precision. Adding,
/// removing and merging are O(1), and so is the plane fit: the paper's merge step needs
/// inlier-weighted centroids and normals (Sec. III-D); the sums give the exact least-squares
/// plane of the union instead of a weighted average of two normals (PEAC, CAPE).
// The ten sums read best three to a line, as the matrix they form:
// clang-format off
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
  /// Adds n points, `stride` floats apart from `points` on. Local accumulators, so that a
  /// run of pixels does not go through memory for every point.
  void addRun(const float* points, std::size_t stride, std::size_t n) {
    double ax = 0.0, ay = 0.0, az = 0.0, axx = 0.0, axy = 0.0, axz = 0.0, ayy = 0.0, ayz = 0.0, azz = 0.0;
    for (std::size_t i = 0; i < n; ++i, points += stride) {
      const double x = points[0], y = points[1], z = points[2];
      ax += x; ay += y; az += z;
      axx += x * x; axy += x * y; axz += x * z;
      ayy += y * y; ayz += y * z; azz += z * z;
    }
    count += static_cast<double>(n);
    sx += ax; sy += ay; sz += az;
    sxx += axx; sxy += axy; sxz += axz;
    syy += ayy; syz += ayz; szz += azz;
  }
  /// Adds n points whose mean is (x, y, z) and whose scatter about it, sum (P - mean)(P - mean)^T,
  /// is `scatter` (xx yy zz - xy yz zx -, as BlockGrid keeps it), or nothing: all n at the mean.
  void addGroup(double n, double x, double y, double z, const float* scatter = nullptr) {
    count += n;
    sx += n * x; sy += n * y; sz += n * z;
    if (scatter) {
      const float* c = scatter;
      sxx += c[0] + n * x * x; syy += c[1] + n * y * y; szz += c[2] + n * z * z;
      sxy += c[4] + n * x * y; syz += c[5] + n * y * z; sxz += c[6] + n * z * x;
    } else {
      sxx += n * x * x; syy += n * y * y; szz += n * z * z;
      sxy += n * x * y; syz += n * y * z; sxz += n * z * x;
    }
  }
  void remove(const Vec3& p) {
    const double x = p.x, y = p.y, z = p.z;
    count -= 1.0;
    sx -= x; sy -= y; sz -= z;
    sxx -= x * x; sxy -= x * y; sxz -= x * z;
    syy -= y * y; syz -= y * z; szz -= z * z;
  }
  void subtract(const PlaneSums& o) {
    count -= o.count;
    sx -= o.sx; sy -= o.sy; sz -= o.sz;
    sxx -= o.sxx; sxy -= o.sxy; sxz -= o.sxz;
    syy -= o.syy; syz -= o.syz; szz -= o.szz;
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

  /// Mean squared distance of the points to the plane n . P + d = 0, from the sums alone.
  double meanSquaredDistance(const Eigen::Vector3d& n, double d) const {
    if (count <= 0.0) return 0.0;
    const double quadratic = n.x() * n.x() * sxx + n.y() * n.y() * syy + n.z() * n.z() * szz +
                             2.0 * (n.x() * n.y() * sxy + n.x() * n.z() * sxz + n.y() * n.z() * syz);
    const double linear = n.x() * sx + n.y() * sy + n.z() * sz;
    return std::max(0.0, (quadratic + 2.0 * d * linear) / count + d * d);
  }

  /// The least-squares plane: centroid, and the eigenvector of the covariance with the
  /// smallest eigenvalue as normal, turned to face the sensor at the origin.
  PlaneFit fit() const;
};
// clang-format on

}  // namespace floodplane
