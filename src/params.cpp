#include "floodplane/params.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace floodplane {

bool isValidSubsampling(int factor) { return factor == 1 || factor == 2 || factor == 4 || factor == 8; }

namespace {
void requirePositive(double value, const char* name) {
  if (!(std::isfinite(value) && value > 0.0))
    throw std::invalid_argument(std::string("floodplane::Params: ") + name +
                                " must be a finite number > 0, got " + std::to_string(value));
}
}  // namespace

void Params::validate() const {
  requirePositive(distance_threshold, "distance_threshold");
  requirePositive(seed_size, "seed_size");
  requirePositive(angular_threshold, "angular_threshold");
  if (angular_threshold >= M_PI / 2)
    throw std::invalid_argument("floodplane::Params: angular_threshold must be < pi/2 rad, got " +
                                std::to_string(angular_threshold));
  requirePositive(merge_distance, "merge_distance");
  if (!(std::isfinite(maximum_curvature) && maximum_curvature >= 0.0))
    throw std::invalid_argument("floodplane::Params: maximum_curvature must be >= 0, got " +
                                std::to_string(maximum_curvature));
  if (!isValidSubsampling(subsampling))
    throw std::invalid_argument("floodplane::Params: subsampling must be 1, 2, 4 or 8, got " +
                                std::to_string(subsampling));
  if (!(std::isfinite(depth_noise_coefficient) && depth_noise_coefficient >= 0.0))
    throw std::invalid_argument("floodplane::Params: depth_noise_coefficient must be >= 0, got " +
                                std::to_string(depth_noise_coefficient));
}

}  // namespace floodplane
