#pragma once

#include <algorithm>

#include "floodplane/segmenter.h"

namespace floodplane {

/// The sensor's depth noise, the one model every stage takes its tolerances from:
///   sigma(r) = sigma_0 + c r^2,
/// the shape of a triangulating sensor's error (structured light, stereo: Nguyen et al. 2012
/// for the Kinect, whose axial noise and disparity quantisation both grow with the square of
/// the depth). A tolerance is the larger of a fixed threshold and three standard deviations.
/// All functions take r^2, so that the per-pixel hot path needs no square root; they are
/// templates so that float hot paths stay in float.
struct DepthNoise {
  double constant = 0.0;   ///< sigma_0 [m]
  double quadratic = 0.0;  ///< c [1/m]; 0 with sigma_0 = 0: the paper's fixed thresholds

  static DepthNoise of(const NoiseModel& model) {
    DepthNoise noise;
    noise.constant = model.sigma_constant;
    noise.quadratic = model.sigma_quadratic;
    return noise;
  }

  /// Whether the model describes exact data (float round-off at most).
  bool negligible() const { return constant < 1e-7 && quadratic < 1e-7; }

  /// Whether the noise is below a tenth of the pixel footprint (range x `angular_pitch`) over
  /// the ranges of rooms, 0.5-8 m: exact geometry for every purpose of the grid, although not
  /// exact. A depth image stored in 0.2 mm units (TUM's 16-bit PNGs) is exact data rounded to
  /// a 0.2 mm lattice, a noise of 0.06 mm, a twentieth of a Kinect pixel's footprint at 1 m; a
  /// depth camera's own noise is several footprints.
  bool negligibleAgainstPixels(double angular_pitch) const {
    constexpr double kShare = 0.1;
    constexpr double kNear = 0.5;
    constexpr double kFar = 8.0;
    return negligible() || (sigma(kNear * kNear) <= kShare * kNear * angular_pitch &&
                            sigma(kFar * kFar) <= kShare * kFar * angular_pitch);
  }

  template <class Real>
  Real sigma(Real range_sq) const {
    return static_cast<Real>(constant) + static_cast<Real>(quadratic) * range_sq;
  }
  /// max(fixed, 3 sigma(r)).
  template <class Real>
  Real tolerance(Real fixed, Real range_sq) const {
    return std::max(fixed, static_cast<Real>(3) * sigma(range_sq));
  }
};

/// The squared range at which to take the depth noise when pixel q is tested from its
/// neighbour p: the nearer of the two. On one surface the two ranges are nearly equal, so
/// this changes nothing there; but an outlier far along its ray (a multipath return 100 km
/// out) must not widen its own tolerances by c r^2 until it fits every plane. A hole at p
/// (NaN) leaves q's own range.
inline float nearerRangeSq(float p_sq, float q_sq) { return p_sq < q_sq ? p_sq : q_sq; }

}  // namespace floodplane
