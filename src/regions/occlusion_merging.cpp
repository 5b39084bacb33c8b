// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "regions/occlusion_merging.h"

#include <algorithm>

namespace floodplane {

namespace {

// A pixel between two pieces is behind their plane beyond this many plane tolerances.
constexpr float kBehindTolerances = 2.0f;

}  // namespace

void OcclusionMerging::findBoxes(int width, int height, const CurrentLabels& labels, std::size_t planes) {
  boxes_.assign(planes, Box{width, height, -1, -1});
  // A row is mostly long runs of one label: one box update per run.
  for (int y = 0; y < height; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
    labels.forEachRunInRow(row, 0, width - 1, [&](std::uint32_t k, int begin, int end) {
      if (k == 0) return;
      Box& box = boxes_[k - 1];
      box.x_min = std::min(box.x_min, begin);
      box.x_max = std::max(box.x_max, end - 1);
      box.y_min = std::min(box.y_min, y);
      box.y_max = std::max(box.y_max, y);
    });
  }
}

bool OcclusionMerging::occludedBetween(const PointGrid& full, const CurrentLabels& labels, std::uint32_t a,
                                       std::uint32_t b, const FloodCriterion& plane) const {
  const Box& box_a = boxes_[a - 1];
  const Box& box_b = boxes_[b - 1];
  const std::size_t width = static_cast<std::size_t>(full.width);
  std::size_t gaps = 0;
  // A pixel between the two that is behind their plane: no surface there. Behind by more than
  // twice the plane tolerance (six noise deviations): the pixels of the plane itself that
  // its 3-sigma band left out (one in 400 on a noisy plane) sit all along the gap, and one
  // of them must not keep the pieces apart.
  const auto behind = [&](std::size_t i) {
    const Vec3 q = Vec3::load(full.point(i));
    float ray_distance = 0.f;
    // NaN (no return) is neither behind nor in front; n faces the sensor, so in front of the
    // plane n . q + d > 0.
    const float range_sq = q.squaredNorm();
    return plane.normal.dot(q) + plane.offset < 0.f && !plane.fitsPlane(q, range_sq, ray_distance) &&
           ray_distance > kBehindTolerances * plane.planeTolerance(range_sq);
  };
  // Walks one line of `count` pixels `step` apart from `first`; false at a pixel behind.
  const auto line = [&](std::size_t first, std::ptrdiff_t step, int count) {
    std::uint32_t last = 0;
    int last_at = -1;
    for (int k = 0; k < count; ++k) {
      const std::size_t i = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(first) + k * step);
      const std::uint32_t label = labels[i];
      if (label != a && label != b) continue;
      if (last != 0 && last != label) {
        ++gaps;
        for (int m = last_at + 1; m < k; ++m)
          if (behind(static_cast<std::size_t>(static_cast<std::ptrdiff_t>(first) + m * step))) return false;
      }
      last = label;
      last_at = k;
    }
    return true;
  };
  const int x_min = std::min(box_a.x_min, box_b.x_min), x_max = std::max(box_a.x_max, box_b.x_max);
  const int y_min = std::min(box_a.y_min, box_b.y_min), y_max = std::max(box_a.y_max, box_b.y_max);
  for (int y = std::max(box_a.y_min, box_b.y_min); y <= std::min(box_a.y_max, box_b.y_max); ++y)
    if (!line(static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x_min), 1, x_max - x_min + 1))
      return false;
  for (int x = std::max(box_a.x_min, box_b.x_min); x <= std::min(box_a.x_max, box_b.x_max); ++x)
    if (!line(static_cast<std::size_t>(y_min) * width + static_cast<std::size_t>(x), static_cast<std::ptrdiff_t>(width),
              y_max - y_min + 1))
      return false;
  return gaps > 0;
}

bool OcclusionMerging::run(const PointGrid& full, PlaneCandidates& planes, const MergeCriterion& criterion,
                           const Tolerances& tolerances, float angular_pitch) {
  std::vector<PlaneCandidate>& list = planes.list();
  const std::size_t n = list.size();
  if (n < 2) return false;
  const CurrentLabels labels = planes.labels();
  fits_.clear();
  for (const PlaneCandidate& candidate : list) fits_.push_back(candidate.sums.fit());
  bool boxes_found = false;
  sets_.reset(n + 1);
  for (std::uint32_t a = 1; a <= n; ++a) {
    for (std::uint32_t b = a + 1; b <= n; ++b) {
      double cost = 0.0;
      if (!criterion.mergeable(list[a - 1].sums, fits_[a - 1], list[b - 1].sums, fits_[b - 1], cost)) continue;
      if (!boxes_found) {
        findBoxes(full.width, full.height, labels, n);
        boxes_found = true;
      }
      PlaneSums both = list[a - 1].sums;
      both.merge(list[b - 1].sums);
      if (occludedBetween(full, labels, a, b, planeCriterion(both.fit(), tolerances, angular_pitch)))
        sets_.unite(static_cast<std::int32_t>(a), static_cast<std::int32_t>(b));
    }
  }
  std::vector<std::uint32_t> group(n + 1, 0);
  for (std::uint32_t k = 1; k <= n; ++k)
    group[k] = static_cast<std::uint32_t>(sets_.find(static_cast<std::int32_t>(k)));
  if (!planes.regroup(group)) return false;
  for (PlaneCandidate& candidate : planes.list())
    candidate.criterion = planeCriterion(candidate.sums.fit(), tolerances, angular_pitch);
  return true;
}

}  // namespace floodplane
