// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "models/flood_criterion.h"

#include <cmath>

namespace floodplane {

FloodCriterion FloodCriterion::make(const Vec3& normal, float offset, double range, double spacing_per_range_sq,
                                    const Tolerances& tolerances) {
  // The pixel pitch varies a little across a plane (it shrinks by cos^2 of the off-axis
  // angle), so neighbours may be up to twice the spacing apart.
  constexpr double kSpacingSlack = 2.0;
  const NoiseModel& noise = tolerances.noise();
  FloodCriterion c;
  c.normal = normal;
  c.offset = offset;
  c.plane_threshold = static_cast<float>(tolerances.planeFloor(range));
  // noiseDeviations as the two coefficients of k sigma(r) = k sigma_0 + k c r^2, for the
  // per-pixel test in float: one point's depth along the ray (Eq. 2), and the depths of both
  // points (Eq. 3).
  c.plane_noise_offset = static_cast<float>(kPointDeviations * noise.sigma_constant);
  c.plane_noise_factor = static_cast<float>(kPointDeviations * noise.sigma_quadratic);
  c.euclidean_offset = static_cast<float>(kDifferenceDeviations * noise.sigma_constant);
  c.euclidean_factor =
      static_cast<float>(kSpacingSlack * spacing_per_range_sq + kDifferenceDeviations * noise.sigma_quadratic);
  return c;
}

}  // namespace floodplane
