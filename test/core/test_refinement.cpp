// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Refinement (segmentAndRefine's counterpart): each plane grows, breadth first, into the
// unlabelled pixels next to it that fit it under its own thresholds; a margin pixel next to
// several planes goes to the one that explains it best; pixels no plane explains, holes and
// filled-in holes stay unlabelled. Hand-made label images over pinhole grids.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "regions/refinement.h"
#include "support/pinhole_grid.h"
#include "support/stage_fixture.h"

namespace floodplane {
namespace {

using Grid = test::PinholeGrid;
using test::kNaN;
using test::kPinholePitch;

// A frame labelled by string art ('.' none, digits: plane numbers); each plane's sums, first
// pixel and criterion are those of its labelled pixels, as region output hands them over.
struct Frame {
  Grid grid;
  PlaneCandidates planes;  // and their label image
  HoleFilling holes;       // none filled
  std::vector<std::size_t> queue;

  Frame(const std::vector<std::string>& art, const std::function<double(int, int)>& depth)
      : grid(static_cast<int>(art[0].size()), static_cast<int>(art.size()), depth) {
    Params params;
    params.distance_threshold = 0.01;  // the paper's sigma_plane; exact data
    const std::vector<std::uint32_t> labels = test::labelsFromArt(art);
    planes = test::planesOfLabels(grid, labels, Tolerances(params, {}, 1.0 / test::kPinholeFocal, labels.size()));
  }

  void refine() { refinePlanes(grid.grid(), holes, planes, queue); }
  // The plane of pixel i now.
  std::uint32_t label(std::size_t i) const { return planes.labels()[i]; }

  std::vector<std::string> art() const {
    std::vector<std::string> rows;
    for (int y = 0; y < grid.height; ++y) {
      std::string row;
      for (int x = 0; x < grid.width; ++x) {
        const std::uint32_t l = label(grid.index(x, y));
        row += l == 0 ? '.' : static_cast<char>('0' + l);
      }
      rows.push_back(row);
    }
    return rows;
  }
  // The sums of the pixels labelled k now.
  PlaneSums sumsOf(std::uint32_t k) const {
    PlaneSums sums;
    for (std::size_t i = 0; i < grid.data.size() / grid.stride; ++i)
      if (label(i) == k) sums.add(grid.point(i));
    return sums;
  }
};

void expectSameSums(const PlaneSums& actual, const PlaneSums& expected) {
  EXPECT_DOUBLE_EQ(actual.count, expected.count);
  EXPECT_NEAR(actual.sx, expected.sx, 1e-6);
  EXPECT_NEAR(actual.sy, expected.sy, 1e-6);
  EXPECT_NEAR(actual.sz, expected.sz, 1e-6);
  EXPECT_NEAR(actual.sxx, expected.sxx, 1e-6);
  EXPECT_NEAR(actual.szz, expected.szz, 1e-6);
}

double flat(int, int) { return 2.0; }

TEST(Refinement, GrowsAPlaneIntoTheUnlabelledPixelsThatFitIt) {
  // A margin the flood left, three pixels wide, and a notch in the plane.
  Frame f(
      {
          "11111111...",  //
          "11111111...",  //
          "111.1111...",  //
          "11111111...",  //
      },
      flat);
  f.refine();
  EXPECT_EQ(f.art(), (std::vector<std::string>{"11111111111", "11111111111", "11111111111", "11111111111"}));
  // The plane's sums follow.
  expectSameSums(f.planes[1].sums, f.sumsOf(1));
  EXPECT_DOUBLE_EQ(f.planes[1].sums.count, 44.0);
}

TEST(Refinement, GivesAMarginPixelToTheNeighbouringPlaneThatExplainsItBest) {
  // Two parallel planes 8 mm apart, both within sigma_plane (1 cm) of the margin column
  // between them. Its pixels lie 1 mm from one plane and 7 mm from the other, alternating.
  const auto depth = [](int u, int v) {
    if (u < 5) return 2.0;
    if (u > 5) return 2.008;
    return v % 2 == 0 ? 2.001 : 2.007;
  };
  Frame f(
      {
          "11111.22222",  //
          "11111.22222",  //
          "11111.22222",  //
          "11111.22222",  //
          "11111.22222",  //
      },
      depth);
  f.refine();
  for (int v = 0; v < 5; ++v) EXPECT_EQ(f.label(f.grid.index(5, v)), v % 2 == 0 ? 1u : 2u) << "row " << v;
  expectSameSums(f.planes[1].sums, f.sumsOf(1));
  expectSameSums(f.planes[2].sums, f.sumsOf(2));
  // Mirrored, the same.
  Frame mirrored(
      {
          "22222.11111",  //
          "22222.11111",  //
          "22222.11111",  //
          "22222.11111",  //
          "22222.11111",  //
      },
      [&](int u, int v) { return depth(10 - u, v); });
  mirrored.refine();
  for (int v = 0; v < 5; ++v) EXPECT_EQ(mirrored.label(mirrored.grid.index(5, v)), v % 2 == 0 ? 1u : 2u) << "row " << v;
}

TEST(Refinement, LeavesPixelsThatNoPlaneExplainsUnlabelled) {
  // A box 30 cm in front of the plane, and the plane's pixels behind it that no labelled
  // pixel of it reaches; a hole.
  const auto depth = [](int u, int v) { return u == 3 ? 1.7 : (u == 1 && v == 1) ? kNaN : 2.0; };
  Frame f(
      {
          "....11111",  //
          "....11111",  //
          "....11111",  //
      },
      depth);
  f.refine();
  EXPECT_EQ(f.art(), (std::vector<std::string>{"....11111", "....11111", "....11111"}));
  EXPECT_DOUBLE_EQ(f.planes[1].sums.count, 15.0);
}

TEST(Refinement, DoesNotReachPixelsOfThePlaneBeyondAHole) {
  // A column without returns between the plane's labelled pixels and more of it: the growth
  // goes from pixel to pixel, and a hole passes no test.
  Frame f({"111.....", "111....."}, [](int u, int) { return u == 4 ? kNaN : 2.0; });
  f.refine();
  EXPECT_EQ(f.art(), (std::vector<std::string>{"1111....", "1111...."}));
}

TEST(Refinement, DoesNotGrowOverADepthStep) {
  // Unlabelled pixels of a parallel surface 10 cm behind: off the plane.
  Frame f({"1111....", "1111...."}, [](int u, int) { return u < 4 ? 2.0 : 2.1; });
  f.refine();
  EXPECT_EQ(f.art(), (std::vector<std::string>{"1111....", "1111...."}));
}

TEST(Refinement, LeavesHolesUnlabelled) {
  Frame f({"11111", "11.11", "11111"}, [](int u, int v) { return u == 2 && v == 1 ? kNaN : 2.0; });
  f.refine();
  EXPECT_EQ(f.label(f.grid.index(2, 1)), 0u);
  EXPECT_DOUBLE_EQ(f.planes[1].sums.count, 14.0);
}

TEST(Refinement, NotesAPlanesNewFirstPixel) {
  Frame f({"......", "......", "..1111", "111111"}, flat);
  EXPECT_EQ(f.planes[1].first_pixel, 14u);
  f.refine();
  EXPECT_EQ(f.planes[1].first_pixel, 0u);
  EXPECT_DOUBLE_EQ(f.planes[1].sums.count, 24.0);
}

TEST(Refinement, GrowsThePlanesUnderTheirNumbersAfterASort) {
  // Plane 1 is the smaller: a sort by size swaps the numbers. The image still has the old
  // ones; refinement writes the new ones as it goes, and grows the planes under them.
  const std::vector<std::string> art = {
      "11..2222222",  //
      "11..2222222",  //
  };
  const auto depth = [](int u, int) { return u < 3 ? 2.0 : 2.5; };
  Frame f(art, depth);
  ASSERT_TRUE(f.planes.sortBySize(0, nullptr));
  ASSERT_EQ(f.planes.remap(1), 2u);
  f.refine();
  EXPECT_EQ(f.art(), (std::vector<std::string>{"22211111111", "22211111111"}));
  EXPECT_DOUBLE_EQ(f.planes[1].sums.count, 16.0);
  EXPECT_DOUBLE_EQ(f.planes[2].sums.count, 6.0);
  EXPECT_EQ(f.planes[1].first_pixel, 3u);
  EXPECT_EQ(f.planes[2].first_pixel, 0u);
  // The same as writing the image in the new numbers first and refining it then.
  Frame g(art, depth);
  ASSERT_TRUE(g.planes.sortBySize(0, nullptr));
  g.planes.writableImage();
  g.refine();
  EXPECT_EQ(g.art(), f.art());
  std::vector<std::uint32_t> f_image, g_image;
  f.planes.releaseImage(f_image);
  g.planes.releaseImage(g_image);
  EXPECT_EQ(f_image, g_image);
}

TEST(Refinement, ClearsTheLabelsOfDroppedPlanesWhenNoneIsLeft) {
  Frame f({"11..", "11.."}, flat);
  ASSERT_TRUE(f.planes.sortBySize(100, nullptr));  // plane 1 is too small
  ASSERT_TRUE(f.planes.list().empty());
  f.refine();
  EXPECT_EQ(f.art(), (std::vector<std::string>{"....", "...."}));
  std::vector<std::uint32_t> image;
  f.planes.releaseImage(image);
  EXPECT_EQ(image, std::vector<std::uint32_t>(8, 0u));
}

TEST(Refinement, NeverLabelsFilledInHoles) {
  // Every third pixel of every other row of a plane is missing: enough for HoleFilling to
  // bridge them.
  const int width = 30, height = 12;
  const auto missing = [](int u, int v) { return u % 3 == 0 && v % 2 == 0; };
  const Grid measured(width, height, [&](int u, int v) { return missing(u, v) ? kNaN : 2.0; });
  Params params;
  params.distance_threshold = 0.01;
  const Tolerances tolerances(params, {}, 1.0 / test::kPinholeFocal, measured.data.size() / 3);
  HoleFilling holes;
  const PointGrid& full = holes.fill(measured.grid(), tolerances);
  ASSERT_TRUE(holes.filled());
  // The left half is plane 1 (the filled points are on it, but not labelled).
  PlaneCandidates planes;
  planes.list().resize(1);
  std::uint32_t* image = planes.newImage(width, height);
  std::fill(image, image + full.size(), 0u);
  for (int v = 0; v < height; ++v)
    for (int u = 0; u < width / 2; ++u) {
      const std::size_t i = static_cast<std::size_t>(v * width + u);
      if (holes.isFilled(i) || !full.isFinite(i)) continue;  // a hole at the corner is left
      image[i] = 1;
      planes[1].sums.add(Vec3::load(full.point(i)));
      planes[1].first_pixel = std::min(planes[1].first_pixel, i);
    }
  planes[1].criterion = planeCriterion(planes[1].sums.fit(), tolerances, kPinholePitch);
  std::vector<std::size_t> queue;
  refinePlanes(full, holes, planes, queue);
  std::vector<std::uint32_t> labels;
  planes.releaseImage(labels);
  std::size_t labelled = 0, measured_points = 0, filled = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (holes.isFilled(i)) {
      EXPECT_EQ(labels[i], 0u) << "filled pixel " << i;
      ++filled;
    } else {
      labelled += labels[i] == 1u ? 1u : 0u;
      measured_points += full.isFinite(i) ? 1u : 0u;
    }
  }
  EXPECT_GT(filled, 50u);
  // Every measured pixel of the right half was reached, through measured pixels alone.
  EXPECT_EQ(labelled, measured_points);
  EXPECT_EQ(measured_points, 300u);
  EXPECT_DOUBLE_EQ(planes[1].sums.count, static_cast<double>(labelled));
}

TEST(Refinement, DoesNothingOnEmptyOrAllHoleFramesOrWithoutPlanes) {
  Frame empty({""}, flat);
  empty.refine();
  std::vector<std::uint32_t> image;
  empty.planes.releaseImage(image);
  EXPECT_TRUE(image.empty());

  Frame no_planes({"....", "...."}, flat);
  no_planes.refine();
  EXPECT_EQ(no_planes.art(), (std::vector<std::string>{"....", "...."}));

  // A plane given by its sums, none of whose pixels is labelled, in a frame with no returns.
  Frame holes({"....", "...."}, [](int, int) { return kNaN; });
  holes.planes.list().resize(1);
  holes.planes[1].sums = Frame({"11", "11"}, flat).planes[1].sums;
  holes.refine();
  EXPECT_EQ(holes.art(), (std::vector<std::string>{"....", "...."}));
  EXPECT_DOUBLE_EQ(holes.planes[1].sums.count, 4.0);
}

TEST(Refinement, LeavesAOnePixelFrameAsItIs) {
  Frame one({"1"}, flat);
  one.refine();
  EXPECT_EQ(one.art(), (std::vector<std::string>{"1"}));
  EXPECT_DOUBLE_EQ(one.planes[1].sums.count, 1.0);
}

}  // namespace
}  // namespace floodplane
