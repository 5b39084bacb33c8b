// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The whole pipeline on ray-cast scenes whose planes are known.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "floodplane/segmenter.h"
#include "test_scenes.h"
#include "util/simd.h"

namespace floodplane {
namespace {

using test::bestIoU;
using test::Pinhole;
using test::RenderedGrid;
using test::ScenePlane;

Pinhole camera() { return test::kinectView(320, 240); }

Params exactParams() {
  Params p;
  p.depth_noise_coefficient = 0.0;
  p.min_inliers = 100;
  return p;
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

TEST(Segmenter, FindsTheThreePlanesOfARoomCorner) {
  const RenderedGrid scene = test::render(camera(), test::roomCorner());
  Segmenter segmenter(exactParams());
  const Segmentation& result = segmenter.segment(scene.grid());
  ASSERT_EQ(result.planes.size(), 3u);
  EXPECT_EQ(result.width, scene.width);
  EXPECT_EQ(result.labels.size(), scene.truth.size());
  for (const ScenePlane& truth : test::roomCorner()) {
    EXPECT_GT(bestIoU(scene, result.labels, truth.id), 0.98) << "plane " << truth.id;
    // The reported plane that overlaps it is the true plane.
    std::size_t pixel = 0;
    while (scene.truth[pixel] != truth.id || result.labels[pixel] == 0) ++pixel;
    const PlaneFit& fit = result.planes[result.labels[pixel] - 1].fit;
    EXPECT_LT(angleBetween(fit.normal, truth.normal), 1e-3);
    EXPECT_NEAR(fit.offset, truth.offset, 1e-3);
  }
}

// With and without noise, sub-sampling and refinement: the stages that count pixels, sort
// and renumber planes and note their first pixels must agree with the label image.
TEST(Segmenter, NumbersPlanesBySizeAndCountsTheirPixels) {
  for (const double noise : {0.0, 0.01}) {
    const RenderedGrid scene = test::render(camera(), test::roomCorner(), noise, 11);
    for (const int subsampling : {1, 2, 4}) {
      for (const bool refine : {true, false}) {
        SCOPED_TRACE(::testing::Message() << "noise " << noise << ", s = " << subsampling << ", refine " << refine);
        Params params = noise > 0.0 ? Params() : exactParams();
        params.min_inliers = 50;
        params.subsampling = subsampling;
        Segmenter segmenter(params);
        Segmenter::Options options;
        options.refine = refine;
        const Segmentation& result = segmenter.segment(scene.grid(), options);
        ASSERT_GE(result.planes.size(), 3u);
        std::vector<std::size_t> counts(result.planes.size() + 1, 0);
        std::vector<std::size_t> first(result.planes.size() + 1, std::numeric_limits<std::size_t>::max());
        for (std::size_t i = 0; i < result.labels.size(); ++i) {
          ASSERT_LE(result.labels[i], result.planes.size());
          ++counts[result.labels[i]];
          first[result.labels[i]] = std::min(first[result.labels[i]], i);
        }
        for (std::size_t k = 0; k < result.planes.size(); ++k) {
          EXPECT_EQ(result.planes[k].inlier_count, counts[k + 1]);
          // The boundary's start: the first pixel in raster order at s = 1; at s > 1 a pixel of the
          // plane whose west neighbour is not (on the plane's body: see SegmentedPlane).
          const std::size_t start = result.planes[k].first_pixel;
          if (subsampling == 1) {
            EXPECT_EQ(start, first[k + 1]);
          } else {
            ASSERT_LT(start, result.labels.size());
            EXPECT_EQ(result.labels[start], k + 1);
            EXPECT_GE(start, first[k + 1]);
            if (start % static_cast<std::size_t>(result.width) != 0) {
              EXPECT_NE(result.labels[start - 1], k + 1);
            }
          }
          if (k > 0) {
            EXPECT_GE(result.planes[k - 1].inlier_count, result.planes[k].inlier_count);
          }
        }
      }
    }
  }
}

TEST(Segmenter, FindsTheRoomCornerUnderKinectLikeNoise) {
  // sigma 1 cm along the rays at 1.5 to 4 m: the default, noise-aware parameters.
  const RenderedGrid scene = test::render(camera(), test::roomCorner(), 0.01, 3);
  Params params;
  params.min_inliers = 100;
  Segmenter segmenter(params);
  const Segmentation& result = segmenter.segment(scene.grid());
  for (const ScenePlane& truth : test::roomCorner())
    EXPECT_GT(bestIoU(scene, result.labels, truth.id), 0.9) << truth.id;
  EXPECT_LE(result.planes.size(), 5u);
}

TEST(Segmenter, KeepsABoardTwoCentimetresInFrontOfAWallApart) {
  ScenePlane board = test::frontalPlane(1.48, 2);
  board.contains = [](const Eigen::Vector3d& p) { return std::abs(p.x()) < 0.2 && std::abs(p.y()) < 0.15; };
  const RenderedGrid scene = test::render(camera(), {board, test::frontalPlane(1.5, 1)});
  Segmenter segmenter(exactParams());
  const Segmentation& result = segmenter.segment(scene.grid());
  EXPECT_EQ(result.planes.size(), 2u);
  EXPECT_GT(bestIoU(scene, result.labels, 1), 0.97);
  EXPECT_GT(bestIoU(scene, result.labels, 2), 0.95);
}

TEST(Segmenter, KeepsCoplanarButSeparateTableTopsApart) {
  // Two table tops at the same height, 20 cm apart, over a floor 75 cm lower.
  ScenePlane floor, left_top, right_top;
  floor.normal = left_top.normal = right_top.normal = Eigen::Vector3d(0, -1, 0);
  floor.offset = 1.2;
  left_top.offset = right_top.offset = 0.45;
  floor.id = 1;
  left_top.id = 2;
  right_top.id = 3;
  left_top.contains = [](const Eigen::Vector3d& p) { return p.x() > -0.9 && p.x() < -0.1 && p.z() < 2.5; };
  right_top.contains = [](const Eigen::Vector3d& p) { return p.x() > 0.1 && p.x() < 0.9 && p.z() < 2.5; };
  const RenderedGrid scene = test::render(camera(), {floor, left_top, right_top});
  Segmenter segmenter(exactParams());
  const Segmentation& result = segmenter.segment(scene.grid());
  EXPECT_GT(bestIoU(scene, result.labels, 2), 0.95);
  EXPECT_GT(bestIoU(scene, result.labels, 3), 0.95);
}

TEST(Segmenter, SeparatesARampAtTenDegreesFromTheFloor) {
  ScenePlane floor, ramp;
  floor.normal = Eigen::Vector3d(0, -1, 0);
  floor.offset = 1.0;
  floor.id = 1;
  const double tilt = 10.0 * M_PI / 180.0;  // rising away from the camera from z = 2.5
  ramp.normal = Eigen::Vector3d(0, -std::cos(tilt), -std::sin(tilt));
  ramp.offset = -ramp.normal.dot(Eigen::Vector3d(0, 1.0, 2.5));
  ramp.id = 2;
  ramp.contains = [](const Eigen::Vector3d& p) { return p.z() > 2.5 && std::abs(p.x()) < 0.6; };
  floor.contains = [](const Eigen::Vector3d& p) { return p.z() <= 2.5 || std::abs(p.x()) >= 0.6; };
  const RenderedGrid scene = test::render(camera(), {floor, ramp});
  Segmenter segmenter(exactParams());
  const Segmentation& result = segmenter.segment(scene.grid());
  EXPECT_GT(bestIoU(scene, result.labels, 1), 0.95);
  EXPECT_GT(bestIoU(scene, result.labels, 2), 0.9);
}

TEST(Segmenter, IsDeterministic) {
  const RenderedGrid scene = test::render(camera(), test::roomCorner(), 0.01, 5);
  Segmenter first, second;
  const std::vector<std::uint32_t> once = first.segment(scene.grid()).labels;
  EXPECT_EQ(first.segment(scene.grid()).labels, once);
  EXPECT_EQ(second.segment(scene.grid()).labels, once);
}

// The flood decides four pixels at a time where a point has four readable floats (PCL's
// layout), pixel by pixel where it has three (these test grids). Both must segment alike:
// only the order in which points are summed differs.
TEST(Segmenter, DecidingFourPixelsAtATimeChangesNothing) {
  if (!simdEnabled()) GTEST_SKIP() << "built without SIMD (FLOODPLANE_SIMD=OFF): there is no four-pixel path";
  Pinhole wide = camera();
  wide.width = 160;
  wide.height = 120;
  wide.focal = 131.25;
  for (const double noise : {0.0, 0.01}) {
    const RenderedGrid scene = test::render(wide, test::roomCorner(), noise, 7);
    const std::vector<float> padded = scene.fourFloatPoints();
    const PointGrid four = scene.fourFloatGrid(padded);
    for (const int subsampling : {1, 2}) {
      Params params;
      params.min_inliers = 100;
      params.subsampling = subsampling;
      Segmenter by_pixel(params), by_group(params);
      const Segmentation& expected = by_pixel.segment(scene.grid());
      const Segmentation& actual = by_group.segment(four);
      EXPECT_EQ(actual.labels, expected.labels) << "noise " << noise << ", s = " << subsampling;
      ASSERT_EQ(actual.planes.size(), expected.planes.size());
      ASSERT_GE(actual.planes.size(), 3u);
      for (std::size_t k = 0; k < actual.planes.size(); ++k) {
        EXPECT_EQ(actual.planes[k].inlier_count, expected.planes[k].inlier_count);
        EXPECT_NEAR(actual.planes[k].fit.offset, expected.planes[k].fit.offset, 1e-9);
        EXPECT_GT(actual.planes[k].fit.normal.dot(expected.planes[k].fit.normal), 1.0 - 1e-12);
      }
    }
  }
}

TEST(Segmenter, ReusesItsBuffersAcrossFrameSizes) {
  const RenderedGrid big = test::render(camera(), test::roomCorner());
  Pinhole small_camera = camera();
  small_camera.width = 64;
  small_camera.height = 48;
  small_camera.focal = 52.5;
  const RenderedGrid small = test::render(small_camera, test::roomCorner());
  Segmenter reused(exactParams());
  const std::vector<std::uint32_t> big_labels = reused.segment(big.grid()).labels;
  reused.segment(small.grid());
  EXPECT_EQ(reused.segment(big.grid()).labels, big_labels);
  Segmenter fresh(exactParams());
  EXPECT_EQ(fresh.segment(small.grid()).labels, reused.segment(small.grid()).labels);
}

TEST(Segmenter, BringsSubsampledLabelsBackToFullResolution) {
  const RenderedGrid scene = test::render(camera(), test::roomCorner());
  for (int factor : {2, 4, 8}) {
    Params params = exactParams();
    params.subsampling = factor;
    Segmenter segmenter(params);
    const Segmentation& result = segmenter.segment(scene.grid());
    ASSERT_EQ(result.labels.size(), scene.truth.size());
    EXPECT_EQ(result.planes.size(), 3u) << "factor " << factor;
    for (const ScenePlane& truth : test::roomCorner())
      EXPECT_GT(bestIoU(scene, result.labels, truth.id), 0.97) << "factor " << factor << " plane " << truth.id;
  }
}

TEST(Segmenter, ReportsOnlyPlanesWithEnoughInliers) {
  ScenePlane small = test::frontalPlane(1.4, 2);
  small.contains = [](const Eigen::Vector3d& p) { return std::abs(p.x()) < 0.06 && std::abs(p.y()) < 0.06; };
  const RenderedGrid scene = test::render(camera(), {small, test::frontalPlane(2.0, 1)});
  Params params = exactParams();
  params.min_inliers = 50;
  Segmenter segmenter(params);
  EXPECT_EQ(segmenter.segment(scene.grid()).planes.size(), 2u);  // the 12 cm square: ~500 px
  params.min_inliers = 2000;
  segmenter.setParams(params);
  const Segmentation& result = segmenter.segment(scene.grid());
  ASSERT_EQ(result.planes.size(), 1u);
  for (const SegmentedPlane& plane : result.planes) EXPECT_GE(plane.inlier_count, 2000u);
}

TEST(Segmenter, RefinementOnlyAddsPixels) {
  const RenderedGrid scene = test::render(camera(), test::roomCorner(), 0.01, 9);
  Params params;
  params.min_inliers = 100;
  Segmenter segmenter(params);
  Segmenter::Options plain;
  plain.refine = false;
  const std::vector<std::uint32_t> unrefined = segmenter.segment(scene.grid(), plain).labels;
  const std::vector<std::uint32_t> refined = segmenter.segment(scene.grid()).labels;
  std::size_t before = 0, after = 0;
  for (std::size_t i = 0; i < refined.size(); ++i) {
    before += unrefined[i] != 0;
    after += refined[i] != 0;
    if (unrefined[i] != 0) {
      EXPECT_NE(refined[i], 0u) << "pixel " << i;
    }
  }
  EXPECT_GE(after, before);
}

TEST(Segmenter, FindsNothingInAnEmptyOrTinyGrid) {
  ScenePlane nothing = test::frontalPlane(1.0);
  nothing.contains = [](const Eigen::Vector3d&) { return false; };
  const RenderedGrid empty = test::render(camera(), {nothing});
  Segmenter segmenter;
  const Segmentation& result = segmenter.segment(empty.grid());
  EXPECT_TRUE(result.planes.empty());
  EXPECT_EQ(std::count(result.labels.begin(), result.labels.end(), 0u), static_cast<long>(result.labels.size()));

  Params params;
  params.min_inliers = 300;
  segmenter.setParams(params);
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {1, 30}, {30, 1}, {5, 5}, {2, 2}}) {
    Pinhole tiny;
    tiny.width = w;
    tiny.height = h;
    const RenderedGrid grid = test::render(tiny, {test::frontalPlane(1.0)});
    const Segmentation& r = segmenter.segment(grid.grid());
    EXPECT_EQ(r.labels.size(), static_cast<std::size_t>(w * h));
    EXPECT_TRUE(r.planes.empty()) << w << "x" << h;  // fewer pixels than min_inliers
  }
}

TEST(Segmenter, HandsPixelsToLaterFloodsThatFitThemBetter) {
  // Eq. 4 at the creases of a room corner: the first flood's band on the next wall is
  // taken back by that wall's flood.
  const RenderedGrid scene = test::render(camera(), test::roomCorner());
  Params params = exactParams();
  params.distance_threshold = 0.05;  // wide bands across the creases
  Segmenter segmenter(params);
  Segmenter::Options options;
  options.measure_phases = true;
  const auto start = std::chrono::steady_clock::now();
  const Segmentation& result = segmenter.segment(scene.grid(), options);
  const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GT(result.stats.pixels_taken_over, 0u);
  EXPECT_GE(result.stats.seeds, 3u);
  for (const ScenePlane& truth : test::roomCorner()) EXPECT_GT(bestIoU(scene, result.labels, truth.id), 0.97);
  // The phases are measured inside the call: each was timed, and together they fit in it.
  EXPECT_GT(result.phases.preparation, 0.0);
  EXPECT_GT(result.phases.flood_fill, 0.0);
  EXPECT_GT(result.phases.seed_selection, 0.0);
  EXPECT_GT(result.phases.region_output, 0.0);
  EXPECT_LE(result.phases.total(), wall_ms);
}

TEST(Segmenter, RejectsBadParameters) {
  Params bad;
  bad.subsampling = 3;
  EXPECT_THROW(Segmenter{bad}, std::invalid_argument);
  bad = Params();
  bad.distance_threshold = -0.01;
  EXPECT_THROW(Segmenter{bad}, std::invalid_argument);
  bad = Params();
  bad.angular_threshold = 2.0;
  Segmenter segmenter;
  EXPECT_THROW(segmenter.setParams(bad), std::invalid_argument);
  EXPECT_DOUBLE_EQ(segmenter.params().angular_threshold, Params().angular_threshold);
}

}  // namespace
}  // namespace floodplane
