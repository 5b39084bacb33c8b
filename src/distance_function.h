#pragma once
// Sec. III-B: the distance function of the flood (Eqs. 1-3), as one test that every stage
// which lets a pixel join a plane calls (the flood, the relabelling's neighbour edges,
// sub-sampled labelling, the refinement).

#include <cmath>

#include "depth_noise.h"
#include "tolerances.h"
#include "simd.h"
#include "vec3.h"

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
/// Both thresholds depend on the range r' of P' (beyond the paper, which uses constants and
/// was evaluated on noise-free simulation):
/// - sigma_plane(r) = max(sigma_plane, 3 sigma_depth(r)), the depth noise's 3-sigma band.
/// - sigma_euclidean(r): on a plane n.P + d = 0 the spacing of pixel neighbours is
///   alpha r^2 / |d| (alpha: angular pixel pitch), and |d| is the same for the whole plane,
///   so the spacing grows as r^2 with one constant per plane (Eq. 8 measures it at the seed).
///   We allow twice that, plus the depth noise of both points (3 sqrt(2) sigma(r)). Without
///   this, a seed's spacing would cut a floor into depth bands.
/// Thresholds are precomputed floats: the test runs once or twice per pixel of every flood.
struct FloodCriterion {
  Vec3 normal;                     ///< n of the current plane estimate (unit)
  float offset = 0.f;              ///< d of the current plane estimate: n . P + d = 0
  float plane_threshold = 0.f;     ///< sigma_plane [m]
  float plane_noise_offset = 0.f;  ///< 3 sigma_0
  float plane_noise_factor = 0.f;  ///< 3 c: plane tolerance grows as 3 c r^2
  float euclidean_offset = 0.f;    ///< 3 sqrt(2) sigma_0
  float euclidean_factor = 0.f;    ///< K: sigma_euclidean(r) = 3 sqrt(2) sigma_0 + K r^2

  /// The criterion of a plane (normal, offset) seen from range `range`, whose neighbouring
  /// pixels are `spacing_per_range_sq` r^2 metres apart at range r.
  static FloodCriterion make(const Vec3& normal, float offset, double range, double spacing_per_range_sq,
                             const Tolerances& tolerances);

  float planeTolerance(float range_sq) const {
    return std::max(plane_threshold, plane_noise_offset + plane_noise_factor * range_sq);
  }
  float euclideanToleranceSq(float range_sq) const {
    const float tolerance = euclidean_offset + euclidean_factor * range_sq;
    return tolerance * tolerance;
  }

  /// Eqs. 1-3 for q reached from its neighbour p; `distance` gets q's plane distance when
  /// the Euclidean test (Eq. 3) passes. Written so that a hole (NaN) fails.
  bool accepts(const Vec3& p, const Vec3& q, float& distance) const {
    const float range_sq = noiseRangeSq(p, q);
    if (!(squaredEuclideanDistance(p, q) < euclideanToleranceSq(range_sq))) return false;
    distance = planeDistance(normal, offset, q);
    return distance < planeTolerance(range_sq);
  }

#if FLOODPLANE_SIMD
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
