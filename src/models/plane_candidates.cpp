// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "models/plane_candidates.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "util/row_search.h"

namespace floodplane {

FloodCriterion planeCriterion(const PlaneFit& fit, const Tolerances& tolerances, float angular_pitch) {
  const double range = fit.centroid.norm();
  const double distance = std::max(std::abs(fit.offset), 0.1 * range);  // bounded where seen edge-on
  const double spacing_per_range_sq = angular_pitch / std::max(distance, 1e-6);
  const Vec3 normal{static_cast<float>(fit.normal.x()), static_cast<float>(fit.normal.y()),
                    static_cast<float>(fit.normal.z())};
  return FloodCriterion::make(normal, static_cast<float>(fit.offset), range, spacing_per_range_sq, tolerances);
}

bool acceptablePlane(const PlaneFit& fit, const Params& params) {
  return fit.valid && fit.curvature <= params.maximum_curvature && facesSensor(fit.normal, fit.centroid);
}

// ---- PlaneCandidates -------------------------------------------------------------------

void PlaneCandidates::clear() {
  candidates_.clear();
  number_.clear();
}

bool PlaneCandidates::sortBySize(std::uint32_t min_inliers, const Params* recheck) {
  const bool changed = sortCandidates(min_inliers, recheck);
  recordRenumbering();
  return changed;
}

bool PlaneCandidates::sortCandidates(std::uint32_t min_inliers, const Params* recheck) {
  order_.resize(candidates_.size());
  std::iota(order_.begin(), order_.end(), 0);
  std::stable_sort(order_.begin(), order_.end(),
                   [&](std::size_t a, std::size_t b) { return candidates_[a].sums.count > candidates_[b].sums.count; });
  remap_.assign(candidates_.size() + 1, 0);
  kept_.clear();
  bool changed = false;
  for (std::size_t rank = 0; rank < order_.size(); ++rank) {
    const PlaneCandidate& candidate = candidates_[order_[rank]];
    if (candidate.sums.count < min_inliers || (recheck && !acceptablePlane(candidate.sums.fit(), *recheck))) {
      changed = true;
      continue;
    }
    kept_.push_back(candidate);
    remap_[order_[rank] + 1] = static_cast<std::uint32_t>(kept_.size());
    changed = changed || order_[rank] != rank;
  }
  candidates_.swap(kept_);
  return changed;
}

bool PlaneCandidates::regroup(const std::vector<std::uint32_t>& group) {
  const std::size_t n = candidates_.size();
  remap_.assign(n + 1, 0);
  std::vector<std::uint32_t> number_of_group(n + 1, 0);
  kept_.clear();
  for (std::size_t k = 1; k <= n; ++k) {
    std::uint32_t& number = number_of_group[group[k]];
    const PlaneCandidate& candidate = candidates_[k - 1];
    if (number == 0) {
      kept_.push_back(candidate);
      number = static_cast<std::uint32_t>(kept_.size());
    } else {
      PlaneCandidate& into = kept_[number - 1];
      into.sums.merge(candidate.sums);
      into.first_pixel = std::min(into.first_pixel, candidate.first_pixel);
    }
    remap_[k] = number;
  }
  const bool merged = kept_.size() != n;
  candidates_.swap(kept_);
  if (merged) {
    // A merged plane may have outgrown the ones before it: number by size again, in the same
    // remap, which is then one renumbering.
    std::vector<std::uint32_t> grouped = remap_;
    sortCandidates(0, nullptr);
    for (std::size_t k = 1; k <= n; ++k) grouped[k] = remap_[grouped[k]];
    remap_.swap(grouped);
  }
  recordRenumbering();
  return merged;
}

bool PlaneCandidates::drop(const std::vector<bool>& drop) {
  remap_.assign(candidates_.size() + 1, 0);
  kept_.clear();
  for (std::size_t k = 1; k <= candidates_.size(); ++k) {
    if (drop[k]) continue;
    kept_.push_back(candidates_[k - 1]);
    remap_[k] = static_cast<std::uint32_t>(kept_.size());
  }
  const bool dropped = kept_.size() != candidates_.size();
  candidates_.swap(kept_);
  recordRenumbering();
  return dropped;
}

// ---- the label image -------------------------------------------------------------------

void PlaneCandidates::recordRenumbering() {
  for (std::uint32_t& number : number_) number = remap_[number];
}

std::uint32_t* PlaneCandidates::newImage(int width, int height) {
  width_ = width;
  height_ = height;
  image_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  imageUpToDate();
  return image_.data();
}

bool PlaneCandidates::imageOutOfDate() const {
  for (std::size_t k = 0; k < number_.size(); ++k)
    if (number_[k] != k) return true;
  return false;
}

void PlaneCandidates::imageUpToDate() {
  number_.resize(candidates_.size() + 1);
  std::iota(number_.begin(), number_.end(), 0u);
}

void PlaneCandidates::renumberPixels(std::size_t begin, std::size_t end) {
  std::uint32_t* labels = image_.data();
  forEachRun(labels, begin, end, [&](std::uint32_t old_label, std::size_t first, std::size_t last) {
    const std::uint32_t k = number_[old_label];
    if (k != old_label) std::fill(labels + first, labels + last, k);
  });
}

std::uint32_t* PlaneCandidates::writableImage() {
  if (imageOutOfDate()) {
    renumberPixels(0, image_.size());
    imageUpToDate();
  }
  return image_.data();
}

void PlaneCandidates::releaseImage(std::vector<std::uint32_t>& out) {
  writableImage();
  out.swap(image_);
  number_.clear();
  width_ = height_ = 0;
}

}  // namespace floodplane
