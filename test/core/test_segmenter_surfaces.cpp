// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Beyond the paper, through the whole pipeline with default (self-calibrating) parameters,
// on exact and on Kinect-like data: shallow creases, planes cut apart by something in front
// of them, coplanar planes that are apart, curved surfaces and thin faces.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "floodplane/segmenter.h"
#include "test_scenes.h"

namespace floodplane {
namespace {

using test::bestIoU;
using test::Pinhole;
using test::RenderedGrid;
using test::ScenePlane;
using test::SceneSurface;

constexpr double kPi = 3.14159265358979323846;

Pinhole camera() { return test::kinectView(320, 240); }

// Noise along the rays of a Kinect (sigma = 0.0019 r^2), or none.
test::RangeNoise kinectNoise(bool noisy) {
  return [noisy](double r) { return noisy ? 0.0019 * r * r : 0.0; };
}

// The defaults at sub-sampling s: every test runs at s = 1 and at s = 4 (coarse to fine),
// which must find what s = 1 finds.
Params defaults(int s) {
  Params p;
  p.min_inliers = 100;  // the default (a thousandth of the pixels) is 77 at 320 x 240
  p.subsampling = s;
  return p;
}
constexpr int kSubsamplings[] = {1, 4};

std::string sensorName(bool noisy) { return noisy ? "Kinect-like noise" : "exact"; }

// The share of the pixels of surface `id` that carry a plane label.
double labelledShare(const RenderedGrid& scene, const std::vector<std::uint32_t>& labels, int id) {
  std::size_t on = 0, labelled = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (scene.truth[i] != id) continue;
    ++on;
    labelled += labels[i] != 0;
  }
  return static_cast<double>(labelled) / static_cast<double>(on);
}

// A plane through `point` with the given normal, for the pixels where `contains` holds.
ScenePlane planeThrough(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, int id,
                        std::function<bool(const Eigen::Vector3d&)> contains) {
  ScenePlane plane;
  plane.normal = normal.normalized();
  plane.offset = -plane.normal.dot(point);
  plane.id = id;
  plane.contains = std::move(contains);
  return plane;
}

TEST(SegmenterSurfaces, TwoFacesMeetingAtFifteenDegreesAreTwoPlanes) {
  for (const int s : kSubsamplings) {
    SCOPED_TRACE(testing::Message() << "s = " << s);
    // A fold 2 m away, pointing at the camera: each face turned 7.5 degrees from frontal.
    const double half = 7.5 * kPi / 180.0;
    const Eigen::Vector3d apex(0.0, 0.0, 2.0);
    const ScenePlane left = planeThrough(apex, {std::sin(half), 0.0, -std::cos(half)}, 1,
                                         [](const Eigen::Vector3d& p) { return p.x() <= 0.0; });
    const ScenePlane right = planeThrough(apex, {-std::sin(half), 0.0, -std::cos(half)}, 2,
                                          [](const Eigen::Vector3d& p) { return p.x() > 0.0; });
    for (const bool noisy : {false, true}) {
      SCOPED_TRACE(sensorName(noisy));
      const RenderedGrid scene = test::render(camera(), {left, right}, kinectNoise(noisy), 21);
      Segmenter segmenter(defaults(s));
      const Segmentation& result = segmenter.segment(scene.grid());
      EXPECT_EQ(result.planes.size(), 2u);
      EXPECT_GT(bestIoU(scene, result.labels, 1), 0.9);
      EXPECT_GT(bestIoU(scene, result.labels, 2), 0.9);
    }
  }
}

TEST(SegmenterSurfaces, AWallBehindAColumnIsOnePlane) {
  for (const int s : kSubsamplings) {
    SCOPED_TRACE(testing::Message() << "s = " << s);
    // A square column 20 cm wide, 1.5 m away, cuts the wall 3 m away in two halves.
    ScenePlane column = test::frontalPlane(1.5, 2);
    column.contains = [](const Eigen::Vector3d& p) { return std::abs(p.x()) < 0.1; };
    const ScenePlane wall = test::frontalPlane(3.0, 1);
    for (const bool noisy : {false, true}) {
      SCOPED_TRACE(sensorName(noisy));
      const RenderedGrid scene = test::render(camera(), {column, wall}, kinectNoise(noisy), 22);
      Segmenter segmenter(defaults(s));
      const Segmentation& result = segmenter.segment(scene.grid());
      // One label over both halves.
      EXPECT_GT(bestIoU(scene, result.labels, 1), 0.95);
      EXPECT_GT(bestIoU(scene, result.labels, 2), 0.9);
      EXPECT_EQ(result.planes.size(), 2u);
    }
  }
}

// Planes are numbered by size, and counted, after pieces are joined too: a column covering
// 40 % of the view is larger than either half of the wall behind it, but not than the wall.
TEST(SegmenterSurfaces, NumbersPlanesBySizeAfterJoiningThePiecesOfAWall) {
  for (const int s : kSubsamplings) {
    SCOPED_TRACE(testing::Message() << "s = " << s);
    ScenePlane column = test::frontalPlane(1.5, 2);
    column.contains = [](const Eigen::Vector3d& p) { return std::abs(p.x()) < 0.37; };
    const RenderedGrid scene = test::render(camera(), {column, test::frontalPlane(3.0, 1)});
    Segmenter segmenter(defaults(s));
    const Segmentation& result = segmenter.segment(scene.grid());
    ASSERT_EQ(result.planes.size(), 2u);
    EXPECT_GT(bestIoU(scene, result.labels, 1), 0.95);
    std::vector<std::uint32_t> counts(3, 0);
    for (const std::uint32_t label : result.labels) ++counts[label];
    EXPECT_EQ(result.planes[0].inlier_count, counts[1]);
    EXPECT_EQ(result.planes[1].inlier_count, counts[2]);
    EXPECT_GT(result.planes[0].inlier_count, result.planes[1].inlier_count);
    // Plane 1 is the wall.
    EXPECT_NEAR(result.planes[0].fit.offset, 3.0, 1e-3);
  }
}

TEST(SegmenterSurfaces, CoplanarTablesWithTheFloorBetweenThemAreTwoPlanes) {
  for (const int s : kSubsamplings) {
    SCOPED_TRACE(testing::Message() << "s = " << s);
    // Two table tops at one height, 20 cm apart, 75 cm above the floor.
    const Eigen::Vector3d up(0.0, -1.0, 0.0);
    const ScenePlane floor = planeThrough({0.0, 1.2, 0.0}, up, 1, [](const Eigen::Vector3d&) { return true; });
    const ScenePlane left_top = planeThrough(
        {0.0, 0.45, 0.0}, up, 2, [](const Eigen::Vector3d& p) { return p.x() > -0.9 && p.x() < -0.1 && p.z() < 2.5; });
    const ScenePlane right_top = planeThrough(
        {0.0, 0.45, 0.0}, up, 3, [](const Eigen::Vector3d& p) { return p.x() > 0.1 && p.x() < 0.9 && p.z() < 2.5; });
    for (const bool noisy : {false, true}) {
      SCOPED_TRACE(sensorName(noisy));
      const RenderedGrid scene = test::render(camera(), {floor, left_top, right_top}, kinectNoise(noisy), 23);
      Segmenter segmenter(defaults(s));
      const Segmentation& result = segmenter.segment(scene.grid());
      EXPECT_GT(bestIoU(scene, result.labels, 2), 0.9);
      EXPECT_GT(bestIoU(scene, result.labels, 3), 0.9);
    }
  }
}

TEST(SegmenterSurfaces, ACylinderAndABallInFrontOfAWallAreNotPlanes) {
  for (const int s : kSubsamplings) {
    SCOPED_TRACE(testing::Message() << "s = " << s);
    const ScenePlane wall = test::frontalPlane(3.5, 1);
    const SceneSurface column = test::uprightCylinder(-0.5, 2.2, 0.25, 2);
    const SceneSurface ball = test::ball({0.7, 0.2, 2.3}, 0.3, 3);
    for (const bool noisy : {false, true}) {
      SCOPED_TRACE(sensorName(noisy));
      const RenderedGrid scene = test::render(camera(), {wall}, {column, ball}, kinectNoise(noisy), 24);
      Segmenter segmenter(defaults(s));
      const Segmentation& result = segmenter.segment(scene.grid());
      EXPECT_GT(bestIoU(scene, result.labels, 1), 0.9);
      // A few flat-enough strips along the column's axis may stay; the surfaces do not.
      EXPECT_LT(labelledShare(scene, result.labels, 2), 0.15);
      EXPECT_LT(labelledShare(scene, result.labels, 3), 0.15);
    }
  }
}

// A wide column (radius 40 cm) under Kinect noise: the flood cuts its front into strips, each
// flat within its noise band, that touch and turn against each other. Judged one by one they
// pass the planarity test (before the pair test, 10-25 % of the column's pixels stayed on
// planes at 2.5 m); judged in touching pairs they are one curved surface.
TEST(SegmenterSurfaces, TheStripsOfAWideColumnAreNotPlanes) {
  for (const int s : kSubsamplings) {
    SCOPED_TRACE(testing::Message() << "s = " << s);
    for (const double z : {1.5, 2.5, 3.5}) {
      for (const unsigned seed : {1u, 2u, 3u}) {
        SCOPED_TRACE(testing::Message() << "column at " << z << " m, noise seed " << seed);
        const double radius = 0.4;
        const ScenePlane wall = test::frontalPlane(z + radius + 1.0, 1);
        const SceneSurface column = test::uprightCylinder(0.0, z + radius, radius, 2);
        const RenderedGrid scene = test::render(camera(), {wall}, {column}, kinectNoise(true), seed);
        Segmenter segmenter(defaults(s));
        const Segmentation& result = segmenter.segment(scene.grid());
        EXPECT_LT(labelledShare(scene, result.labels, 2), 0.02);
      }
    }
  }
}

// A shelf board reaching out 30 cm from a wall, its top 30 cm below eye level and
// `half_width` either side of the view's centre: the wall (id 1), the board's top (2) and its
// front edge (3), `thickness` high, `front` metres away.
std::vector<ScenePlane> shelfBoard(double front, double thickness, double half_width) {
  const ScenePlane wall = test::frontalPlane(front + 0.3, 1);
  const ScenePlane top =
      planeThrough({0.0, 0.3, 0.0}, {0.0, -1.0, 0.0}, 2, [front, half_width](const Eigen::Vector3d& p) {
        return p.z() >= front && p.z() <= front + 0.3 && std::abs(p.x()) < half_width;
      });
  ScenePlane edge = test::frontalPlane(front, 3);
  edge.contains = [thickness, half_width](const Eigen::Vector3d& p) {
    return p.y() >= 0.3 && p.y() <= 0.3 + thickness && std::abs(p.x()) < half_width;
  };
  return {wall, top, edge};
}

// Exact data: a shelf board 2 cm thick, its front edge 1.5 or 2 m away and 3-4 pixels high. No
// seed cross fits on it (before LeftoverSeeds its best IoU was 0.09 and 0), but the region the
// floods leave there is flat: it seeds its own flood. At 1.5 m the top's flood, seen at a
// grazing angle, takes the edge's first row at the crease (one of four: IoU 0.75).
TEST(SegmenterSurfaces, FindsAnEdgeNarrowerThanAnySeedCross) {
  for (const int s : kSubsamplings) {
    SCOPED_TRACE(testing::Message() << "s = " << s);
    for (const double front : {1.5, 2.0}) {
      SCOPED_TRACE(testing::Message() << "edge at " << front << " m");
      const RenderedGrid scene = test::render(camera(), shelfBoard(front, 0.02, 0.6), kinectNoise(false), 26);
      Segmenter segmenter(defaults(s));
      const Segmentation& result = segmenter.segment(scene.grid());
      EXPECT_GT(bestIoU(scene, result.labels, 1), 0.9);
      EXPECT_GT(bestIoU(scene, result.labels, 3), front < 2.0 ? 0.7 : 0.8);
    }
  }
}

TEST(SegmenterSurfaces, FindsTheFrontEdgeOfAShelfBoard) {
  for (const int s : kSubsamplings) {
    SCOPED_TRACE(testing::Message() << "s = " << s);
    // A shelf board, its top 30 cm below eye level, reaching out 30 cm from a wall. Exact: 3 cm
    // thick, its front edge 1.5 m away and 5 pixels high. Kinect-like noise: 5 cm thick, 1 m
    // away, 13 pixels high. (Measured limit under that noise at this resolution: 5 cm edges
    // are found up to 1.2 m, 3 cm edges up to 0.8 m; beyond, the edge is narrower than a seed
    // cross whose arms span three noise deviations, and nothing seeds it.)
    for (const bool noisy : {false, true}) {
      SCOPED_TRACE(sensorName(noisy));
      const double thickness = noisy ? 0.05 : 0.03;
      const double front = noisy ? 1.0 : 1.5;
      const RenderedGrid scene = test::render(camera(), shelfBoard(front, thickness, 0.5), kinectNoise(noisy), 25);
      Segmenter segmenter(defaults(s));
      const Segmentation& result = segmenter.segment(scene.grid());
      EXPECT_GT(bestIoU(scene, result.labels, 1), 0.9);
      EXPECT_GT(bestIoU(scene, result.labels, 2), 0.8);
      EXPECT_GT(bestIoU(scene, result.labels, 3), 0.8);
    }
  }
}

}  // namespace
}  // namespace floodplane
