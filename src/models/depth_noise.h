// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <initializer_list>

#include "floodplane/noise_model.h"
#include "util/simd.h"

namespace floodplane {

// The sensor's depth noise, the one model every stage takes its tolerances from: NoiseModel's
//   sigma(r) = sigma_0 + c r^2,
// the shape of a triangulating sensor's error (structured light, stereo: Nguyen et al. 2012
// for the Kinect, whose axial noise and disparity quantisation both grow with the square of
// the depth). These helpers take r^2, so that the per-pixel hot paths need no square root;
// they are templates so that float hot paths stay in float.

/// How many noise deviations a tolerance allows, named once for every stage:
/// - one point's depth: 3 sigma(r) holds 99.7 % of Gaussian noise. The point band of Eq. 2 along
///   the ray, the angle it subtends in the seed test (Eqs. 6-7), and every length that must
///   clear one point's noise (half the seed cube, Sec. III-C; sigma_plane-merge, Eq. 9).
constexpr double kPointDeviations = 3.0;
/// - the difference of two noisy depths, whose deviation is sqrt(2) sigma(r): 3 sqrt(2) sigma(r).
///   Eq. 3 between two neighbours, the depth smoothing's gate, the hole filling's bridge.
constexpr double kDifferenceDeviations = 3.0 * 1.4142135623730951;  // 3 sqrt(2)

/// sigma(r), for r^2 = range_sq.
template <class Real>
Real depthSigma(const NoiseModel& noise, Real range_sq) {
  return static_cast<Real>(noise.sigma_constant) + static_cast<Real>(noise.sigma_quadratic) * range_sq;
}

/// k noise deviations at range r: k sigma(r), for r^2 = range_sq (k: kPointDeviations,
/// kDifferenceDeviations).
template <class Real>
Real noiseDeviations(const NoiseModel& noise, double k, Real range_sq) {
  return static_cast<Real>(k) * depthSigma(noise, range_sq);
}

/// Whether the model describes exact data (float round-off at most).
inline bool negligibleNoise(const NoiseModel& noise) {
  return noise.sigma_constant < 1e-7 && noise.sigma_quadratic < 1e-7;
}

/// Whether the noise is below a tenth of the pixel footprint (range x `angular_pitch`) over
/// the ranges of rooms, 0.5-8 m: exact geometry for every purpose of the grid, although not
/// exact. A depth image stored in 0.2 mm units (TUM's 16-bit PNGs) is exact data rounded to
/// a 0.2 mm lattice, a noise of 0.06 mm, a twentieth of a Kinect pixel's footprint at 1 m; a
/// depth camera's own noise is several footprints.
inline bool negligibleAgainstPixels(const NoiseModel& noise, double angular_pitch) {
  constexpr double kShare = 0.1;
  constexpr double kNear = 0.5;
  constexpr double kFar = 8.0;
  return negligibleNoise(noise) || (depthSigma(noise, kNear * kNear) <= kShare * kNear * angular_pitch &&
                                    depthSigma(noise, kFar * kFar) <= kShare * kFar * angular_pitch);
}

/// Whether the measured noise is the rounding of a depth lattice and nothing more: exact depths
/// stored in steps q(r) (a simulator's depth image in millimetres), whose error is uniform over
/// a step, q(r) / sqrt(12), at most kRoundingShare times that over the ranges of rooms. Such a
/// frame is exact geometry on a staircase: the smoothing, which averages Gaussian noise away,
/// cannot average away treads wider than its kernel (an oblique plane), and the noise
/// measured after it sees the flat treads, not the risers. A sensor's own noise dithers its
/// lattice (a Kinect's spread is half a disparity step or more before rounding: 0.5-0.7 steps
/// measured, a scanner's 0.8) and keeps the smoothing.
inline bool roundingOnly(const NoiseModel& noise) {
  constexpr double kRoundingShare = 1.5;
  constexpr double kUniformDeviation = 0.28867513459481287;  // 1 / sqrt(12)
  for (const double range : {0.5, 2.0, 8.0}) {
    const double step = noise.step(range);
    if (!(step > 0.0) || depthSigma(noise, range * range) > kRoundingShare * kUniformDeviation * step) return false;
  }
  return true;
}

/// The squared range at which to take the depth noise when pixel q is tested from its
/// neighbour p: the nearer of the two. On one surface the two ranges are nearly equal, so
/// this changes nothing there; but an outlier far along its ray (a multipath return 100 km
/// out) must not widen its own tolerances by c r^2 until it fits every plane. A hole at p
/// (NaN) leaves q's own range.
inline float nearerRangeSq(float p_sq, float q_sq) { return p_sq < q_sq ? p_sq : q_sq; }

#if FLOODPLANE_SIMD
/// static_cast<float>(noiseDeviations(noise, k, double(range_sq))) lane by lane: the noise in
/// double, as the scalar code takes it.
inline Float4 noiseDeviations(const NoiseModel& noise, double k, Float4 range_sq) {
  const __m128d constant = _mm_set1_pd(noise.sigma_constant), quadratic = _mm_set1_pd(noise.sigma_quadratic),
                scale = _mm_set1_pd(k);
  const auto half = [&](__m128d r2) { return _mm_mul_pd(scale, _mm_add_pd(constant, _mm_mul_pd(quadratic, r2))); };
  const __m128 low = _mm_cvtpd_ps(half(_mm_cvtps_pd(range_sq.v)));
  const __m128 high = _mm_cvtpd_ps(half(_mm_cvtps_pd(_mm_movehl_ps(range_sq.v, range_sq.v))));
  return {_mm_movelh_ps(low, high)};
}

#endif  // FLOODPLANE_SIMD

#if FLOODPLANE_AVX
/// noiseDeviations for four lanes, in double.
FLOODPLANE_TARGET_AVX inline __m128 noiseDeviationsInDouble(const NoiseModel& noise, double k, __m128 range_sq) {
  const __m256d sigma = _mm256_add_pd(_mm256_set1_pd(noise.sigma_constant),
                                      _mm256_mul_pd(_mm256_set1_pd(noise.sigma_quadratic), _mm256_cvtps_pd(range_sq)));
  return _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_set1_pd(k), sigma));
}

/// noiseDeviations in eight lanes: the noise in double, four lanes at a time.
FLOODPLANE_TARGET_AVX inline Float8 noiseDeviations(const NoiseModel& noise, double k, Float8 range_sq) {
  const __m128 low = noiseDeviationsInDouble(noise, k, _mm256_castps256_ps128(range_sq.v));
  const __m128 high = noiseDeviationsInDouble(noise, k, _mm256_extractf128_ps(range_sq.v, 1));
  return {_mm256_insertf128_ps(_mm256_castps128_ps256(low), high, 1)};
}

#endif  // FLOODPLANE_AVX

}  // namespace floodplane
