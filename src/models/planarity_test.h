// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "floodplane/plane_fit.h"
#include "stages/tolerances.h"
#include "util/vec3.h"

namespace floodplane {

/// Beyond the paper: the planarity test. A facet of a cylinder, a ball or a person stays within
/// three noise deviations of its own plane, so it passes every test of the flood and the
/// merge. Here each plane's inliers are fitted with a quadratic surface
///   w = a u^2 + b u v + c v^2 + d u + e v + f
/// in the plane's own frame (u, v along it, w across it), from running moment sums. A plane is
/// curved when what the quadratic explains beyond the plane is beyond what the noise could fake
/// (a chi-square test against the noise model across the surface) and its larger principal
/// curvature is that of the curved things in rooms (radii below half a metre): a real wall
/// bent by a few millimetres over metres, or by a depth camera's calibration, stays a plane.
///
/// Two touching planes are judged as one surface too (curvedPair, facet_pairs.h). So that
/// this costs nothing per point, a plane's sums are its points' moments up to the fourth order
/// in x, y and z, from which the quadratic's sums in any frame follow exactly: the plane's own,
/// or that of its union with a neighbour.
class PlanarityTest {
 public:
  /// Starts the sums for planes 1..fits.size() (fits[k - 1] is plane k).
  void reset(const std::vector<PlaneFit>& fits);
  /// Adds an inlier of plane k; with a `weight`, as that many inliers at `point` (a block's
  /// mean standing for its pixels).
  void add(std::uint32_t k, const Vec3& point, double weight = 1.0);
  /// Whether plane k has enough sampled points to show a bend at all.
  bool judgeable(std::uint32_t k) const;
  /// Whether plane k bends more than its noise explains.
  bool curved(std::uint32_t k, const Tolerances& tolerances) const;
  /// The larger principal curvature of plane k's quadratic [1/m].
  double curvature(std::uint32_t k) const;
  /// Whether planes k and l, whose union's plane is `joint`, are two facets of one curved
  /// surface: their union is curved as curved() judges a plane, and one smooth quadratic
  /// explains it better than k and l each by a plane of its own (residual sums of squares
  /// along the union's normal, six parameters either way), where at a crease the two planes
  /// fit better.
  bool curvedPair(std::uint32_t k, std::uint32_t l, const PlaneFit& joint, const Tolerances& tolerances) const;

  /// The number of monomials x^a y^b z^c with a + b + c <= 4.
  static constexpr int kMonomials = 35;

 private:
  // A frame on a plane: w along its normal.
  struct Frame {
    Eigen::Vector3d centroid, u, v, w;
  };
  static Frame frameOf(const PlaneFit& fit);
  // The quadratic's sums in one frame.
  struct Sums {
    double moments[17] = {};  // the distinct entries of sum m m^T, m = (1, u, v, u^2, uv, v^2), but the count
    double rhs[6] = {};       // sum m w
    double ww = 0.0;          // sum w^2
    double count = 0.0;
    Sums& operator+=(const Sums& o);
  };
  // Plane k's sums in `frame`.
  Sums sumsIn(std::uint32_t k, const Frame& frame) const;
  // The quadratic fit of a sample: the sum of squares it explains beyond the plane, its larger
  // principal curvature [1/m], and the residual sums of squares of the sample about its best
  // plane and about the quadratic.
  struct Quadric {
    double explained = 0.0, curvature = 0.0;
    double plane_residual = 0.0, residual = 0.0;
  };
  static Quadric fitQuadric(const Sums& s);
  // Whether sums `s` of points about the plane `fit` bend beyond the noise (see curved()).
  static bool bends(const Sums& s, const Quadric& q, const PlaneFit& fit, const Tolerances& tolerances);

  std::vector<Vec3> origins_;  // per plane: its centroid, the origin of its moments
  // Per plane: the sums of x^a y^b z^c over its sampled points (relative to its origin), in
  // the order of kMonomials: by degree, then by falling a, then falling b.
  std::vector<double> moments_;
  std::vector<PlaneFit> fits_;
};

// Inline: it runs for every sampled inlier of every plane, from region output.
inline void PlanarityTest::add(std::uint32_t k, const Vec3& point, double weight) {
  const Vec3 d = point - origins_[k - 1];
  const double x = d.x, y = d.y, z = d.z;
  const double xx = x * x, xy = x * y, xz = x * z, yy = y * y, yz = y * z, zz = z * z;
  const double values[kMonomials] = {1.0,     x,       y,       z,       xx,      xy,      xz,      yy,      yz,
                                     zz,      xx * x,  xx * y,  xx * z,  xy * y,  xy * z,  xz * z,  yy * y,  yy * z,
                                     yz * z,  zz * z,  xx * xx, xx * xy, xx * xz, xx * yy, xx * yz, xx * zz, xy * yy,
                                     xy * yz, xy * zz, xz * zz, yy * yy, yy * yz, yy * zz, yz * zz, zz * zz};
  double* m = moments_.data() + static_cast<std::size_t>(k - 1) * kMonomials;
  if (weight == 1.0) {
    for (int i = 0; i < kMonomials; ++i) m[i] += values[i];
  } else {
    for (int i = 0; i < kMonomials; ++i) m[i] += weight * values[i];
  }
}

}  // namespace floodplane
