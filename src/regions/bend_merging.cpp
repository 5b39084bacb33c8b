// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "regions/bend_merging.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace floodplane {

namespace {

// A band with fewer points than a seed patch's side has no normal across the border.
constexpr double kSmallestBand = 3.0 * BendMerging::kBandPixels;
// The bands are walked from about this many pixel pairs of a border.
constexpr std::size_t kBandRows = 64;

// The shorter side of the rectangle that a uniform spread with these moments covers [m].
double shorterSide(const PlaneFit& fit) { return std::sqrt(12.0 * std::max(0.0, fit.eigenvalues[1])); }

// The cheap tests of a touching pair k, l (`pair` of the facet pairs), before its bands.
bool bendMayJoin(std::uint32_t k, std::uint32_t l, bool union_bends, const std::vector<PlaneCandidate>& planes,
                 const std::vector<bool>& curved, const PlanarityTest& test) {
  if (curved[k] && curved[l]) return false;
  const PlaneFit fit_k = planes[k - 1].sums.fit(), fit_l = planes[l - 1].sums.fit();
  if (!fit_k.valid || !fit_l.valid) return false;
  // A plane judged curved alone joins a flat one only as the bend of a larger flat surface
  // (the corner of a warped table): the flat one spans more than the radius of the curved
  // things of a room both ways (a facet of a body, a bin or a pipe is narrower than it
  // across its axis), and their union is flat by its curvature, however significant its
  // bend.
  if ((curved[k] || curved[l]) && !(shorterSide(curved[k] ? fit_l : fit_k) > 1.0 / PlanarityTest::kSmallestCurvature))
    return false;
  // The union is no curved surface.
  if (union_bends) return false;
  if (curved[k] || curved[l]) {
    PlaneSums joint = planes[k - 1].sums;
    joint.merge(planes[l - 1].sums);
    const PlaneFit fit = joint.fit();
    if (!fit.valid || !(test.unionCurvature(k, l, fit) < PlanarityTest::kSmallestCurvature)) return false;
  }
  return true;
}

// From pixel `from` of plane k, away from its neighbour across the border by (dx, dy): the
// pixels of k that go on straight, up to kBandPixels, into `band`.
void walkBand(const PointGrid& grid, const CurrentLabels& labels, std::size_t from, std::uint32_t k, int dx, int dy,
              PlaneSums& band) {
  const int width = grid.width, height = grid.height;
  int x = static_cast<int>(from % static_cast<std::size_t>(width));
  int y = static_cast<int>(from / static_cast<std::size_t>(width));
  for (int step = 0; step < BendMerging::kBandPixels; ++step, x += dx, y += dy) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
    if (labels[i] != k) return;
    band.add(Vec3::load(grid.point(i)));
  }
}

// The bands along the border of `pair` (k, l) pass Eq. 9 and the border shows no step along
// their normal. The bands are walked from about kBandRows of its pixel pairs, evenly spread
// along it (a long border's bands need no more to show their planes).
bool bandsJoin(const PointGrid& grid, const CurrentLabels& labels, const FacetPairs& pairs, std::size_t pair,
               std::uint32_t k, std::uint32_t l, const MergeCriterion& criterion) {
  SegmentBorder border;  // the pixel pairs across the border (i on k, j on l), for the step
  pairs.forEachPixelPair(
      pair, [&](std::size_t i, std::size_t j) { border.add(Vec3::load(grid.point(i)), Vec3::load(grid.point(j))); });
  const std::size_t row = static_cast<std::size_t>(grid.width);
  PlaneSums low, high;
  const std::size_t stride = std::max<std::size_t>(1, static_cast<std::size_t>(border.count) / kBandRows);
  std::size_t n = 0;
  pairs.forEachPixelPair(pair, [&](std::size_t i, std::size_t j) {
    if (n++ % stride != 0) return;
    const int dx = j == i + 1 ? 1 : (i == j + 1 ? -1 : 0);
    const int dy = j == i + row ? 1 : (i == j + row ? -1 : 0);
    walkBand(grid, labels, i, k, -dx, -dy, low);
    walkBand(grid, labels, j, l, dx, dy, high);
  });
  if (low.count < kSmallestBand || high.count < kSmallestBand) return false;
  double cost = 0.0;
  if (!criterion.mergeable(low, low.fit(), high, high.fit(), cost)) return false;
  PlaneSums bands = low;
  bands.merge(high);
  double step = 0.0;
  return criterion.withoutStep(bands.fit().normal, border, step);
}

}  // namespace

bool BendMerging::judge(const PointGrid& grid, const CurrentLabels& labels, const FacetPairs& pairs,
                        const std::vector<bool>& union_bends, const std::vector<PlaneCandidate>& planes,
                        const std::vector<bool>& curved, const PlanarityTest& test, const MergeCriterion& criterion,
                        std::vector<std::uint32_t>& group) {
  const std::size_t count = planes.size();
  group.resize(count + 1);
  std::iota(group.begin(), group.end(), 0u);
  if (pairs.pairs().empty()) return false;
  sets_.reset(count + 1);
  bool any = false;
  for (std::size_t pair = 0; pair < pairs.pairs().size(); ++pair) {
    // The cheap tests first, the bands last.
    const std::uint32_t k = pairs.pairs()[pair].first, l = pairs.pairs()[pair].second;
    if (!bendMayJoin(k, l, union_bends[pair], planes, curved, test)) continue;
    if (!bandsJoin(grid, labels, pairs, pair, k, l, criterion)) continue;
    sets_.unite(static_cast<std::int32_t>(k), static_cast<std::int32_t>(l));
    any = true;
  }
  for (std::size_t k = 1; k <= count; ++k)
    group[k] = static_cast<std::uint32_t>(sets_.find(static_cast<std::int32_t>(k)));
  return any;
}

}  // namespace floodplane
