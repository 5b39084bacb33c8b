// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Beyond the paper: two touching planes that Eq. 9 keeps apart over their whole extent are one
// plane the sensor bent when they pass it where they meet (bands along their border), the
// border shows no step and their union is not curved; a crease or a step keeps them apart.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "models/facet_pairs.h"
#include "models/planarity_test.h"
#include "regions/bend_merging.h"
#include "support/pinhole_grid.h"
#include "support/stage_fixture.h"

namespace floodplane {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A wall 2 m away facing the camera, `width` x `height` pixels (2 cm each): plane 1 left of
// column `split`, plane 2 from it on, whose depth beyond the split at X0 is
// 2 + offset + bend (X - X0)^2 + (X - X0) tan(degrees).
struct Wall {
  test::PinholeGrid grid;
  PlaneCandidates planes;
  Params params = test::exactParams();
  Tolerances tolerances;
  PlanarityTest planarity;
  std::vector<PlaneFit> fits;

  Wall(double bend, double degrees, double offset, int width = 40, int height = 16, int split = 20)
      : grid(width, height, [=](int u, int) {
          const double x = (u - (width - 1) / 2.0) / test::kPinholeFocal;
          if (u < split) return 2.0;
          const double x0 = (split - 0.5 - (width - 1) / 2.0) / test::kPinholeFocal * 2.0;
          // z = 2 + offset + bend (X - X0)^2 + (X - X0) t with X = x z: the root of
          // bend x^2 z^2 + (t x - 2 bend x X0 - 1) z + 2 + offset + bend X0^2 - t X0 = 0 near 2.
          const double t = std::tan(degrees * kPi / 180.0);
          double z = 2.0;
          for (int i = 0; i < 50; ++i) {
            const double d = x * z - x0;
            z = 2.0 + offset + bend * d * d + d * t;
          }
          return z;
        }) {
    std::vector<std::uint32_t> image;
    for (int v = 0; v < height; ++v)
      for (int u = 0; u < width; ++u) image.push_back(u < split ? 1u : 2u);
    tolerances = Tolerances(params, {}, 1.0 / test::kPinholeFocal, image.size());
    planes = test::planesOfLabels(grid, image, tolerances);
    for (const PlaneCandidate& plane : planes.list()) fits.push_back(plane.sums.fit());
    planarity.reset(fits);
    for (std::size_t i = 0; i < image.size(); ++i) planarity.add(image[i], grid.point(i));
  }

  // Whether Eq. 9 merges the two planes over their whole extent.
  bool mergeableAsAWhole() const {
    double cost = 0.0;
    return MergeCriterion(params, tolerances)
        .mergeable(planes.list()[0].sums, fits[0], planes.list()[1].sums, fits[1], cost);
  }

  // The bend merging's groups of the touching pairs (FacetPairs), `curved` the planes judged
  // curved alone.
  bool judge(std::vector<std::uint32_t>& group, const std::vector<bool>& curved = {false, false, false}) {
    FacetPairs pairs;
    pairs.find(grid.grid(), planes.labels(), planes.list(), fits, {false, true, true});
    std::vector<bool> union_bends;
    for (const auto& [k, l] : pairs.pairs()) {
      PlaneSums joint = planes.list()[k - 1].sums;
      joint.merge(planes.list()[l - 1].sums);
      bool bends = false;
      planarity.curvedPair(k, l, joint.fit(), tolerances, &bends);
      union_bends.push_back(bends);
    }
    BendMerging merging;
    return merging.judge(grid.grid(), planes.labels(), pairs, union_bends, planes.list(), curved, planarity,
                         MergeCriterion(params, tolerances), group);
  }
};

TEST(BendMerging, JoinsAPlaneThatBendsAwayWithoutACrease) {
  // Plane 2 leaves plane 1's plane smoothly (tangent at the border, 9 degrees at its far end,
  // a radius of 2.5 m): as a whole it fails Eq. 9, where the two meet it is one plane.
  Wall wall(0.2, 0.0, 0.0);
  ASSERT_FALSE(wall.mergeableAsAWhole());
  std::vector<std::uint32_t> group;
  ASSERT_TRUE(wall.judge(group));
  ASSERT_EQ(group.size(), 3u);
  EXPECT_EQ(group[1], group[2]);
}

TEST(BendMerging, KeepsACreaseApart) {
  // Plane 2 turns 20 degrees away at the border.
  Wall wall(0.0, 20.0, 0.0);
  std::vector<std::uint32_t> group;
  EXPECT_FALSE(wall.judge(group));
  ASSERT_EQ(group.size(), 3u);
  EXPECT_NE(group[1], group[2]);
}

TEST(BendMerging, KeepsAStepApart) {
  // Plane 2 parallel, 2 cm behind plane 1 (a board on a wall seen from the board).
  Wall wall(0.0, 0.0, 0.02);
  std::vector<std::uint32_t> group;
  EXPECT_FALSE(wall.judge(group));
}

TEST(BendMerging, JoinsACurvedPieceToALargePlaneItBends) {
  // The bent pair of the first test with plane 2 judged curved alone (a warped table's corner):
  // plane 1 spans 1.2 m both ways, more than the radius of a curved thing of a room.
  Wall wall(0.2, 0.0, 0.0, 80, 60, 60);
  std::vector<std::uint32_t> group;
  ASSERT_TRUE(wall.judge(group, {false, false, true}));
  EXPECT_EQ(group[1], group[2]);
}

TEST(BendMerging, JoinsNoCurvedPieceToASmallPlane) {
  // The same with plane 1 0.4 m x 0.32 m: as narrow as a body's facet.
  Wall wall(0.2, 0.0, 0.0);
  std::vector<std::uint32_t> group;
  EXPECT_FALSE(wall.judge(group, {false, false, true}));
  EXPECT_NE(group[1], group[2]);
}

TEST(BendMerging, JoinsNoTwoCurvedPlanes) {
  Wall wall(0.2, 0.0, 0.0, 80, 60, 60);
  std::vector<std::uint32_t> group;
  EXPECT_FALSE(wall.judge(group, {false, true, true}));
}

}  // namespace
}  // namespace floodplane
