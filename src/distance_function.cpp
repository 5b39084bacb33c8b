#include "distance_function.h"

#include <cmath>

namespace floodplane {

FloodCriterion FloodCriterion::make(const Vec3& normal, float offset, double range, double spacing_per_range_sq,
                                    const Tolerances& tolerances) {
  // The pixel pitch varies a little across a plane (it shrinks by cos^2 of the off-axis
  // angle), so neighbours may be up to twice the spacing apart.
  constexpr double kSpacingSlack = 2.0;
  const DepthNoise& noise = tolerances.noise();
  FloodCriterion c;
  c.normal = normal;
  c.offset = offset;
  c.plane_threshold = static_cast<float>(tolerances.planeFloor(range));
  c.plane_noise_offset = static_cast<float>(3.0 * noise.constant);
  c.plane_noise_factor = static_cast<float>(3.0 * noise.quadratic);
  // The depth noise of both points: 3 sqrt(2) sigma(r).
  c.euclidean_offset = static_cast<float>(3.0 * std::sqrt(2.0) * noise.constant);
  c.euclidean_factor =
      static_cast<float>(kSpacingSlack * spacing_per_range_sq + 3.0 * std::sqrt(2.0) * noise.quadratic);
  return c;
}

}  // namespace floodplane
