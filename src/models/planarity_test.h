// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "floodplane/plane_fit.h"
#include "models/tolerances.h"
#include "util/simd.h"
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
  /// Adds an inlier of plane k.
  void add(std::uint32_t k, const Vec3& point);
  /// The same with a weight: the point stands for `weight` measured points (a block's mean).
  void add(std::uint32_t k, const Vec3& point, double weight);
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
  /// `union_bends`, if given, is set to whether their union bends as curved() judges a plane
  /// (false when either is too small to judge: nothing is known against the union).
  bool curvedPair(std::uint32_t k, std::uint32_t l, const PlaneFit& joint, const Tolerances& tolerances,
                  bool* union_bends = nullptr) const;
  /// The larger principal curvature of the union of planes k and l [1/m] (see curvature()).
  double unionCurvature(std::uint32_t k, std::uint32_t l, const PlaneFit& joint) const;
  /// The curvature below which a surface is no curved thing of a room, however significant
  /// its bend (a radius of half a metre).
  static constexpr double kSmallestCurvature = 2.0;  // 1/m

  /// The number of monomials x^a y^b z^c with a + b + c <= 4.
  static constexpr int kMonomials = 35;

 private:
  // A frame on a plane: w along its normal.
  struct Frame {
    Eigen::Vector3d centroid, u, v, w;
  };
  static Frame frameOf(const PlaneFit& fit);
  template <typename Scale>
  void addScaled(std::uint32_t k, const Vec3& point, Scale scale);
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

// Inline: it runs for every sampled inlier of every plane, from region output. Each monomial
// is added as it is computed (no array of them in between: at s = 1 that costs a few percent
// of a frame); `scale` is the identity for an unweighted point, so that its sums are the
// plain ones.
template <typename Scale>
inline void PlanarityTest::addScaled(std::uint32_t k, const Vec3& point, Scale scale) {
  const Vec3 d = point - origins_[k - 1];
  const double x = d.x, y = d.y, z = d.z;
  const double xx = x * x, xy = x * y, xz = x * z, yy = y * y, yz = y * z, zz = z * z;
  double* m = moments_.data() + static_cast<std::size_t>(k - 1) * kMonomials;
  m[0] += scale(1.0);
  m[1] += scale(x);
  m[2] += scale(y);
  m[3] += scale(z);
  m[4] += scale(xx);
  m[5] += scale(xy);
  m[6] += scale(xz);
  m[7] += scale(yy);
  m[8] += scale(yz);
  m[9] += scale(zz);
  m[10] += scale(xx * x);
  m[11] += scale(xx * y);
  m[12] += scale(xx * z);
  m[13] += scale(xy * y);
  m[14] += scale(xy * z);
  m[15] += scale(xz * z);
  m[16] += scale(yy * y);
  m[17] += scale(yy * z);
  m[18] += scale(yz * z);
  m[19] += scale(zz * z);
  m[20] += scale(xx * xx);
  m[21] += scale(xx * xy);
  m[22] += scale(xx * xz);
  m[23] += scale(xx * yy);
  m[24] += scale(xx * yz);
  m[25] += scale(xx * zz);
  m[26] += scale(xy * yy);
  m[27] += scale(xy * yz);
  m[28] += scale(xy * zz);
  m[29] += scale(xz * zz);
  m[30] += scale(yy * yy);
  m[31] += scale(yy * yz);
  m[32] += scale(yy * zz);
  m[33] += scale(yz * zz);
  m[34] += scale(zz * zz);
}

inline void PlanarityTest::add(std::uint32_t k, const Vec3& point) {
#if FLOODPLANE_SIMD
  // The same 35 sums two at a time (SSE2 doubles): each lane's product and sum is the scalar
  // one's IEEE operation on the same operands, so the sums are bit for bit addScaled's.
  const Vec3 d = point - origins_[k - 1];
  double* m = moments_.data() + static_cast<std::size_t>(k - 1) * kMonomials;
  const auto accumulate = [m](int i, __m128d values) { _mm_storeu_pd(m + i, _mm_add_pd(_mm_loadu_pd(m + i), values)); };
  const double x = d.x, y = d.y, z = d.z;
  const __m128d vx = _mm_set1_pd(x), vz = _mm_set1_pd(z);
  const __m128d x_y = _mm_set_pd(y, x), y_z = _mm_set_pd(z, y);
  const __m128d xx_xy = _mm_mul_pd(vx, x_y);                // (xx, xy)
  const __m128d xz_yy = _mm_mul_pd(x_y, _mm_set_pd(y, z));  // (xz, yy)
  const __m128d yz_zz = _mm_mul_pd(vz, y_z);                // (yz, zz)
  const __m128d xy_xz = _mm_shuffle_pd(xx_xy, xz_yy, 1);    // (xy, xz)
  const __m128d yy_yz = _mm_shuffle_pd(xz_yy, yz_zz, 1);    // (yy, yz)
  const __m128d xx = _mm_unpacklo_pd(xx_xy, xx_xy);
  const __m128d yy = _mm_unpackhi_pd(xz_yy, xz_yy);
  const __m128d zz = _mm_unpackhi_pd(yz_zz, yz_zz);
  const __m128d xy = _mm_unpackhi_pd(xx_xy, xx_xy);
  accumulate(0, _mm_set_pd(x, 1.0));
  accumulate(2, y_z);
  accumulate(4, xx_xy);
  accumulate(6, xz_yy);
  accumulate(8, yz_zz);
  accumulate(10, _mm_mul_pd(xx, x_y));                              // xx x, xx y
  accumulate(12, _mm_mul_pd(xx_xy, _mm_set_pd(y, z)));              // xx z, xy y
  accumulate(14, _mm_mul_pd(xy_xz, vz));                            // xy z, xz z
  accumulate(16, _mm_mul_pd(yy, y_z));                              // yy y, yy z
  accumulate(18, _mm_mul_pd(yz_zz, vz));                            // yz z, zz z
  accumulate(20, _mm_mul_pd(xx, xx_xy));                            // xx xx, xx xy
  accumulate(22, _mm_mul_pd(xx, _mm_shuffle_pd(xy_xz, yy_yz, 1)));  // xx xz, xx yy
  accumulate(24, _mm_mul_pd(xx, yz_zz));                            // xx yz, xx zz
  accumulate(26, _mm_mul_pd(xy, yy_yz));                            // xy yy, xy yz
  accumulate(28, _mm_mul_pd(xy_xz, zz));                            // xy zz, xz zz
  accumulate(30, _mm_mul_pd(yy, yy_yz));                            // yy yy, yy yz
  accumulate(32, _mm_mul_pd(yy_yz, zz));                            // yy zz, yz zz
  m[34] += _mm_cvtsd_f64(zz) * _mm_cvtsd_f64(zz);
#else
  addScaled(k, point, [](double value) { return value; });
#endif
}

inline void PlanarityTest::add(std::uint32_t k, const Vec3& point, double weight) {
  addScaled(k, point, [weight](double value) { return weight * value; });
}

}  // namespace floodplane
