// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// One pass of seeds, floods, relabelling and merging over a grid, and the two ways the coarse
// pass starts the fine one: pixels given to a segment for good, and a segment flooding on from
// them. Exact pinhole grids.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "flood/flood_pass.h"
#include "models/plane_candidates.h"
#include "support/pinhole_grid.h"

namespace floodplane {
namespace {

constexpr float kPitch = static_cast<float>(1.0 / test::kPinholeFocal);

using Grid = test::PinholeGrid;

// Two frontal planes side by side: 2 m left of column 30, 2.5 m from it on.
double twoPlanes(int u, int) { return u < 30 ? 2.0 : 2.5; }

struct Pass {
  Grid frame;
  Params params;
  FloodGrid grid;
  FloodPass pass;
  SegmentationStats stats;
  PhaseTimes phases;

  explicit Pass(Grid g) : frame(std::move(g)) {
    params.depth_noise_constant = 0.0;
    params.depth_noise_coefficient = 0.0;
    params.min_inliers = 50;
    grid.points = frame.grid();
    grid.tolerances = Tolerances(params, NoiseModel(), kPitch, frame.grid().size());
    grid.pitch = kPitch;
    grid.noise_free = true;
    pass.begin(grid, params);
  }
  std::int32_t label(int u, int v) const { return pass.labels()[frame.index(u, v)]; }
  // The cluster (root segment) of pixel (u, v) after merging.
  std::int32_t cluster(const MergedSegments& merged, int u, int v) const {
    const std::int32_t s = merged.labels[frame.index(u, v)];
    return s == 0 ? 0 : merged.root[s];
  }
};

TEST(FloodPass, SegmentsTwoPlanesIntoTwoClusters) {
  Pass p(Grid(60, 40, twoPlanes, 4));
  p.pass.seedAndFlood(false, p.stats, p.phases);
  p.pass.relabel();
  const MergedSegments merged = p.pass.merge(MergeCriterion(p.params, p.grid.tolerances));
  EXPECT_GT(p.stats.seeds, 0u);
  const std::int32_t left = p.cluster(merged, 5, 20), right = p.cluster(merged, 50, 20);
  ASSERT_NE(left, 0);
  ASSERT_NE(right, 0);
  EXPECT_NE(left, right);
  for (int v = 0; v < 40; ++v)
    for (int u = 0; u < 60; ++u) EXPECT_EQ(p.cluster(merged, u, v), u < 30 ? left : right) << u << ", " << v;
}

// A segment for the left plane whose pixels are columns 0-9, given before any flood.
std::int32_t giveLeftColumns(Pass& p) {
  Segment segment;
  for (int v = 0; v < 40; ++v)
    for (int u = 0; u < 10; ++u) segment.sums.add(p.frame.point(u, v));
  segment.criterion = planeCriterion(segment.sums.fit(), p.grid.tolerances, kPitch);
  const std::int32_t label = p.pass.addSegment(segment);
  for (int v = 0; v < 40; ++v)
    for (int u = 0; u < 10; ++u) p.pass.claim(p.frame.index(u, v), label);
  return label;
}

TEST(FloodPass, KeepsGivenPixelsAndFloodsTheRest) {
  Pass p(Grid(60, 40, twoPlanes, 4));
  const std::int32_t given = giveLeftColumns(p);
  p.pass.seedAndFlood(false, p.stats, p.phases);
  for (int v = 0; v < 40; ++v)
    for (int u = 0; u < 10; ++u) ASSERT_EQ(p.label(u, v), given) << u << ", " << v;
  // The rest of the left plane is flooded by a seed of its own, which touches the given pixels:
  // the two merge.
  p.pass.relabel();
  const MergedSegments merged = p.pass.merge(MergeCriterion(p.params, p.grid.tolerances));
  EXPECT_EQ(p.cluster(merged, 29, 20), p.cluster(merged, 0, 0));
  EXPECT_NE(p.cluster(merged, 30, 20), p.cluster(merged, 0, 0));
}

TEST(FloodPass, FloodsOnFromGivenPixelsToThePlanesEdge) {
  Pass p(Grid(60, 40, twoPlanes, 4));
  const std::int32_t given = giveLeftColumns(p);
  std::vector<std::size_t> starts;
  for (int v = 0; v < 40; ++v) starts.push_back(p.frame.index(9, v));  // the given pixels' edge
  p.pass.extend(given, starts, p.pass.segments()[static_cast<std::size_t>(given)].criterion, p.stats);
  for (int v = 0; v < 40; ++v)
    for (int u = 0; u < 60; ++u) ASSERT_EQ(p.label(u, v), u < 30 ? given : 0) << u << ", " << v;
  EXPECT_EQ(p.pass.segments()[static_cast<std::size_t>(given)].sums.count, 30.0 * 40.0);
}

}  // namespace
}  // namespace floodplane
