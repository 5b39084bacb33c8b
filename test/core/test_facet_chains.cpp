// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The facets of one body judged together (FacetChains): grids of block means seen through a
// pinhole, cut into facets by hand, with a block mean's noise of 2 mm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "coarse/facet_chains.h"
#include "support/pinhole_grid.h"

namespace floodplane {
namespace {

using Grid = test::PinholeGrid;

// The block means of `depth` on a w x h grid, cut into facets by `facet` (0: none), each
// facet's fit and sums, and FacetChains' verdict on them.
struct Chains {
  Grid grid;
  std::vector<std::uint32_t> facet_of_block;
  std::vector<PlaneSums> sums;
  std::vector<PlaneFit> fits;
  std::vector<bool> curved;

  Chains(int w, int h, const std::function<double(int, int)>& depth,
         const std::function<std::uint32_t(int, int)>& facet)
      : grid(w, h, depth) {
    std::uint32_t count = 0;
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u) {
        facet_of_block.push_back(facet(u, v));
        count = std::max(count, facet(u, v));
      }
    sums.assign(count, PlaneSums());
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u)
        if (const std::uint32_t k = facet(u, v)) sums[k - 1].add(grid.point(u, v));
    std::vector<const PlaneSums*> views;
    for (const PlaneSums& s : sums) {
      fits.push_back(s.fit());
      views.push_back(&s);
    }
    Params params;
    NoiseModel noise;
    noise.sigma_constant = 0.002;
    const Tolerances tolerances(params, noise, 1.0 / test::kPinholeFocal, grid.grid().size());
    curved.assign(count + 1, false);
    FacetChains chains;
    chains.judge(grid.grid(), facet_of_block, fits, views, tolerances, curved);
  }
  std::size_t curvedCount() const { return static_cast<std::size_t>(std::count(curved.begin(), curved.end(), true)); }
};

// Facets of 6 x 6 blocks (12 cm at 2 m), numbered from 1 across the grid.
std::uint32_t tiles(int u, int v) { return static_cast<std::uint32_t>(v / 6 * 5 + u / 6 + 1); }

TEST(FacetChains, JudgesTheFacetsOfABodyCurvedTogether) {
  // A parabolic cylinder 0.6 x 0.6 m at 1.9-2.1 m (a torso's bend), 25 facets of 12 cm: each
  // is flat within a few millimetres, neighbours meet at 10-30 degrees.
  const auto body = [](int u, int) {
    const double x = (u - 14.5) / test::kPinholeFocal * 2.0;
    return 1.9 + 2.0 * x * x;
  };
  Chains run(30, 30, body, tiles);
  EXPECT_EQ(run.curvedCount(), 25u);
}

TEST(FacetChains, LeavesTheFacesOfACreaseAlone) {
  // A roof: two planes meeting at about 90 degrees along a facet border. Each side's facets chain
  // (coplanar: the chain is flat), but not across the crease.
  const auto roof = [](int u, int) { return 2.0 + std::abs(u - 17.5) / test::kPinholeFocal * 2.0; };
  Chains run(30, 30, roof, tiles);
  EXPECT_EQ(run.curvedCount(), 0u);
}

TEST(FacetChains, LeavesASmallObjectToTheFacetPairs) {
  // The same bend over 24 cm (four facets of 6 cm): a bottle, a scanned part; shorter than a body.
  const auto bottle = [](int u, int) {
    const double x = (u - 5.5) / test::kPinholeFocal * 2.0;
    return 1.9 + 8.0 * x * x;
  };
  Chains run(12, 12, bottle, [](int u, int v) { return static_cast<std::uint32_t>(v / 6 * 2 + u / 6 + 1); });
  EXPECT_EQ(run.curvedCount(), 0u);
}

TEST(FacetChains, DoesNotChainALargePlane) {
  // A wall 0.8 m wide (one facet) with a body's facets along its right side: the wall is not a
  // facet of the body.
  const auto scene = [](int u, int) {
    if (u < 40) return 2.0;
    const double x = (u - 40) / test::kPinholeFocal * 2.0;
    return 2.0 - 0.5 * x - 2.0 * x * x;
  };
  const auto facets = [](int u, int v) {
    return u < 40 ? 1u : static_cast<std::uint32_t>(2 + v / 6 * 4 + (u - 40) / 6);
  };
  Chains run(64, 30, scene, facets);
  EXPECT_FALSE(run.curved[1]);
  EXPECT_GT(run.curvedCount(), 0u);  // the body's facets still are
}

}  // namespace
}  // namespace floodplane
