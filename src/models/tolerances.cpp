// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "models/tolerances.h"

#include <algorithm>
#include <cmath>

namespace floodplane {

namespace {

// sigma_plane's floor without noise, in pixel footprints.
constexpr double kPlaneFootprints = 0.5;
// Half the seed cube at least spans this many pixel footprints.
constexpr double kSeedFootprints = 6.0;
// sigma_plane-merge's floor, in pixel footprints.
constexpr double kMergeFootprints = 1.0;
// The default smallest plane: one pixel in this many.
constexpr double kPixelsPerMinimumPlane = 1000.0;
// A merge's parts fit its plane within half of sigma_plane or this many noise deviations (RMS):
// a part further off the merged plane than that on average is a plane of its own (a 2 cm
// board on a wall).
constexpr double kMergeFitDeviations = 2.0;

}  // namespace

Tolerances::Tolerances(const Params& params, const NoiseModel& noise, double angular_pitch, std::size_t pixels)
    : distance_threshold_(params.distance_threshold),
      seed_size_(params.seed_size),
      merge_distance_(params.merge_distance),
      noise_(noise),
      angular_pitch_(angular_pitch) {
  min_inliers_ = params.min_inliers
                     ? *params.min_inliers
                     : static_cast<std::uint32_t>(std::lround(static_cast<double>(pixels) / kPixelsPerMinimumPlane));
}

double Tolerances::planeFloor(double range) const {
  return distance_threshold_ ? *distance_threshold_ : kPlaneFootprints * footprint(range);
}

double Tolerances::seedHalfSide(double range, double scale) const {
  const double fixed = seed_size_ ? 0.5 * *seed_size_ : kSeedFootprints * footprint(range);
  return std::max(scale * fixed, noiseDeviations(noise_, kPointDeviations, range * range));
}

double Tolerances::mergeDistance(double range) const {
  const double fixed = merge_distance_ ? *merge_distance_ : kMergeFootprints * footprint(range);
  return std::max(fixed, noiseDeviations(noise_, kPointDeviations, range * range));
}

double Tolerances::mergeFit(double range) const {
  return std::max(0.5 * planeFloor(range), noiseDeviations(noise_, kMergeFitDeviations, range * range));
}

}  // namespace floodplane
