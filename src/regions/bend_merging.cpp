// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "regions/bend_merging.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "util/label_borders.h"

namespace floodplane {

namespace {

// A band with fewer points than a seed patch's side has no normal across the border.
constexpr double kSmallestBand = 3.0 * BendMerging::kBandPixels;

// The shorter side of the rectangle that a uniform spread with these moments covers [m].
double shorterSide(const PlaneFit& fit) { return std::sqrt(12.0 * std::max(0.0, fit.eigenvalues[1])); }

}  // namespace

bool BendMerging::judge(const PointGrid& grid, const CurrentLabels& labels,
                        const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                        const std::vector<PlaneCandidate>& planes, const std::vector<bool>& curved,
                        const PlanarityTest& test, const MergeCriterion& criterion, const Tolerances& tolerances,
                        std::vector<std::uint32_t>& group) {
  const std::size_t count = planes.size();
  group.resize(count + 1);
  std::iota(group.begin(), group.end(), 0u);
  keys_.clear();
  for (const auto& [k, l] : pairs)
    if (!curved[k] || !curved[l])
      keys_.push_back(borderKey(static_cast<std::int32_t>(k), static_cast<std::int32_t>(l)));
  if (keys_.empty()) return false;
  std::sort(keys_.begin(), keys_.end());
  bands_.assign(2 * keys_.size(), PlaneSums());
  borders_.assign(keys_.size(), SegmentBorder());
  // The bands: from each pixel pair across a shared border, the pixels of either plane that go
  // on straight away from the border, up to kBandPixels (band 2 pair is the low plane's of
  // keys_[pair], 2 pair + 1 the high one's), and the pixel pairs across the border.
  const int width = grid.width, height = grid.height;
  {
    const auto walk = [&](std::size_t from, std::uint32_t k, int dx, int dy, std::size_t band) {
      int x = static_cast<int>(from % static_cast<std::size_t>(width));
      int y = static_cast<int>(from / static_cast<std::size_t>(width));
      for (int step = 0; step < kBandPixels; ++step, x += dx, y += dy) {
        if (x < 0 || y < 0 || x >= width || y >= height) return;
        const std::size_t i =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
        if (labels[i] != k) return;
        bands_[band].add(Vec3::load(grid.point(i)));
      }
    };
    forEachLabelBorder(grid, labels.image, [&](std::size_t i, std::size_t j) {
      const std::uint32_t k = labels[i], l = labels[j];
      if (k == l || k == 0 || l == 0) return;
      const std::uint64_t key = borderKey(static_cast<std::int32_t>(k), static_cast<std::int32_t>(l));
      const auto found = std::lower_bound(keys_.begin(), keys_.end(), key);
      if (found == keys_.end() || *found != key) return;
      const std::size_t pair = static_cast<std::size_t>(found - keys_.begin());
      const Vec3 p = Vec3::load(grid.point(i)), q = Vec3::load(grid.point(j));
      if (k < l)
        borders_[pair].add(p, q);
      else
        borders_[pair].add(q, p);
      const int dx = j == i + 1 ? 1 : 0, dy = 1 - dx;
      walk(i, k, -dx, -dy, 2 * pair + (k < l ? 0 : 1));
      walk(j, l, dx, dy, 2 * pair + (k < l ? 1 : 0));
    });
  }
  sets_.reset(count + 1);
  bool any = false;
  for (std::size_t pair = 0; pair < keys_.size(); ++pair) {
    // The bands pass Eq. 9, the border shows no step.
    const PlaneSums& low = bands_[2 * pair];
    const PlaneSums& high = bands_[2 * pair + 1];
    if (low.count < kSmallestBand || high.count < kSmallestBand) continue;
    double cost = 0.0;
    if (!criterion.mergeable(low, low.fit(), high, high.fit(), cost)) continue;
    PlaneSums bands = low;
    bands.merge(high);
    double step = 0.0;
    if (!criterion.withoutStep(bands.fit().normal, borders_[pair], step)) continue;
    // The union is no curved surface.
    const std::uint32_t k = static_cast<std::uint32_t>(keys_[pair] >> 32);
    const std::uint32_t l = static_cast<std::uint32_t>(keys_[pair] & 0xffffffffu);
    PlaneSums joint = planes[k - 1].sums;
    joint.merge(planes[l - 1].sums);
    const PlaneFit fit = joint.fit();
    if (!fit.valid || test.unionBends(k, l, fit, tolerances)) continue;
    // A plane judged curved alone joins a flat one only as the bend of a larger flat surface
    // (the corner of a warped table): the flat one spans more than the radius of the curved
    // things of a room both ways (a facet of a body, a bin or a pipe is narrower than it
    // across its axis), and their union is flat by its curvature, however significant its
    // bend.
    if (curved[k] || curved[l]) {
      const PlaneFit& flat = curved[k] ? planes[l - 1].sums.fit() : planes[k - 1].sums.fit();
      if (!(shorterSide(flat) > 1.0 / PlanarityTest::kSmallestCurvature)) continue;
      if (!(test.unionCurvature(k, l, fit) < PlanarityTest::kSmallestCurvature)) continue;
    }
    sets_.unite(static_cast<std::int32_t>(k), static_cast<std::int32_t>(l));
    any = true;
  }
  for (std::size_t k = 1; k <= count; ++k)
    group[k] = static_cast<std::uint32_t>(sets_.find(static_cast<std::int32_t>(k)));
  return any;
}

}  // namespace floodplane
