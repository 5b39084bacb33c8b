// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Seeds for what the seed lattice leaves (LeftoverSeeds): a region of unclaimed points that
// fits a plane seeds a flood with that plane; a curved or a small region does not.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <vector>

#include "models/tolerances.h"
#include "seeds/leftover_seeds.h"
#include "support/pinhole_grid.h"
#include "util/distance_buffer.h"

namespace floodplane {
namespace {

constexpr int kWidth = 60, kHeight = 40;

// Exact depths (no noise): the tolerances of exact data.
Tolerances exactTolerances() { return Tolerances(Params(), NoiseModel(), 1.0 / test::kPinholeFocal, kWidth * kHeight); }

// Every pixel claimed by segment 1 but columns [first, last).
DistanceBuffer claimedBut(int first, int last) {
  DistanceBuffer buffer;
  buffer.reset(kWidth * kHeight);
  for (int v = 0; v < kHeight; ++v)
    for (int u = 0; u < kWidth; ++u)
      if (u < first || u >= last) buffer.claim(static_cast<std::size_t>(v * kWidth + u), 1, 0.f);
  return buffer;
}

TEST(LeftoverSeeds, SeedsANarrowFlatStripWithItsPlane) {
  // A wall at 2 m turned 60 degrees about the vertical; a strip 6 pixels wide is unclaimed.
  const double slope = std::tan(60.0 * 3.14159265358979323846 / 180.0);
  const test::PinholeGrid grid(kWidth, kHeight, [slope](int u, int) {
    const double x = (u - (kWidth - 1) / 2.0) / test::kPinholeFocal;
    return 2.0 / (1.0 - x * slope);
  });
  const DistanceBuffer buffer = claimedBut(27, 33);
  LeftoverSeeds leftover;
  const std::vector<Seed>& seeds = leftover.find(grid.grid(), buffer, exactTolerances(), 100);
  ASSERT_EQ(seeds.size(), 1u);
  const Seed& seed = seeds[0];
  const int u = static_cast<int>(seed.index % kWidth);
  EXPECT_GE(u, 27);
  EXPECT_LT(u, 33);
  // The wall's normal, facing the sensor: (sin 60, 0, -cos 60) up to sign conventions of z.
  const Eigen::Vector3d expected = Eigen::Vector3d(slope, 0.0, -1.0).normalized();
  const Eigen::Vector3d normal(seed.normal.x, seed.normal.y, seed.normal.z);
  EXPECT_GT(std::abs(normal.dot(expected)), 0.999);
  EXPECT_GT(seed.spacing, 0.f);
}

TEST(LeftoverSeeds, LeavesACurvedRegionAndASmallOneUnseeded) {
  // A column (radius 10 cm, axis 1 m away) filling the view: no plane fits 20 of its columns.
  const test::PinholeGrid column(kWidth, kHeight, [](int u, int) {
    const double x = (u - (kWidth - 1) / 2.0) / test::kPinholeFocal;  // along the ray per unit depth
    // The nearer root of |(t x, t) - (0, 1.1)| = 0.1 in the x-z plane.
    const double a = x * x + 1.0, b = -2.0 * 1.1, c = 1.1 * 1.1 - 0.01;
    return (-b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  });
  LeftoverSeeds leftover;
  EXPECT_TRUE(leftover.find(column.grid(), claimedBut(20, 40), exactTolerances(), 100).empty());
  // A flat region of 2 x 40 = 80 pixels, under the 100 asked for.
  const test::PinholeGrid wall(kWidth, kHeight, [](int, int) { return 2.0; });
  EXPECT_TRUE(leftover.find(wall.grid(), claimedBut(29, 31), exactTolerances(), 100).empty());
  EXPECT_EQ(leftover.find(wall.grid(), claimedBut(29, 31), exactTolerances(), 80).size(), 1u);
}

}  // namespace
}  // namespace floodplane
