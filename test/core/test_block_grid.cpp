// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Coarse to fine, the one full-resolution read: a frame into s x s blocks with their measured
// pixels' counts, means, exact sums and depth spread, checked against the pixels one by one;
// four floats at a time against pixel by pixel; and the separation of the surfaces a block
// straddles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "frame/block_grid.h"
#include "support/pinhole_grid.h"
#include "util/simd.h"

namespace floodplane {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using Grid = test::PinholeGrid;

// A tilted plane with holes: every 7th pixel, and a 3 x 3 patch.
double tiltedWithHoles(int u, int v) {
  if ((u * 31 + v * 17) % 7 == 0) return kNaN;
  if (u >= 10 && u < 13 && v >= 4 && v < 7) return kNaN;
  return 2.0 + 0.01 * u + 0.005 * v;
}

// The sums of block (bx, by)'s finite points, pixel by pixel.
PlaneSums blockSums(const Grid& grid, int s, int bx, int by) {
  PlaneSums sums;
  for (int v = by * s; v < std::min(by * s + s, grid.height); ++v)
    for (int u = bx * s; u < std::min(bx * s + s, grid.width); ++u) {
      const Vec3 p = grid.point(u, v);
      if (std::isfinite(p.z)) sums.add(p);
    }
  return sums;
}

TEST(BlockGrid, SumsEachBlocksMeasuredPixels) {
  for (const int s : {2, 4}) {
    for (const auto& [width, height] : {std::pair{24, 16}, std::pair{27, 13}}) {
      SCOPED_TRACE(::testing::Message() << "s = " << s << ", " << width << " x " << height);
      const Grid grid(width, height, tiltedWithHoles, 4);
      BlockGrid blocks;
      blocks.read(grid.grid(), s);
      const PointGrid& means = blocks.means();
      ASSERT_EQ(means.width, (width + s - 1) / s);
      ASSERT_EQ(means.height, (height + s - 1) / s);
      ASSERT_EQ(means.stride, 4u);
      for (int by = 0; by < means.height; ++by)
        for (int bx = 0; bx < means.width; ++bx) {
          const std::size_t i = static_cast<std::size_t>(by * means.width + bx);
          const PlaneSums expected = blockSums(grid, s, bx, by);
          ASSERT_EQ(blocks.count(i), static_cast<std::uint32_t>(expected.count)) << bx << ", " << by;
          const int w = std::min(s, width - bx * s), h = std::min(s, height - by * s);
          EXPECT_EQ(blocks.area(i), static_cast<std::uint32_t>(w * h));
          EXPECT_EQ(blocks.complete(i), expected.count == w * h);
          if (expected.count == 0) {
            EXPECT_FALSE(means.isFinite(i));
            continue;
          }
          const Eigen::Vector3d mean = expected.centroid();
          const Vec3 m = Vec3::load(means.point(i));
          EXPECT_NEAR(m.x, mean.x(), 1e-6);
          EXPECT_NEAR(m.y, mean.y(), 1e-6);
          EXPECT_NEAR(m.z, mean.z(), 1e-6);
          // The sums reproduce the pixels' own, covariance included.
          const PlaneSums sums = blocks.sums(i);
          EXPECT_DOUBLE_EQ(sums.count, expected.count);
          const Eigen::Vector3d centroid = Eigen::Vector3d(sums.sx, sums.sy, sums.sz) / sums.count;
          EXPECT_NEAR((centroid - mean).norm(), 0.0, 1e-6);
          const auto covariance = [](const PlaneSums& q) {
            const Eigen::Vector3d c(q.sx / q.count, q.sy / q.count, q.sz / q.count);
            Eigen::Matrix3d products;
            products << q.sxx, q.sxy, q.sxz, q.sxy, q.syy, q.syz, q.sxz, q.syz, q.szz;
            return Eigen::Matrix3d(products / q.count - c * c.transpose());
          };
          EXPECT_LT((covariance(sums) - covariance(expected)).norm(), 1e-8);
        }
    }
  }
}

TEST(BlockGrid, ReadsFourFloatsAtATimeAsPixelByPixel) {
  if (!simdEnabled()) GTEST_SKIP() << "built without SIMD (FLOODPLANE_SIMD=OFF): there is no four-float path";
  // Three floats a point go pixel by pixel, four floats a point four at a time.
  const Grid packed(30, 22, tiltedWithHoles, 3), padded(30, 22, tiltedWithHoles, 4);
  for (const int s : {2, 4, 8}) {
    BlockGrid a, b;
    a.read(packed.grid(), s);
    b.read(padded.grid(), s);
    for (std::size_t i = 0; i < a.means().size(); ++i) {
      ASSERT_EQ(a.count(i), b.count(i));
      ASSERT_EQ(std::memcmp(a.means().point(i), b.means().point(i), 3 * sizeof(float)), 0) << "block " << i;
      ASSERT_EQ(std::memcmp(a.scatter(i), b.scatter(i), 3 * sizeof(float)), 0) << "block " << i;
      ASSERT_EQ(std::memcmp(a.scatter(i) + 4, b.scatter(i) + 4, 3 * sizeof(float)), 0) << "block " << i;
    }
  }
}

TEST(BlockGrid, GivesTheMeanSquaredDistanceOfItsPixelsFromAPlane) {
  const Grid grid(16, 16, tiltedWithHoles, 4);
  BlockGrid blocks;
  blocks.read(grid.grid(), 4);
  const Vec3 normal{0.f, 0.6f, -0.8f};
  const float offset = 1.9f;
  for (int by = 0; by < 4; ++by)
    for (int bx = 0; bx < 4; ++bx) {
      const std::size_t i = static_cast<std::size_t>(by * 4 + bx);
      double sum = 0.0;
      int n = 0;
      for (int v = by * 4; v < by * 4 + 4; ++v)
        for (int u = bx * 4; u < bx * 4 + 4; ++u) {
          const Vec3 p = grid.point(u, v);
          if (!std::isfinite(p.z)) continue;
          const double d = normal.dot(p) + offset;
          sum += d * d;
          ++n;
        }
      if (n == 0) continue;
      EXPECT_NEAR(blocks.meanSquaredDistance(i, normal, offset), sum / n, 1e-5 * sum / n) << i;
    }
}

TEST(BlockGrid, AddsItsMeanOncePerMeasuredPixel) {
  const Grid grid(8, 8, tiltedWithHoles, 4);
  BlockGrid blocks;
  blocks.read(grid.grid(), 4);
  PlaneSums sums;
  blocks.addMeanTo(0, sums);
  const Vec3 m = Vec3::load(blocks.means().point(0));
  EXPECT_DOUBLE_EQ(sums.count, blocks.count(0));
  EXPECT_NEAR(sums.sz, blocks.count(0) * static_cast<double>(m.z), 1e-9);
  EXPECT_NEAR(sums.szz, blocks.count(0) * static_cast<double>(m.z) * m.z, 1e-9);
}

TEST(BlockGrid, KeepsTheSurfaceOfTheFirstPixelWhereABlockStraddlesAStep) {
  // A wall at 2 m with a box 20 cm in front of it over columns 6-9 (neighbouring pixels are
  // 2 cm apart there): block 1 (columns 4-7) holds both; its first pixel is on the wall. A
  // tilted plane's blocks are one surface.
  const auto depth = [](int u, int) { return u >= 6 && u < 10 ? 1.8 : 2.0; };
  const Grid grid(16, 8, depth, 4);
  BlockGrid blocks;
  blocks.read(grid.grid(), 4);
  NoiseModel noise;  // exact data
  blocks.separateSurfaces(grid.grid(), noise, static_cast<float>(1.0 / test::kPinholeFocal));
  EXPECT_TRUE(blocks.split(1));
  EXPECT_EQ(blocks.count(1), 8u);  // columns 4 and 5 of its two rows
  EXPECT_NEAR(blocks.means().point(1)[2], 2.0, 1e-6);
  EXPECT_FALSE(blocks.split(0));
  EXPECT_TRUE(blocks.split(2));  // columns 8-11: its first pixel on the board
  EXPECT_NEAR(blocks.means().point(2)[2], 1.8, 1e-6);
  EXPECT_FALSE(blocks.complete(1));

  const Grid tilted(
      16, 8, [](int u, int v) { return 2.0 + 0.015 * u + 0.01 * v; }, 4);
  blocks.read(tilted.grid(), 4);
  blocks.separateSurfaces(tilted.grid(), noise, static_cast<float>(1.0 / test::kPinholeFocal));
  for (std::size_t i = 0; i < blocks.means().size(); ++i) EXPECT_FALSE(blocks.split(i)) << i;
}

TEST(BlockGrid, JoinsABlocksPixelsThroughAnyPathOfSmallSteps) {
  // Exact data at 2 m, pixels 0.01 rad apart: one surface steps up to 8 cm between neighbours.
  // One block of 4 x 4: rows 0-1 flat, rows 2-3 rising to the left in steps of 5 cm, 15 cm
  // above row 1 in column 0. Each row is one surface and column 0 is cut between rows 1 and 2,
  // but column 3 joins them: one surface.
  const auto joined = [](int u, int v) { return v < 2 ? 2.0 : 2.0 + 0.05 * (3 - u); };
  const Grid grid(4, 4, joined, 4);
  BlockGrid blocks;
  blocks.read(grid.grid(), 4);
  NoiseModel noise;
  blocks.separateSurfaces(grid.grid(), noise, static_cast<float>(1.0 / test::kPinholeFocal));
  EXPECT_FALSE(blocks.split(0));
  EXPECT_EQ(blocks.count(0), 16u);
  // The same rows with column 3 cut as well (rows 2-3 15 cm up everywhere): two surfaces.
  const Grid cut(
      4, 4, [](int, int v) { return v < 2 ? 2.0 : 2.15; }, 4);
  blocks.read(cut.grid(), 4);
  blocks.separateSurfaces(cut.grid(), noise, static_cast<float>(1.0 / test::kPinholeFocal));
  EXPECT_TRUE(blocks.split(0));
  EXPECT_EQ(blocks.count(0), 8u);
  EXPECT_NEAR(blocks.means().point(0)[2], 2.0, 1e-6);
}

TEST(BlockGrid, LeavesANoisySurfaceWhole) {
  // Depth noise of 5 mm at 2 m: within what two neighbouring pixels of one surface can differ.
  const auto depth = [](int u, int v) { return 2.0 + 0.005 * std::sin(u * 12.9898 + v * 78.233); };
  const Grid grid(16, 16, depth, 4);
  BlockGrid blocks;
  blocks.read(grid.grid(), 4);
  NoiseModel noise;
  noise.sigma_constant = 0.005;
  blocks.separateSurfaces(grid.grid(), noise, static_cast<float>(1.0 / test::kPinholeFocal));
  for (std::size_t i = 0; i < blocks.means().size(); ++i) EXPECT_FALSE(blocks.split(i)) << i;
}

}  // namespace
}  // namespace floodplane
