// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace floodplane {

/// Eq. 4: per pixel, the segment that owns it and the plane distance with which it was
/// claimed. A flood takes a pixel only if its plane fits better than the current owner's,
///   f_plane(p_seed, p') < D(p'),
/// so later floods from better seeds take over pixels that noise gave to spurious planes.
/// Label 0 means unclaimed, which stands for the paper's D(p) = infinity: the distances of
/// unclaimed pixels are never read, so a frame's reset touches only the labels.
class DistanceBuffer {
 public:
  void reset(std::size_t pixels) {
    labels_.assign(pixels, 0);
    if (distances_.size() < pixels) distances_.resize(pixels);
  }

  std::int32_t label(std::size_t pixel) const { return labels_[pixel]; }
  float distance(std::size_t pixel) const { return distances_[pixel]; }

  /// Eq. 4 as a predicate: would a flood at this plane distance take the pixel?
  /// `margin` is a hysteresis the paper does not have: an owned pixel changes hands only if
  /// the new plane is closer by more than the margin. With depth noise, two floods on one
  /// wall have almost the same plane and would otherwise trade pixels by coin flip, leaving
  /// both as salt and pepper for the relabelling to shatter.
  bool fitsBetter(std::size_t pixel, float plane_distance, float margin = 0.f) const {
    return labels_[pixel] == 0 || plane_distance + margin < distances_[pixel];
  }

  /// Gives the pixel to `segment` at `plane_distance`; returns the previous owner (0: none).
  std::int32_t claim(std::size_t pixel, std::int32_t segment, float plane_distance) {
    const std::int32_t previous = labels_[pixel];
    labels_[pixel] = segment;
    distances_[pixel] = plane_distance;
    return previous;
  }

  /// Gives the n pixels from `first` on to `segment` at the given distances.
  void claimRun(std::size_t first, std::size_t n, std::int32_t segment, const float* plane_distances) {
    std::fill_n(labels_.begin() + static_cast<std::ptrdiff_t>(first), n, segment);
    std::copy_n(plane_distances, n, distances_.begin() + static_cast<std::ptrdiff_t>(first));
  }

  /// Gives the n pixels from `first` on to `segment` at one distance.
  void claimRun(std::size_t first, std::size_t n, std::int32_t segment, float plane_distance) {
    std::fill_n(labels_.begin() + static_cast<std::ptrdiff_t>(first), n, segment);
    std::fill_n(distances_.begin() + static_cast<std::ptrdiff_t>(first), n, plane_distance);
  }

  const std::vector<float>& distances() const { return distances_; }
  std::vector<std::int32_t>& labels() { return labels_; }
  const std::vector<std::int32_t>& labels() const { return labels_; }

 private:
  std::vector<std::int32_t> labels_;
  std::vector<float> distances_;
};

}  // namespace floodplane
