// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "floodplane/params.h"
#include "models/depth_noise.h"

namespace floodplane {

/// Every length tolerance of the method at a range r, in one place: the paper's fixed
/// lengths where Params sets them, otherwise the scale-free defaults, derived from the depth
/// noise sigma(r) and the pixel footprint alpha r (alpha: the angle between neighbouring
/// viewing rays). kPointDeviations of the noise widen every tolerance (depth_noise.h).
class Tolerances {
 public:
  Tolerances() = default;
  Tolerances(const Params& params, const NoiseModel& noise, double angular_pitch, std::size_t pixels);

  const NoiseModel& noise() const { return noise_; }
  /// The same tolerances under another noise model.
  Tolerances withNoise(const NoiseModel& noise) const {
    Tolerances copy = *this;
    copy.noise_ = noise;
    return copy;
  }
  /// The width of a pixel's footprint at range r [m].
  double footprint(double range) const { return angular_pitch_ * range; }

  /// The fixed part of sigma_plane (Eq. 2) for a flood seeded at range r: the parameter, or a
  /// fraction of the pixel footprint (exact data need only the float round-off covered).
  double planeFloor(double range) const;
  /// Half the side of the seed cube (Sec. III-C) at range r; `scale` shrinks its fixed part
  /// (the finer second seeding pass), not the noise's.
  double seedHalfSide(double range, double scale = 1.0) const;
  /// sigma_plane-merge (Eq. 9) at range r.
  double mergeDistance(double range) const;
  /// The largest RMS distance of a part from the plane of a merge (see MergeCriterion).
  double mergeFit(double range) const;
  /// The smallest plane reported.
  std::uint32_t minInliers() const { return min_inliers_; }

 private:
  // The paper's fixed lengths where Params sets them.
  std::optional<double> distance_threshold_;
  std::optional<double> seed_size_;
  std::optional<double> merge_distance_;
  NoiseModel noise_;
  double angular_pitch_ = 0.0;
  std::uint32_t min_inliers_ = 0;
};

}  // namespace floodplane
