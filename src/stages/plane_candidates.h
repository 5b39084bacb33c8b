// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "floodplane/params.h"
#include "floodplane/plane_fit.h"
#include "models/flood_criterion.h"
#include "models/plane_sums.h"
#include "models/tolerances.h"

namespace floodplane {

/// "No pixel yet" for PlaneCandidate::first_pixel.
constexpr std::size_t kNoPixel = std::numeric_limits<std::size_t>::max();

/// A label image read through a renumbering not yet applied to it: the plane number of pixel
/// i is number[image[i]]. The stages after refinement renumber the planes (sorting them,
/// merging occluded pieces, dropping curved ones) and read the labels in between; they read
/// them through this, and the image is rewritten once, at the end.
struct RenumberedLabels {
  const std::uint32_t* image = nullptr;
  const std::uint32_t* number = nullptr;
  std::uint32_t operator[](std::size_t i) const { return number[image[i]]; }
};

/// A plane on its way to the output: its full-resolution inliers and its membership test.
struct PlaneCandidate {
  PlaneSums sums;            ///< of its full-resolution inliers
  FloodCriterion criterion;  ///< its plane and thresholds, for labelling and refinement
  std::size_t first_pixel = kNoPixel;
};

/// The candidate planes and their numbers in the label image (1..K, 0: no plane). Planes are
/// numbered by size, largest first; renumbering maps old numbers to new through remap().
class PlaneCandidates {
 public:
  std::vector<PlaneCandidate>& list() { return candidates_; }
  const std::vector<PlaneCandidate>& list() const { return candidates_; }
  PlaneCandidate& operator[](std::uint32_t label) { return candidates_[label - 1]; }

  /// Drops candidates under `min_inliers` and, when `recheck` is given, those whose inliers
  /// no longer make an acceptable plane under its parameters; orders the rest by size.
  /// Returns whether any number changed (the label image then needs renumberPixels).
  bool sortBySize(std::uint32_t min_inliers, const Params* recheck);
  /// Merges the candidates whose numbers k share a value group[k] (group[0] is ignored) and
  /// orders the result by size again. Returns whether any merged (the label image then needs
  /// renumberPixels).
  bool regroup(const std::vector<std::uint32_t>& group);
  /// Drops the candidates whose number k has drop[k] set (drop[0] is ignored), keeping the
  /// order of the rest. Returns whether any was dropped.
  bool drop(const std::vector<bool>& drop);
  /// The new number of old number k, after sortBySize or drop (0: dropped).
  std::uint32_t remap(std::uint32_t k) const { return remap_[k]; }
  /// Forgets every plane's first pixel, before a full renumbering.
  void forgetFirstPixels();
  /// Applies remap() to labels [begin, end) and notes first pixels (those before `begin`
  /// already noted).
  void renumberPixels(std::uint32_t* labels, std::size_t begin, std::size_t end);
  /// Applies remap() to the whole label image and notes every plane's first pixel anew.
  void renumberImage(std::vector<std::uint32_t>& labels) {
    forgetFirstPixels();
    renumberPixels(labels.data(), 0, labels.size());
  }

  /// Deferred renumbering. From here on the label image keeps the numbers it has, and
  /// labels() reads it through the pending renumbering: remap() when `pending` (the last
  /// sortBySize, regroup or drop changed the numbers and the image was not renumbered), none
  /// otherwise. First pixels follow the planes through every renumbering, so none is lost.
  void deferRenumbering(bool pending);
  /// Adds the last regroup's or drop's remap() to the pending renumbering.
  void composeRenumbering();
  /// The image as its pixels' current plane numbers.
  RenumberedLabels labels(const std::vector<std::uint32_t>& image) const { return {image.data(), number_.data()}; }
  /// Rewrites the image with the current numbers, in one pass.
  void applyRenumbering(std::vector<std::uint32_t>& image) const;

 private:
  std::vector<PlaneCandidate> candidates_;
  std::vector<PlaneCandidate> kept_;
  std::vector<std::uint32_t> remap_;
  std::vector<std::uint32_t> number_;  // the deferred renumbering: image number -> current number
  std::vector<std::size_t> order_;
};

/// What a reported plane must be: a valid fit, no more curved than allowed, facing the sensor.
bool acceptablePlane(const PlaneFit& fit, const Params& params);

/// A plane's membership test for pixels that join it after merging, from its fit. The
/// Euclidean tolerance follows from the plane itself: neighbouring pixels on n.P + d = 0 are
/// alpha r^2 / |d| apart (see FloodCriterion).
FloodCriterion planeCriterion(const PlaneFit& fit, const Tolerances& tolerances, float angular_pitch);

}  // namespace floodplane
