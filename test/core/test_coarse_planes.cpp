// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Coarse to fine: the coarse pass over the block means finds the big planes, and their inner
// blocks are given to the fine pass before its first seed; the planes then flood on into the
// pixels around. Exact pinhole grids of frontal planes, a board in front of a wall, a hole, a
// curved surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "coarse/coarse_planes.h"
#include "flood/flood_pass.h"
#include "frame/hole_filling.h"
#include "support/pinhole_grid.h"

namespace floodplane {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr float kPitch = static_cast<float>(1.0 / test::kPinholeFocal);

using Grid = test::PinholeGrid;

// The coarse pass over `frame` read in blocks of s x s, its coarse planes, and the fine pass
// they start, as Segmenter runs them on exact data.
struct CoarseToFine {
  Grid frame;
  Params params;
  BlockGrid blocks;
  HoleFilling block_holes;
  HoleFilling pixel_holes;  // nothing filled: the grid has few holes
  FloodGrid coarse_grid;
  FloodGrid fine_grid;
  FloodPass coarse;
  CoarsePlanes planes;
  FloodPass fine;
  SegmentationStats stats;
  std::size_t claimed = 0;

  CoarseToFine(Grid grid, int s) : frame(std::move(grid)) {
    params.depth_noise_constant = 0.0;
    params.depth_noise_coefficient = 0.0;
    params.subsampling = s;
    params.min_inliers = 50;
    const NoiseModel exact;
    const std::size_t pixels = frame.grid().size();
    const Tolerances measured_tolerances(params, exact, kPitch, pixels);
    blocks.read(frame.grid(), s);
    blocks.separateSurfaces(frame.grid(), exact, kPitch);
    coarse_grid.pitch = kPitch * static_cast<float>(s);
    coarse_grid.tolerances = Tolerances(params, exact, coarse_grid.pitch, pixels);
    coarse_grid.points = block_holes.fill(blocks.means(), coarse_grid.tolerances);
    coarse_grid.factor = s;
    coarse_grid.noise_free = true;
    coarse.begin(coarse_grid, params);
    PhaseTimes phases;
    coarse.seedAndFlood(false, stats, phases);
    coarse.relabel();
    const MergedSegments clusters = coarse.merge(MergeCriterion(params, coarse_grid.tolerances));
    planes.find(blocks, coarse_grid, coarse, clusters, params, measured_tolerances);
    fine_grid.points = pixel_holes.fill(frame.grid(), measured_tolerances);
    fine_grid.tolerances = measured_tolerances;
    fine_grid.pitch = kPitch;
    fine_grid.noise_free = true;
    fine.begin(fine_grid, params);
    claimed = planes.claim(blocks, fine_grid.points, pixel_holes, measured_tolerances, kPitch, fine, stats);
  }

  std::int32_t label(int u, int v) const { return fine.labels()[frame.index(u, v)]; }
};

// A frontal wall at 2 m.
double wall(int, int) { return 2.0; }

TEST(CoarsePlanes, GivesEveryPixelOfAWallThatFillsTheFrameToOneSegment) {
  for (const int s : {2, 4}) {
    CoarseToFine run(Grid(96, 64, wall, 4), s);
    ASSERT_EQ(run.planes.size(), 1u) << "s = " << s;
    EXPECT_EQ(run.claimed, 96u * 64u) << "s = " << s;
    for (const std::int32_t label : run.fine.labels()) ASSERT_EQ(label, run.label(0, 0)) << "s = " << s;
    // The segment has the wall's plane and every pixel's weight.
    const Segment& segment = run.fine.segments()[static_cast<std::size_t>(run.label(0, 0))];
    EXPECT_EQ(segment.sums.count, 96.0 * 64.0);
    const PlaneFit fit = segment.sums.fit();
    EXPECT_NEAR(std::abs(fit.normal.z()), 1.0, 1e-6);
    EXPECT_NEAR(fit.offset, 2.0, 1e-4);
  }
}

TEST(CoarsePlanes, LeavesABoardInFrontOfAWallToTheFinePass) {
  // A board 10 cm in front of the wall, 20 x 16 pixels, away from the block edges.
  const auto depth = [](int u, int v) { return u >= 37 && u < 57 && v >= 22 && v < 38 ? 1.9 : 2.0; };
  CoarseToFine run(Grid(96, 64, depth, 4), 4);
  ASSERT_GE(run.planes.size(), 1u);
  const std::int32_t wall_label = run.label(0, 0);
  ASSERT_NE(wall_label, 0);
  // The wall's flood stops at the board: no board pixel is the wall's, every wall pixel is.
  for (int v = 0; v < 64; ++v)
    for (int u = 0; u < 96; ++u) {
      const bool board = depth(u, v) < 2.0;
      if (board)
        EXPECT_NE(run.label(u, v), wall_label) << u << ", " << v;
      else
        EXPECT_EQ(run.label(u, v), wall_label) << u << ", " << v;
    }
  // Some wall pixels around the board were not given as inner blocks: the flood reached them.
  EXPECT_LT(run.claimed, static_cast<std::size_t>(96 * 64 - 20 * 16));
}

TEST(CoarsePlanes, FloodsAPocketInsideAPlaneOnlyWhereItFits) {
  // A 4 x 4 patch 5 cm (2.5 pixel footprints) in front of the wall (one block at s = 4, with the wall all around): the
  // wall floods into the pocket with its plane there, and stops at the patch.
  const auto depth = [](int u, int v) { return u >= 40 && u < 44 && v >= 28 && v < 32 ? 1.95 : 2.0; };
  CoarseToFine run(Grid(96, 64, depth, 4), 4);
  const std::int32_t wall_label = run.label(0, 0);
  ASSERT_NE(wall_label, 0);
  for (int v = 0; v < 64; ++v)
    for (int u = 0; u < 96; ++u) {
      if (depth(u, v) < 2.0)
        EXPECT_NE(run.label(u, v), wall_label) << u << ", " << v;
      else
        EXPECT_EQ(run.label(u, v), wall_label) << u << ", " << v;
    }
}

TEST(CoarsePlanes, GivesNoHoleOfTheFrameToAPlane) {
  const auto depth = [](int u, int v) {
    return (u == 40 && v == 30) || (u >= 60 && u < 64 && v >= 8 && v < 12) ? kNaN : 2.0;
  };
  CoarseToFine run(Grid(96, 64, depth, 4), 4);
  ASSERT_EQ(run.planes.size(), 1u);
  EXPECT_EQ(run.label(40, 30), 0);
  EXPECT_EQ(run.label(61, 9), 0);
  EXPECT_NE(run.label(41, 30), 0);
  EXPECT_EQ(run.label(41, 30), run.label(0, 0));
}

TEST(CoarsePlanes, TakesNoPlaneOnACurvedSurface) {
  // A cylinder of 40 cm radius seen side on, its axis vertical 2.4 m away, filling the frame:
  // every block lies on a smooth bend that a block alone cannot show.
  const auto depth = [](int u, int) {
    const double x = (u - 19.5) / test::kPinholeFocal * 2.0;  // about the lateral offset
    return 2.4 - std::sqrt(0.16 - x * x);
  };
  CoarseToFine run(Grid(40, 64, depth, 4), 4);
  EXPECT_EQ(run.planes.size(), 0u);
  EXPECT_EQ(run.claimed, 0u);
}

TEST(CoarsePlanes, FindsNothingInAFrameWithoutReturns) {
  CoarseToFine run(Grid(
                       32, 24, [](int, int) { return kNaN; }, 4),
                   4);
  EXPECT_EQ(run.planes.size(), 0u);
  EXPECT_EQ(run.claimed, 0u);
  for (const std::int32_t label : run.fine.labels()) EXPECT_EQ(label, 0);
}

}  // namespace
}  // namespace floodplane
