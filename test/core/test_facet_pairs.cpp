// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The candidate facet pairs (FacetPairs): planes that touch along enough pixel pairs whose
// points are 3-D neighbours, with normals close enough to be facets of one curved surface.
// Whether a pair is one surface is the planarity test's (test_planarity.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "models/facet_pairs.h"
#include "models/plane_candidates.h"
#include "support/pinhole_grid.h"

namespace floodplane {
namespace {

constexpr double kFocal = test::kPinholeFocal;
constexpr double kPi = 3.14159265358979323846;
constexpr int kWidth = 40, kHeight = 30;

// Two planes side by side, split at column 20: plane 1 on the left faces the camera at 2 m,
// plane 2 on the right turns from it by `degrees` about the vertical at the split and lies
// `step` metres further back. Rows from `first_row` on (above it no plane: label 0).
struct TwoPlanes {
  test::PinholeGrid grid;
  std::vector<std::uint32_t> image;
  std::vector<PlaneCandidate> planes;
  std::vector<PlaneFit> fits;

  TwoPlanes(double degrees, double step, int first_row = 0)
      : grid(kWidth, kHeight, [degrees, step](int u, int) {
          const double x = (u - (kWidth - 1) / 2.0) / kFocal;  // the ray's x per unit depth
          const double split = (20 - (kWidth - 1) / 2.0) / kFocal * 2.0;
          if (u < 20) return 2.0;
          // z = 2 + step + (X - split) tan(degrees), X = x z.
          const double slope = std::tan(degrees * kPi / 180.0);
          return (2.0 + step - split * slope) / (1.0 - x * slope);
        }) {
    for (int v = 0; v < kHeight; ++v)
      for (int u = 0; u < kWidth; ++u) image.push_back(v < first_row ? 0u : (u < 20 ? 1u : 2u));
    Params params;
    params.distance_threshold = 0.01;
    const Tolerances tolerances(params, {}, 1.0 / kFocal, image.size());
    std::vector<PlaneSums> sums(2);
    for (std::size_t i = 0; i < image.size(); ++i)
      if (image[i] != 0) sums[image[i] - 1].add(grid.point(i));
    for (const PlaneSums& s : sums) {
      PlaneCandidate candidate;
      candidate.sums = s;
      candidate.criterion = planeCriterion(s.fit(), tolerances, static_cast<float>(1.0 / kFocal));
      planes.push_back(candidate);
      fits.push_back(s.fit());
    }
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> find(const std::vector<bool>& eligible = {false, true, true}) {
    pairs.find(grid.grid(), PlainLabels{image.data()}, planes, fits, eligible);
    return pairs.pairs();
  }
  FacetPairs pairs;
};

using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

TEST(FacetPairs, PairsTwoPlanesThatMeetWithoutAStepAtAShallowAngle) {
  TwoPlanes scene(20.0, 0.0);
  EXPECT_EQ(scene.find(), (Pairs{{1, 2}}));
}

TEST(FacetPairs, VisitsThePixelPairsOfEachBorder) {
  // One pixel pair a row across the split at column 20: (19, v) on plane 1, (20, v) on plane 2.
  TwoPlanes scene(20.0, 0.0);
  ASSERT_EQ(scene.find(), (Pairs{{1, 2}}));
  std::vector<std::pair<std::size_t, std::size_t>> visited;
  scene.pairs.forEachPixelPair(0, [&](std::size_t i, std::size_t j) { visited.emplace_back(i, j); });
  ASSERT_EQ(visited.size(), static_cast<std::size_t>(kHeight));
  for (int v = 0; v < kHeight; ++v) {
    const std::size_t i = static_cast<std::size_t>(v * kWidth + 19);
    EXPECT_EQ(visited[static_cast<std::size_t>(v)], std::make_pair(i, i + 1));
  }
}

TEST(FacetPairs, DoesNotPairPlanesThatTouchOnlyInTheImage) {
  // Plane 2 half a metre behind plane 1: their border pixels are no 3-D neighbours.
  TwoPlanes scene(20.0, 0.5);
  EXPECT_TRUE(scene.find().empty());
}

TEST(FacetPairs, DoesNotPairPlanesMeetingAtMoreThanTheLargestFacetAngle) {
  TwoPlanes scene(FacetPairs::kMaximumAngle * 180.0 / kPi + 10.0, 0.0);
  EXPECT_TRUE(scene.find().empty());
}

TEST(FacetPairs, NeedsABorderOfTheSmallestLength) {
  // The border runs down the rows that carry planes: one pixel pair a row.
  TwoPlanes shorter(20.0, 0.0, kHeight - static_cast<int>(FacetPairs::kMinimumBorder) + 1);
  EXPECT_TRUE(shorter.find().empty());
  TwoPlanes just(20.0, 0.0, kHeight - static_cast<int>(FacetPairs::kMinimumBorder));
  EXPECT_EQ(just.find(), (Pairs{{1, 2}}));
}

TEST(FacetPairs, PairsOnlyEligiblePlanes) {
  TwoPlanes scene(20.0, 0.0);
  EXPECT_TRUE(scene.find({false, true, false}).empty());
}

TEST(FacetPairs, ReadsThePlanesImageInTheirCurrentNumbers) {
  // A third plane without a pixel in the image outgrows the two: after the sort by size, the
  // image's planes 1 and 2 are planes 2 and 3, and plane 1 is not eligible. (Read in the
  // image's numbers, the pair would be (1, 2), and left out.)
  TwoPlanes scene(20.0, 0.0);
  PlaneCandidates planes;
  PlaneCandidate third = scene.planes[0];
  third.sums.count = 10000.0;
  planes.list() = {scene.planes[0], scene.planes[1], third};
  std::copy(scene.image.begin(), scene.image.end(), planes.newImage(kWidth, kHeight));
  ASSERT_TRUE(planes.sortBySize(0, nullptr));
  ASSERT_EQ(planes.remap(3), 1u);
  ASSERT_EQ(planes.remap(1), 2u);
  const std::vector<PlaneFit> fits = {scene.fits[0], scene.fits[0], scene.fits[1]};
  FacetPairs pairs;
  pairs.find(scene.grid.grid(), planes.labels(), planes.list(), fits, {false, false, true, true});
  EXPECT_EQ(pairs.pairs(), (Pairs{{2, 3}}));
}

}  // namespace
}  // namespace floodplane
