// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Beyond the paper: pieces of one plane cut apart by something in front of it are joined when
// every pixel of the gap between them is in front of the plane, on it, or has no return; never
// across pixels behind it (two coplanar tables with the floor between them stay two).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "regions/occlusion_merging.h"
#include "support/pinhole_grid.h"
#include "support/stage_fixture.h"

namespace floodplane {
namespace {

using Grid = test::PinholeGrid;
using test::exactParams;
using test::kNaN;
using test::kPinholePitch;

// A frame whose planes are labelled by string art ('.' none, digits: plane numbers 1..K,
// numbered by size as region output leaves them); each plane's sums are those of its pixels.
struct Frame {
  Grid grid;
  PlaneCandidates planes;  // and their label image
  Params params = exactParams();
  Tolerances tolerances;

  Frame(const std::vector<std::string>& art, const std::function<double(int, int)>& depth)
      : grid(static_cast<int>(art[0].size()), static_cast<int>(art.size()), depth) {
    const std::vector<std::uint32_t> image = test::labelsFromArt(art);
    tolerances = Tolerances(params, {}, 1.0 / test::kPinholeFocal, image.size());
    planes = test::planesOfLabels(grid, image, tolerances);
  }

  bool merge() {
    return OcclusionMerging().run(grid.grid(), planes, MergeCriterion(params, tolerances), tolerances, kPinholePitch);
  }
};

// Two pieces of a wall 3 m away, ten columns apart.
const std::vector<std::string> kTwoPieces = {
    "1111111111..........2222222222",  //
    "1111111111..........2222222222",  //
    "1111111111..........2222222222",  //
    "1111111111..........2222222222",  //
    "1111111111..........2222222222",  //
    "1111111111..........2222222222",  //
};
bool inGap(int u) { return u >= 10 && u < 20; }

TEST(OcclusionMerging, JoinsPiecesOfAWallBehindAColumn) {
  // The gap is a column 1 m in front of the wall.
  Frame f(kTwoPieces, [](int u, int) { return inGap(u) ? 2.0 : 3.0; });
  for (PlaneCandidate& plane : f.planes.list()) plane.criterion = FloodCriterion();  // to be made anew
  ASSERT_TRUE(f.merge());
  ASSERT_EQ(f.planes.list().size(), 1u);
  EXPECT_EQ(f.planes.remap(1), 1u);
  EXPECT_EQ(f.planes.remap(2), 1u);
  EXPECT_DOUBLE_EQ(f.planes[1].sums.count, 120.0);
  EXPECT_EQ(f.planes[1].first_pixel, 0u);
  // The merged plane's criterion is that of its whole sums.
  EXPECT_NEAR(f.planes[1].criterion.offset, 3.0f, 1e-4f);
  EXPECT_NEAR(f.planes[1].criterion.normal.z, -1.0f, 1e-5f);
}

TEST(OcclusionMerging, JoinsPiecesAcrossPixelsWithoutAReturn) {
  Frame f(kTwoPieces, [](int u, int) { return inGap(u) ? kNaN : 3.0; });
  ASSERT_TRUE(f.merge());
  EXPECT_EQ(f.planes.list().size(), 1u);
}

TEST(OcclusionMerging, JoinsPiecesAcrossUnlabelledPixelsOnThePlane) {
  Frame f(kTwoPieces, [](int, int) { return 3.0; });
  ASSERT_TRUE(f.merge());
  EXPECT_EQ(f.planes.list().size(), 1u);
}

TEST(OcclusionMerging, KeepsTwoCoplanarTablesWithTheFloorBetweenThemApart) {
  // The gap sees something 1 m behind the plane of the two pieces.
  Frame f(kTwoPieces, [](int u, int) { return inGap(u) ? 4.0 : 3.0; });
  EXPECT_FALSE(f.merge());
  ASSERT_EQ(f.planes.list().size(), 2u);
  EXPECT_EQ(f.planes.remap(1), 1u);
  EXPECT_EQ(f.planes.remap(2), 2u);
  EXPECT_DOUBLE_EQ(f.planes[1].sums.count, 60.0);
}

TEST(OcclusionMerging, OnePixelBehindThePlaneKeepsThemApart) {
  // An occluder everywhere but at one pixel, through which the room behind is seen.
  Frame f(kTwoPieces, [](int u, int v) { return u == 15 && v == 3 ? 4.0 : inGap(u) ? 2.0 : 3.0; });
  EXPECT_FALSE(f.merge());
  EXPECT_EQ(f.planes.list().size(), 2u);
}

TEST(OcclusionMerging, APixelOfThePlaneJustOutsideItsBandDoesNotKeepThemApart) {
  // 1.5 cm behind: beyond the 1 cm plane tolerance (the flood left it out), within two.
  Frame behind_band(kTwoPieces, [](int u, int v) { return u == 15 && v == 3 ? 3.015 : 3.0; });
  EXPECT_TRUE(behind_band.merge());
  // 3 cm behind is beyond two tolerances: a surface behind.
  Frame behind_twice(kTwoPieces, [](int u, int v) { return u == 15 && v == 3 ? 3.03 : 3.0; });
  EXPECT_FALSE(behind_twice.merge());
}

TEST(OcclusionMerging, JoinsPiecesOfAWallBehindALabelledOccluder) {
  // The column is a plane of its own (3), in front of the wall.
  const std::vector<std::string> art = {
      "1111111111..333333..2222222222",  //
      "1111111111..333333..2222222222",  //
      "1111111111..333333..2222222222",  //
      "1111111111..333333..2222222222",  //
      "1111111111..333333..2222222222",  //
      "1111111111..333333..2222222222",  //
  };
  Frame f(art, [](int u, int) { return inGap(u) ? 2.0 : 3.0; });
  ASSERT_TRUE(f.merge());
  ASSERT_EQ(f.planes.list().size(), 2u);
  EXPECT_EQ(f.planes.remap(1), 1u);
  EXPECT_EQ(f.planes.remap(2), 1u);
  EXPECT_EQ(f.planes.remap(3), 2u);
  EXPECT_DOUBLE_EQ(f.planes[2].sums.count, 36.0);
}

TEST(OcclusionMerging, NumbersTheJoinedPlaneBySize) {
  // Pieces 2 and 3 (60 pixels each) join into 120, more than plane 1 (90), a parallel plane
  // half a metre in front that does not fit theirs.
  const std::vector<std::string> art = {
      "2222222222..........3333333333",  //
      "2222222222..........3333333333",  //
      "2222222222..........3333333333",  //
      "2222222222..........3333333333",  //
      "2222222222..........3333333333",  //
      "2222222222..........3333333333",  //
      "111111111111111111111111111111",  //
      "111111111111111111111111111111",  //
      "111111111111111111111111111111",  //
  };
  Frame f(art, [](int u, int v) { return v >= 6 ? 2.5 : inGap(u) ? 2.0 : 3.0; });
  ASSERT_TRUE(f.merge());
  ASSERT_EQ(f.planes.list().size(), 2u);
  EXPECT_EQ(f.planes.remap(1), 2u);
  EXPECT_EQ(f.planes.remap(2), 1u);
  EXPECT_EQ(f.planes.remap(3), 1u);
  EXPECT_DOUBLE_EQ(f.planes[1].sums.count, 120.0);
  EXPECT_DOUBLE_EQ(f.planes[2].sums.count, 90.0);
}

TEST(OcclusionMerging, JoinsPiecesAboveAndBelowAnOccluderAlongTheirColumns) {
  const std::vector<std::string> art = {
      "11111111",  //
      "11111111",  //
      "11111111",  //
      "........",  //
      "........",  //
      "22222222",  //
      "22222222",  //
      "22222222",  //
  };
  Frame f(art, [](int, int v) { return v == 3 || v == 4 ? 2.0 : 3.0; });
  ASSERT_TRUE(f.merge());
  EXPECT_EQ(f.planes.list().size(), 1u);
}

TEST(OcclusionMerging, KeepsPiecesThatShareNoRowOrColumnApart) {
  // Diagonal pieces with an occluder everywhere else: no pixels between them to judge.
  const std::vector<std::string> art = {
      "1111........",  //
      "1111........",  //
      "1111........",  //
      "........2222",  //
      "........2222",  //
      "........2222",  //
  };
  Frame f(art, [](int u, int v) { return (v < 3 && u < 4) || (v >= 3 && u >= 8) ? 3.0 : 2.0; });
  EXPECT_FALSE(f.merge());
  EXPECT_EQ(f.planes.list().size(), 2u);
}

TEST(OcclusionMerging, KeepsParallelPlanesApartWhateverIsBetweenThem) {
  // Plane 2 is 20 cm behind plane 1: Eq. 9 does not let them merge.
  Frame f(kTwoPieces, [](int u, int) { return inGap(u) ? 2.0 : u < 10 ? 3.0 : 3.2; });
  EXPECT_FALSE(f.merge());
  EXPECT_EQ(f.planes.list().size(), 2u);
}

TEST(OcclusionMerging, KeepsPlanesAtAnAngleApart) {
  // Plane 2 turns away by 0.3 rad about the vertical axis, through the middle of the gap.
  const double slope = std::tan(0.3);
  Frame f(kTwoPieces, [&](int u, int) {
    if (inGap(u)) return 2.0;
    if (u < 10) return 3.0;
    // Along pixel u's ray x = (u - cx) z / f, on z = 3 + slope (x - x_mid).
    const double ray = (u - 14.5) / test::kPinholeFocal;
    return 3.0 / (1.0 - slope * ray);
  });
  EXPECT_FALSE(f.merge());
  EXPECT_EQ(f.planes.list().size(), 2u);
}

TEST(OcclusionMerging, DoesNothingWithFewerThanTwoPlanes) {
  Frame none({"...."}, [](int, int) { return 3.0; });
  EXPECT_FALSE(none.merge());
  EXPECT_TRUE(none.planes.list().empty());
  Frame one({"1111", "1111", "1111"}, [](int, int) { return 3.0; });
  EXPECT_FALSE(one.merge());
  EXPECT_EQ(one.planes.list().size(), 1u);
}

TEST(OcclusionMerging, KeepsPlanesWithoutPixelsInTheImageApart) {
  // An all-NaN frame whose label image has no pixel of the two planes, whose sums are those
  // of two coplanar pieces: no pixels between them to judge.
  Frame pieces(kTwoPieces, [](int, int) { return 3.0; });
  Frame f({".........................", "........................."}, [](int, int) { return kNaN; });
  f.planes = pieces.planes;
  std::uint32_t* image = f.planes.newImage(f.grid.width, f.grid.height);
  std::fill(image, image + f.grid.width * f.grid.height, 0u);
  EXPECT_FALSE(f.merge());
  EXPECT_EQ(f.planes.list().size(), 2u);
}

TEST(OcclusionMerging, ReadsTheLabelsInThePlanesCurrentNumbers) {
  // The image carries the numbers it was written in; a sort by size has given the planes new
  // numbers since: the row below (image 3, a parallel plane in front) is plane 1 now, the left and right
  // pieces (images 1 and 2) planes 2 and 3. The floor is seen between the pieces.
  const std::vector<std::string> art = {
      "1111111111..........2222222222",  //
      "1111111111..........2222222222",  //
      "1111111111..........2222222222",  //
      "1111111111..........2222222222",  //
      "1111111111..........2222222222",  //
      "1111111111..........2222222222",  //
      "333333333333333333333333333333",  //
      "333333333333333333333333333333",  //
      "333333333333333333333333333333",  //
  };
  const auto depth = [](int u, int v) { return v >= 6 ? 2.5 : inGap(u) ? 4.0 : 3.0; };
  Frame f(art, depth);
  ASSERT_TRUE(f.planes.sortBySize(0, nullptr));
  ASSERT_EQ(f.planes.remap(3), 1u);
  ASSERT_EQ(f.planes.remap(1), 2u);
  ASSERT_EQ(f.planes.remap(2), 3u);
  // Read in the image's numbers, planes 2 and 3 (the pieces, by their sums) would be the right
  // piece and the row, which touch along the right piece's columns.
  EXPECT_FALSE(f.merge());
  // Seen through an occluder instead of the floor, the pieces (planes 2 and 3) join, and
  // outnumber the row.
  Frame g(art, [](int u, int v) { return v >= 6 ? 2.5 : inGap(u) ? 2.0 : 3.0; });
  ASSERT_TRUE(g.planes.sortBySize(0, nullptr));
  ASSERT_TRUE(g.merge());
  EXPECT_EQ(g.planes.remap(1), 2u);
  EXPECT_EQ(g.planes.remap(2), 1u);
  EXPECT_EQ(g.planes.remap(3), 1u);
  ASSERT_EQ(g.planes.list().size(), 2u);
  EXPECT_DOUBLE_EQ(g.planes[1].sums.count, 120.0);
  EXPECT_EQ(g.planes.labels()[g.grid.index(0, 0)], 1u);
  EXPECT_EQ(g.planes.labels()[g.grid.index(29, 5)], 1u);
  EXPECT_EQ(g.planes.labels()[g.grid.index(15, 7)], 2u);
  EXPECT_EQ(g.planes.labels()[g.grid.index(15, 0)], 0u);
}

}  // namespace
}  // namespace floodplane
