// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Beyond the paper: the edge-preserving 3 x 3 mean before segmenting. It divides independent
// noise by about three on a surface, keeps a depth step's two sides apart and holes as holes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "frame/depth_smoothing.h"
#include "test_scenes.h"
#include "util/simd.h"

namespace floodplane {
namespace {

using test::Pinhole;
using test::RenderedGrid;

Pinhole camera() { return test::kinectView(120, 90); }

NoiseModel constantNoise(double sigma) {
  NoiseModel noise;
  noise.sigma_constant = sigma;
  return noise;
}

// The RMS distance of the points of `grid` (pixels with truth `id`, away from the border)
// from the frontal plane z = depth, along z.
double rmsFromFrontalPlane(const PointGrid& grid, const RenderedGrid& scene, int id, double depth) {
  double sum = 0.0;
  int n = 0;
  for (int y = 1; y + 1 < scene.height; ++y) {
    for (int x = 1; x + 1 < scene.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * scene.width + x;
      if (scene.truth[i] != id) continue;
      const double dz = grid.point(i)[2] - depth;
      sum += dz * dz;
      ++n;
    }
  }
  return std::sqrt(sum / n);
}

TEST(DepthSmoothing, DividesIndependentNoiseOnAPlaneByAboutThree) {
  const double sigma = 0.004;
  const RenderedGrid scene = test::render(camera(), {test::frontalPlane(2.0)}, sigma, 2);
  DepthSmoothing smoothing;
  const PointGrid& smoothed = smoothing.smooth(scene.grid(), constantNoise(sigma));
  const double before = rmsFromFrontalPlane(scene.grid(), scene, 1, 2.0);
  const double after = rmsFromFrontalPlane(smoothed, scene, 1, 2.0);
  EXPECT_NEAR(before, sigma, 0.1 * sigma);
  // The mean of nine: a third, a little more where the gate leaves a neighbour out.
  EXPECT_LT(after, 0.4 * sigma);
  EXPECT_GT(after, 0.25 * sigma);
}

TEST(DepthSmoothing, KeepsTheTwoSidesOfADepthStepApart) {
  // A board 5 cm (about nine noise deviations) in front of a wall.
  const double sigma = 0.004;
  test::ScenePlane board = test::frontalPlane(1.95, 2);
  board.contains = [](const Eigen::Vector3d& p) { return p.x() < 0.0; };
  const RenderedGrid scene = test::render(camera(), {board, test::frontalPlane(2.0, 1)}, sigma, 3);
  DepthSmoothing smoothing;
  const PointGrid& smoothed = smoothing.smooth(scene.grid(), constantNoise(sigma));
  // Every point stays on its own surface, the columns along the step too.
  for (std::size_t i = 0; i < scene.truth.size(); ++i) {
    const double depth = scene.truth[i] == 2 ? 1.95 : 2.0;
    ASSERT_LT(std::abs(smoothed.point(i)[2] - depth), 5.0 * sigma) << "pixel " << i;
  }
  EXPECT_LT(rmsFromFrontalPlane(smoothed, scene, 1, 2.0), 0.45 * sigma);
  EXPECT_LT(rmsFromFrontalPlane(smoothed, scene, 2, 1.95), 0.45 * sigma);
}

TEST(DepthSmoothing, KeepsHolesAndAveragesOnlyTheReturnsAroundThem) {
  RenderedGrid scene = test::render(camera(), {test::frontalPlane(2.0)}, 0.0);
  const std::size_t hole = static_cast<std::size_t>(40) * scene.width + 60;
  for (int k = 0; k < 3; ++k) scene.xyz[3 * hole + k] = std::numeric_limits<float>::quiet_NaN();
  DepthSmoothing smoothing;
  const PointGrid& smoothed = smoothing.smooth(scene.grid(), constantNoise(0.001));
  EXPECT_EQ(smoothed.stride, 4u);
  EXPECT_FALSE(smoothed.isFinite(hole));
  for (const std::size_t neighbour : {hole - 1, hole + 1, hole - scene.width, hole + scene.width}) {
    ASSERT_TRUE(smoothed.isFinite(neighbour));
    EXPECT_NEAR(smoothed.point(neighbour)[2], 2.0, 1e-5);
  }
  // On an exact plane facing the camera the mean of neighbours is the plane again, edges and
  // corners of the grid included.
  for (std::size_t i = 0; i < scene.truth.size(); ++i) {
    if (i == hole) continue;
    ASSERT_NEAR(smoothed.point(i)[2], 2.0, 1e-5) << i;
    ASSERT_EQ(smoothed.point(i)[3], 0.0f);
  }
}

// Points with four floats (PCL's layout) are smoothed four (SSE2) or eight (AVX) at a time,
// packed x y z points one at a time; all must give the same floats, bit for bit, at a step,
// around holes, at the grid's edges, on widths that are no multiple of four or eight and on
// grids of a row or a column.
void expectSmoothingChangesNoBit(DepthSmoothing::VectorWidth vector_width) {
  test::ScenePlane board = test::frontalPlane(1.95, 2);
  board.contains = [](const Eigen::Vector3d& p) { return p.x() < 0.0; };
  NoiseModel noise;
  noise.sigma_constant = 0.001;
  noise.sigma_quadratic = 0.0007;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const auto& [width, height] :
       {std::pair{123, 37}, {1, 1}, {5, 1}, {1, 6}, {6, 2}, {9, 3}, {10, 4}, {17, 5}, {24, 3}}) {
    RenderedGrid scene = test::render(test::kinectView(width, height), {board, test::frontalPlane(2.0, 1)}, 0.004, 5);
    const std::size_t n = scene.truth.size();
    for (const std::size_t hole : {std::size_t{0}, n / 2, n - 1}) {
      for (int k = 0; k < 3; ++k) scene.xyz[3 * hole + k] = nan;
    }
    scene.xyz[3 * (n / 3) + 2] = std::numeric_limits<float>::infinity();
    // A patch of points on the plane x = -0, three rows high so that both passes see -0 around
    // a point: the sums must start from +0 as the scalar code's do.
    for (int y = std::max(0, height / 2 - 1); y <= std::min(height - 1, height / 2 + 1); ++y) {
      for (int x = 0; x < std::min(width, 20); ++x) scene.xyz[3 * (static_cast<std::size_t>(y) * width + x)] = -0.0f;
    }
    const std::vector<float> padded = scene.fourFloatPoints();
    const PointGrid four = scene.fourFloatGrid(padded);
    DepthSmoothing by_point, by_lanes(vector_width);
    const PointGrid& expected = by_point.smooth(scene.grid(), noise);
    const PointGrid& actual = by_lanes.smooth(four, noise);
    ASSERT_EQ(actual.size(), expected.size());
    std::size_t smoothed = 0;
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < 4; ++k) {
        const float e = expected.point(i)[k], a = actual.point(i)[k];
        if (std::isnan(e)) {
          ASSERT_TRUE(std::isnan(a)) << width << " x " << height << ", pixel " << i << " coordinate " << k;
        } else {
          ASSERT_EQ(std::memcmp(&e, &a, sizeof e), 0)
              << width << " x " << height << ", pixel " << i << " coordinate " << k << ": " << e << " " << a;
        }
      }
      if (std::isfinite(expected.point(i)[2]) && expected.point(i)[2] != scene.xyz[3 * i + 2]) ++smoothed;
    }
    if (n > 100) {
      EXPECT_GT(smoothed, n / 2);  // the comparison is of smoothed points
    }
  }
}

TEST(DepthSmoothing, SmoothingFourPointsAtATimeChangesNoBit) {
  if (!simdEnabled()) GTEST_SKIP() << "built without SIMD (FLOODPLANE_SIMD=OFF): there is no four-point path";
  expectSmoothingChangesNoBit(DepthSmoothing::VectorWidth::kSse2);
}

TEST(DepthSmoothing, SmoothingEightPointsAtATimeChangesNoBit) {
  if (!cpuHasAvx()) GTEST_SKIP() << "no AVX on this CPU, or built without SIMD: there is no eight-point path";
  expectSmoothingChangesNoBit(DepthSmoothing::VectorWidth::kWidest);
}

}  // namespace
}  // namespace floodplane
