// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Sec. III-B: the distance function of the flood (Eqs. 1-3), as one test that every stage
// which lets a pixel join a plane calls (the flood, the relabelling's neighbour edges,
// sub-sampled labelling, the refinement).

#include <cmath>

#include "models/depth_noise.h"
#include "models/tolerances.h"
#include "util/simd.h"
#include "util/vec3.h"

namespace floodplane {

/// Eq. 2: f_plane(p_seed, p') = |(P_seed - P') . n_seed|, written with the plane's offset
/// d = -n . P_seed so that the flood can replace (n, d) by a least-squares refit.
inline float planeDistance(const Vec3& normal, float offset, const Vec3& point) {
  return std::abs(normal.dot(point) + offset);
}

/// Eq. 3 squared: ||P - P'||^2 (compared with sigma_euclidean^2).
inline float squaredEuclideanDistance(const Vec3& a, const Vec3& b) { return (a - b).squaredNorm(); }

/// The squared range at which the noise of q, tested from its neighbour p, is taken.
inline float noiseRangeSq(const Vec3& p, const Vec3& q) { return nearerRangeSq(p.squaredNorm(), q.squaredNorm()); }

/// The membership test of Eq. 1 for one plane: a pixel p' joins from its neighbour p when
///   f_plane(p') < sigma_plane(r')  and  f_euclidean(p, p') < sigma_euclidean(r').
///
/// Beyond the paper (which uses constants and was evaluated on noise-free simulation):
/// - Eq. 2 under the sensor's noise. A depth sensor errs along its viewing rays, so a point of
///   a plane seen at an angle a from its normal lies off the plane by sigma(r) cos a, not by
///   sigma(r): the noise band of a plane seen obliquely is thin. The plane test therefore
///   passes when the point's distance to the plane is within the fixed sigma_plane (the
///   parameter, or a fraction of the pixel footprint), or when its distance *along its ray*,
///   f_plane / cos a (the depth error that would put it on the plane), is within three noise
///   deviations 3 sigma(r). The ray distance is what Eq. 4 compares: the plane that explains
///   a pixel with the smaller depth error takes it, which decides the band along a crease
///   between a wall seen edge-on and one seen face-on the right way.
/// - sigma_euclidean(r): on a plane n.P + d = 0 the spacing of pixel neighbours is
///   alpha r^2 / |d| (alpha: angular pixel pitch), and |d| is the same for the whole plane,
///   so the spacing grows as r^2 with one constant per plane (Eq. 8 measures it at the seed).
///   We allow twice that, plus the depth noise of both points (3 sqrt(2) sigma(r)). Without
///   this, a seed's spacing would cut a floor into depth bands.
/// Thresholds are precomputed floats: the test runs once or twice per pixel of every flood.
struct FloodCriterion {
  Vec3 normal;                     ///< n of the current plane estimate (unit)
  float offset = 0.f;              ///< d of the current plane estimate: n . P + d = 0
  float plane_threshold = 0.f;     ///< sigma_plane [m], across the plane
  float plane_noise_offset = 0.f;  ///< 3 sigma_0, along the ray
  float plane_noise_factor = 0.f;  ///< 3 c: the noise tolerance grows as 3 c r^2
  float euclidean_offset = 0.f;    ///< 3 sqrt(2) sigma_0
  float euclidean_factor = 0.f;    ///< K: sigma_euclidean(r) = 3 sqrt(2) sigma_0 + K r^2

  /// The criterion of a plane (normal, offset) seen from range `range`, whose neighbouring
  /// pixels are `spacing_per_range_sq` r^2 metres apart at range r.
  static FloodCriterion make(const Vec3& normal, float offset, double range, double spacing_per_range_sq,
                             const Tolerances& tolerances);

  /// 3 sigma(r) along the ray, for r^2 = range_sq.
  float noiseTolerance(float range_sq) const { return plane_noise_offset + plane_noise_factor * range_sq; }
  /// The larger of the two tolerances, as one scale (Eq. 4's hysteresis).
  float planeTolerance(float range_sq) const { return std::max(plane_threshold, noiseTolerance(range_sq)); }
  float euclideanToleranceSq(float range_sq) const {
    const float tolerance = euclidean_offset + euclidean_factor * range_sq;
    return tolerance * tolerance;
  }

  /// Eq. 2 for q, whose noise is taken at `noise_range_sq` (see noiseRangeSq): whether q fits
  /// the plane, and its distance to the plane along its ray in `ray_distance`. NaN fails.
  bool fitsPlane(const Vec3& q, float noise_range_sq, float& ray_distance) const {
    const float dot = normal.dot(q);
    const float distance = std::abs(dot + offset);
    ray_distance = distance * std::sqrt(q.squaredNorm()) / std::abs(dot);
    return distance < plane_threshold || ray_distance < noiseTolerance(noise_range_sq);
  }

  /// Eqs. 1-3 for q reached from its neighbour p; `ray_distance` gets q's distance along its
  /// ray when the Euclidean test (Eq. 3) passes. Written so that a hole (NaN) fails.
  bool accepts(const Vec3& p, const Vec3& q, float& ray_distance) const {
    const float range_sq = noiseRangeSq(p, q);
    if (!(squaredEuclideanDistance(p, q) < euclideanToleranceSq(range_sq))) return false;
    return fitsPlane(q, range_sq, ray_distance);
  }

#if FLOODPLANE_SIMD
  /// fitsPlane lane by lane, with the same operations in the same order.
  Mask4 fitsPlane(const PointLanes& q, Float4 noise_range_sq, Float4& ray_distance) const {
    const Float4 dot = q.dot(normal);
    const Float4 distance = (dot + Float4::broadcast(offset)).abs();
    ray_distance = distance * q.squaredNorm().sqrt() / dot.abs();
    return (distance < Float4::broadcast(plane_threshold)) |
           (ray_distance <
            Float4::broadcast(plane_noise_offset) + Float4::broadcast(plane_noise_factor) * noise_range_sq);
  }
  /// planeTolerance lane by lane, for ranges that are not NaN (see Float4::max).
  Float4 planeTolerance(Float4 range_sq) const {
    return Float4::max(Float4::broadcast(plane_threshold),
                       Float4::broadcast(plane_noise_offset) + Float4::broadcast(plane_noise_factor) * range_sq);
  }
  Float4 euclideanToleranceSq(Float4 range_sq) const {
    const Float4 tolerance = Float4::broadcast(euclidean_offset) + Float4::broadcast(euclidean_factor) * range_sq;
    return tolerance * tolerance;
  }
#endif
};

}  // namespace floodplane
