// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "models/facet_pairs.h"

#include <algorithm>
#include <cmath>

#include "models/flood_criterion.h"
#include "util/label_borders.h"

namespace floodplane {

template <class Labels>
void FacetPairs::find(const PointGrid& grid, const Labels& labels, const std::vector<PlaneCandidate>& planes,
                      const std::vector<PlaneFit>& fits, const std::vector<bool>& eligible) {
  touching_.clear();
  pixel_pairs_.clear();
  pairs_.clear();
  runs_.clear();
  pair_runs_.clear();
  const std::size_t count = fits.size();
  const double cos_maximum = std::cos(kMaximumAngle);
  const auto close = [&](std::uint32_t k, std::uint32_t l) {
    return std::abs(fits[k - 1].normal.dot(fits[l - 1].normal)) >= cos_maximum;
  };
  // Planes with a possible partner (most planes of a room meet at right angles, a frame may
  // have none): the scan below looks only at them, and is skipped when there are none.
  candidate_.assign(count + 1, 0);
  bool any = false;
  for (std::uint32_t k = 1; k <= count; ++k) {
    if (!eligible[k] || !fits[k - 1].valid) continue;
    for (std::uint32_t l = k + 1; l <= count; ++l) {
      if (eligible[l] && fits[l - 1].valid && close(k, l)) candidate_[k] = candidate_[l] = 1;
    }
    any = any || candidate_[k];
  }
  if (!any) return;

  // Pixels i and j = i + 1 or i + width, of two different planes (the image's numbers differ,
  // neither is 0).
  const auto touch = [&](std::size_t i, std::size_t j) {
    const std::uint32_t k = labels[i], l = labels[j];
    if (k == l || k == 0 || l == 0 || !candidate_[k] || !candidate_[l] || !close(k, l)) return;
    const std::uint64_t key = borderKey(static_cast<std::int32_t>(k), static_cast<std::int32_t>(l));
    if (!runs_.empty() && runs_.back().key == key)
      ++runs_.back().count;
    else
      runs_.push_back({key, static_cast<std::uint32_t>(pixel_pairs_.size()), 1});
    pixel_pairs_.emplace_back(static_cast<std::uint32_t>(k < l ? i : j), static_cast<std::uint32_t>(k < l ? j : i));
    const Vec3 p = Vec3::load(grid.point(i)), q = Vec3::load(grid.point(j));
    if (!(squaredEuclideanDistance(p, q) < planes[k - 1].criterion.euclideanToleranceSq(noiseRangeSq(p, q)))) return;
    // Consecutive pixel pairs of one border are counted in one entry: the list stays short.
    if (!touching_.empty() && touching_.back().key == key)
      ++touching_.back().count;
    else
      touching_.push_back({key, 1});
  };
  forEachLabelBorder(grid, labels.image, touch);
  keepLongBorders();
}

void FacetPairs::keepLongBorders() {
  std::sort(touching_.begin(), touching_.end(), [](const Touch& a, const Touch& b) { return a.key < b.key; });
  // The runs of pixel pairs by border, each border's in the scan's order.
  std::stable_sort(runs_.begin(), runs_.end(), [](const Run& a, const Run& b) { return a.key < b.key; });
  for (std::size_t i = 0; i < touching_.size();) {
    std::size_t j = i;
    std::uint32_t border = 0;
    for (; j < touching_.size() && touching_[j].key == touching_[i].key; ++j) border += touching_[j].count;
    if (border >= kMinimumBorder) {
      pairs_.emplace_back(static_cast<std::uint32_t>(touching_[i].key >> 32),
                          static_cast<std::uint32_t>(touching_[i].key & 0xffffffffu));
      const auto range = std::equal_range(runs_.begin(), runs_.end(), Run{touching_[i].key, 0, 0},
                                          [](const Run& a, const Run& b) { return a.key < b.key; });
      pair_runs_.emplace_back(static_cast<std::size_t>(range.first - runs_.begin()),
                              static_cast<std::size_t>(range.second - runs_.begin()));
    }
    i = j;
  }
}

template void FacetPairs::find(const PointGrid&, const PlainLabels&, const std::vector<PlaneCandidate>&,
                               const std::vector<PlaneFit>&, const std::vector<bool>&);
template void FacetPairs::find(const PointGrid&, const CurrentLabels&, const std::vector<PlaneCandidate>&,
                               const std::vector<PlaneFit>&, const std::vector<bool>&);

}  // namespace floodplane
