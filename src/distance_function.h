#pragma once

#include <algorithm>
#include <cmath>

#include "floodplane/point_grid.h"

namespace floodplane {

/// Depth noise that grows with the square of the range, sigma_depth(r) = c r^2, the shape of
/// a structured-light camera's error (Nguyen et al. 2012: axial noise; plus the disparity
/// quantisation, also quadratic in depth). Tolerances become max(fixed, 3 sigma_depth).
/// All functions take r^2 so that the per-pixel hot path needs no square root.
struct DepthNoise {
  double coefficient = 0.0;  ///< c [1/m]; 0 = no range-dependent noise

  double sigma(double range_sq) const { return coefficient * range_sq; }
  /// The tolerance at range r: the fixed threshold, or three standard deviations of the
  /// noise when that is larger.
  double tolerance(double fixed, double range_sq) const {
    return std::max(fixed, 3.0 * sigma(range_sq));
  }
};

/// The squared range at which to take the depth noise when pixel q is tested from its
/// neighbour p: the nearer of the two. On one surface the two ranges are nearly equal, so
/// this changes nothing there; but an outlier far along its ray (a multipath return 100 km
/// out) must not widen its own tolerances by c r^2 until it fits every plane. A hole at p
/// (NaN) leaves q's own range.
inline float nearerRangeSq(float p_sq, float q_sq) { return p_sq < q_sq ? p_sq : q_sq; }
/// The same from the two points.
inline float noiseRangeSq(const Vec3& p, const Vec3& q) { return nearerRangeSq(p.squaredNorm(), q.squaredNorm()); }

/// Eq. 2: f_plane(p_seed, p') = |(P_seed - P') . n_seed|, written with the plane's offset
/// d = -n . P_seed so that the flood can replace (n, d) by a least-squares refit.
inline float planeDistance(const Vec3& normal, float offset, const Vec3& point) {
  return std::abs(normal.dot(point) + offset);
}

/// Eq. 3 squared: ||P - P'||^2 (compared with sigma_euclidean^2).
inline float squaredEuclideanDistance(const Vec3& a, const Vec3& b) { return (a - b).squaredNorm(); }

/// The membership test of Eq. 1 for one flood: a pixel p' joins from its neighbour p when
///   f_plane(p') < sigma_plane(r')  and  f_euclidean(p, p') < sigma_euclidean(r').
///
/// Both thresholds depend on the range r' of P' (beyond the paper, which uses constants and
/// was evaluated on noise-free simulation):
/// - sigma_plane(r) = max(sigma_plane, 3 c r^2), the depth noise's 3-sigma band.
/// - sigma_euclidean(r): Eq. 8 measures the spacing s0 of neighbouring points at the seed,
///   at range r0. On a plane n.P + d = 0 the spacing of pixel neighbours is alpha r^2 / |d|
///   (alpha: angular pixel pitch), and |d| is the same for the whole plane, so the spacing at
///   range r is s0 (r / r0)^2. We allow twice that, plus the depth noise of both points
///   (3 sqrt(2) c r^2). Both terms grow with r^2, so sigma_euclidean(r)^2 = K r^4 with one
///   constant K per flood. Without this, a seed's spacing would cut a floor into depth bands.
struct FloodCriterion {
  Vec3 normal;               ///< n of the current plane estimate (unit)
  float offset = 0.f;        ///< d of the current plane estimate: n . P + d = 0
  float plane_threshold = 0.f;       ///< sigma_plane [m]
  float plane_noise_factor = 0.f;    ///< 3 c: plane tolerance grows as 3 c r^2
  float euclidean_factor_sq = 0.f;   ///< K: sigma_euclidean(r)^2 = K r^4

  /// Sets K from Eq. 8's spacing at the seed (sigma_euclidean [m per pixel]) and the seed's
  /// squared range, and the noise coefficient c.
  void setEuclidean(float seed_spacing, float seed_range_sq, float noise_coefficient) {
    constexpr float kSpacingSlack = 2.0f;  // the pixel pitch varies a little across a plane
    const float spacing_term = kSpacingSlack * seed_spacing / std::max(seed_range_sq, 1e-12f);
    const float noise_term = 3.0f * std::sqrt(2.0f) * noise_coefficient;
    const float k = spacing_term + noise_term;
    euclidean_factor_sq = k * k;
  }

  float planeTolerance(float range_sq) const {
    return std::max(plane_threshold, plane_noise_factor * range_sq);
  }
  float euclideanToleranceSq(float range_sq) const {
    return euclidean_factor_sq * range_sq * range_sq;
  }
};

}  // namespace floodplane
