// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Beyond the paper: bridging small holes. A surface that lost a third of its returns pixel by
// pixel (a scanner on a dark surface) is filled in on the plane and found whole; depth steps
// and wide holes (shadows) are left alone; filled pixels are never labelled.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "floodplane/segmenter.h"
#include "frame/hole_filling.h"
#include "test_scenes.h"

namespace floodplane {
namespace {

using test::Pinhole;
using test::RenderedGrid;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

Pinhole camera() { return test::kinectView(160, 120); }

Tolerances exactTolerances(std::size_t pixels) {
  static const Params params;
  return Tolerances(params, NoiseModel(), 1.0 / camera().focal, pixels);
}

// Removes each point with probability `share` (seeded).
void dropReturns(RenderedGrid& scene, double share, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < scene.truth.size(); ++i) {
    if (u(rng) >= share) continue;
    for (int k = 0; k < 3; ++k) scene.xyz[3 * i + static_cast<std::size_t>(k)] = kNaN;
    scene.truth[i] = 0;
  }
}

TEST(HoleFilling, FillsSpeckleOnAPlaneWithPointsOnThePlane) {
  RenderedGrid scene = test::render(camera(), test::roomCorner());
  const RenderedGrid measured = scene;
  dropReturns(scene, 0.35, 3);
  HoleFilling holes;
  const PointGrid& filled = holes.fill(scene.grid(), exactTolerances(scene.truth.size()));
  ASSERT_TRUE(holes.filled());
  std::size_t filled_points = 0, missing = 0;
  for (std::size_t i = 0; i < scene.truth.size(); ++i) {
    const float* p = filled.point(i);
    if (!scene.grid().isFinite(i)) {
      ++missing;
      if (!holes.isFilled(i)) continue;
      ++filled_points;
      // Inside a wall (its 9 x 9 neighbourhood all on it) the point lies on the wall: the
      // interpolation of two points of a plane stays on it.
      const int u = static_cast<int>(i % 160), v = static_cast<int>(i / 160);
      bool interior = u >= 4 && v >= 4 && u < 156 && v < 116;
      for (int dv = -4; interior && dv <= 4; ++dv)
        for (int du = -4; interior && du <= 4; ++du)
          interior = measured.truth[static_cast<std::size_t>((v + dv) * 160 + u + du)] == measured.truth[i];
      if (!interior) continue;
      const test::ScenePlane wall = test::roomCorner()[static_cast<std::size_t>(measured.truth[i] - 1)];
      EXPECT_NEAR(wall.normal.dot(Eigen::Vector3d(p[0], p[1], p[2])) + wall.offset, 0.0, 1e-4) << i;
    } else {
      EXPECT_FALSE(holes.isFilled(i));
      EXPECT_EQ(p[2], scene.xyz[3 * i + 2]);  // measured points stay as they are
    }
  }
  EXPECT_GT(static_cast<double>(filled_points), 0.9 * static_cast<double>(missing));
}

TEST(HoleFilling, DoesNotBridgeADepthStep) {
  // A wall at 2 m with a box face at 1.5 m in front of its left half; the column of pixels
  // between them has no return, as do random pixels everywhere (so that the frame is filled).
  test::ScenePlane box = test::frontalPlane(1.5, 2);
  box.contains = [](const Eigen::Vector3d& p) { return p.x() < 0.0; };
  RenderedGrid scene = test::render(camera(), {box, test::frontalPlane(2.0, 1)});
  dropReturns(scene, 0.1, 5);
  for (int v = 0; v < 120; ++v)
    for (int u = 79; u <= 80; ++u)
      for (int k = 0; k < 3; ++k) scene.xyz[3 * (static_cast<std::size_t>(v) * 160 + u) + k] = kNaN;
  HoleFilling holes;
  const PointGrid& filled = holes.fill(scene.grid(), exactTolerances(scene.truth.size()));
  ASSERT_TRUE(holes.filled());
  for (int v = 0; v < 120; ++v) {
    EXPECT_FALSE(filled.isFinite(static_cast<std::size_t>(v) * 160 + 79)) << v;
    EXPECT_FALSE(filled.isFinite(static_cast<std::size_t>(v) * 160 + 80)) << v;
  }
}

TEST(HoleFilling, LeavesWideHolesAndFramesWithFewHolesAsTheyAre) {
  // A shadow 30 pixels wide and a few single dropouts: nothing to fill, no copy.
  RenderedGrid scene = test::render(camera(), test::roomCorner());
  for (int v = 0; v < 120; ++v)
    for (int u = 40; u < 70; ++u)
      for (int k = 0; k < 3; ++k) scene.xyz[3 * (static_cast<std::size_t>(v) * 160 + u) + k] = kNaN;
  dropReturns(scene, 0.005, 7);
  HoleFilling holes;
  const PointGrid& result = holes.fill(scene.grid(), exactTolerances(scene.truth.size()));
  EXPECT_FALSE(holes.filled());
  EXPECT_EQ(result.data, scene.xyz.data());
}

TEST(HoleFilling, LetsTheSegmentationFindASpeckledPlaneAndLabelsOnlyMeasuredPixels) {
  RenderedGrid scene = test::render(camera(), test::roomCorner());
  dropReturns(scene, 0.4, 11);  // below the percolation threshold: no 4-connected surface left
  Params params;
  params.min_inliers = 200;
  Segmenter segmenter(params);
  const Segmentation& result = segmenter.segment(scene.grid());
  ASSERT_EQ(result.planes.size(), 3u);
  std::vector<std::size_t> counted(4, 0);
  for (std::size_t i = 0; i < result.labels.size(); ++i) {
    if (result.labels[i] == 0) continue;
    EXPECT_TRUE(scene.grid().isFinite(i)) << "a filled-in hole is labelled";
    ++counted[result.labels[i]];
  }
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(result.planes[k].inlier_count, counted[k + 1]);
  // Each wall keeps most of its measured pixels.
  std::size_t measured = 0, labelled = 0;
  for (std::size_t i = 0; i < result.labels.size(); ++i) {
    measured += scene.truth[i] != 0 ? 1 : 0;
    labelled += result.labels[i] != 0 ? 1 : 0;
  }
  EXPECT_GT(static_cast<double>(labelled), 0.9 * static_cast<double>(measured));
}

}  // namespace
}  // namespace floodplane
