// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Distances from points to primitive surfaces and inside-the-solid tests, against values
// worked out by hand: what the scene generators rely on to keep cameras 0.5 m clear of every
// surface and out of every solid.

#include "synth/surface_distance.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace {

using namespace floodplane::synth;

constexpr double kPi = 3.14159265358979323846;

TEST(SurfaceDistance, RectangleAndPolygonWithAHole) {
  const Rectangle wall{Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(2, 0, 0),
                       Eigen::Vector3d(0, 0, 2)};                      // x, z in [-1, 1] x [0, 2]
  EXPECT_NEAR(distanceToSurface(wall, {0.3, 0.7, 1.5}), 0.7, 1e-12);   // in front of it
  EXPECT_NEAR(distanceToSurface(wall, {1.3, 0.4, 1.0}), 0.5, 1e-12);   // beside: to the edge x = 1
  EXPECT_NEAR(distanceToSurface(wall, {-1.3, 0.0, 2.4}), 0.5, 1e-12);  // beyond a corner
  EXPECT_FALSE(insideSolid(wall, {0.0, 0.0, 1.0}));

  // A 2 x 2 wall in the plane z = 0 with a 1 x 1 hole in its middle.
  Polygon with_hole;
  with_hole.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  with_hole.holes = {{{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}}};
  EXPECT_NEAR(distanceToSurface(with_hole, {0.8, 0.0, 0.3}), 0.3, 1e-12);                   // over the wall
  EXPECT_NEAR(distanceToSurface(with_hole, {0.0, 0.0, 0.4}), std::hypot(0.4, 0.5), 1e-12);  // over the hole
  EXPECT_NEAR(distanceToSurface(with_hole, {0.1, 0.0, 0.0}), 0.4, 1e-12);                   // in the hole's plane
}

TEST(SurfaceDistance, BoxFromOutsideAndInside) {
  const Box box{
      Eigen::Vector3d(1, 2, 0.5), Eigen::Vector3d(2, 1, 1),
      Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix()};       // covers x 0.5-1.5, y 1-3, z 0-1
  EXPECT_NEAR(distanceToSurface(box, {1.0, 2.0, 2.0}), 1.0, 1e-12);                   // above
  EXPECT_NEAR(distanceToSurface(box, {2.0, 2.0, 0.5}), 0.5, 1e-12);                   // beside, across the short side
  EXPECT_NEAR(distanceToSurface(box, {1.0, 3.5, 0.5}), 0.5, 1e-12);                   // beside, along the long side
  EXPECT_NEAR(distanceToSurface(box, {1.0, 2.0, 0.4}), 0.4, 1e-12);                   // inside: to the bottom
  EXPECT_NEAR(distanceToSurface(box, {2.5, 3.5, 0.5}), std::hypot(1.0, 0.5), 1e-12);  // off a vertical edge
  EXPECT_TRUE(insideSolid(box, {1.2, 2.8, 0.9}));
  EXPECT_FALSE(insideSolid(box, {1.6, 2.0, 0.5}));
}

TEST(SurfaceDistance, SphereAndCylinder) {
  const Sphere ball{Eigen::Vector3d(0, 0, 1), 0.5};
  EXPECT_NEAR(distanceToSurface(ball, {0, 2, 1}), 1.5, 1e-12);
  EXPECT_NEAR(distanceToSurface(ball, {0, 0, 1.2}), 0.3, 1e-12);
  EXPECT_TRUE(insideSolid(ball, {0.1, 0.1, 1.1}));
  EXPECT_FALSE(insideSolid(ball, {0.0, 0.6, 1.0}));

  const Cylinder can{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 2), 0.5, 1.0};  // axis of any length
  EXPECT_NEAR(distanceToSurface(can, {2, 0, 0.5}), 1.5, 1e-12);                      // from the side
  EXPECT_NEAR(distanceToSurface(can, {0.2, 0, 1.7}), 0.7, 1e-12);                    // above the top
  EXPECT_NEAR(distanceToSurface(can, {0.8, 0, 1.4}), 0.5, 1e-12);                    // beyond the rim
  EXPECT_NEAR(distanceToSurface(can, {0.1, 0, 0.5}), 0.4, 1e-12);                    // inside, nearest the side
  EXPECT_TRUE(insideSolid(can, {0.1, 0.1, 0.9}));
  EXPECT_FALSE(insideSolid(can, {0.1, 0.1, 1.1}));
}

TEST(SurfaceDistance, ObliquePrism) {
  // A unit square swept along (0.5, 0, 1): a parallelepiped leaning towards +x.
  const Prism prism{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, Eigen::Vector3d(0.5, 0, 1)};
  EXPECT_NEAR(distanceToSurface(prism, {0.5, 0.5, -0.3}), 0.3, 1e-12);  // below the bottom
  EXPECT_NEAR(distanceToSurface(prism, {1.0, 0.5, 1.2}), 0.2, 1e-12);   // above the top
  // Beside the leaning face through x = 1 + 0.5 z: its outward normal is (2, 0, -1) / sqrt(5).
  const Eigen::Vector3d point(2.0, 0.5, 0.5);
  EXPECT_NEAR(distanceToSurface(prism, point), (2.0 - 1.25) * 2.0 / std::sqrt(5.0), 1e-12);
  EXPECT_TRUE(insideSolid(prism, {1.2, 0.5, 0.8}));   // x = 1.2 is inside at that height
  EXPECT_FALSE(insideSolid(prism, {0.2, 0.5, 0.8}));  // left of the leaning face x = 0.4
}

TEST(SurfaceDistance, NearestOverAScene) {
  Scene scene;
  scene.primitives = {
      {"floor", Rectangle{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(0, 10, 0)}},
      {"ball", Sphere{Eigen::Vector3d(1, 0, 1.5), 0.2}}};
  EXPECT_NEAR(nearestSurfaceDistance(scene, {0, 0, 1.5}), 0.8, 1e-12);
  EXPECT_NEAR(nearestSurfaceDistance(scene, {0, 0, 0.6}), 0.6, 1e-12);
  EXPECT_TRUE(insideAnySolid(scene, {1.05, 0, 1.5}));
  EXPECT_FALSE(insideAnySolid(scene, {0, 0, 1.5}));
}

}  // namespace
