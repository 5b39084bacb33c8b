// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The random scene family: one seed, one pair of scenes, byte for byte; different seeds,
// different scenes; ground truth that holds for every pixel of the exact render (flat pixels on
// their plane, unlabelled pixels on a sphere or a cylinder's side); cameras 0.5-6 m from the
// nearest surface that see several planes over most of the image; blocks whose faces meet at
// shallow angles.

#include "synth/scene_generator.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "synth/renderer.h"
#include "synth/scene_file.h"
#include "synth/surface_distance.h"

namespace {

using namespace floodplane::synth;

constexpr double kPi = 3.14159265358979323846;

bool isNaN(const Eigen::Vector3f& point) { return std::isnan(point.z()); }

// Points are floats: 1e-6 of the distance to the camera bounds their round-off.
double roundOff(const Eigen::Vector3f& point) { return 1e-6 * std::max(1.0, static_cast<double>(point.norm())); }

RenderedFrame render(const Scene& scene, SensorModel sensor, std::uint64_t seed) {
  RenderSettings settings;
  settings.sensor = sensor;
  settings.seed = seed;
  return renderScene(scene, settings);
}

bool sameBytes(const RenderedFrame& a, const RenderedFrame& b) {
  return a.points.size() == b.points.size() && a.labels == b.labels &&
         std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(Eigen::Vector3f)) == 0;
}

TEST(RandomScenes, NamesCarryTheSeedInAtLeastFourDigits) {
  EXPECT_EQ(randomSceneName(7), "random_0007");
  EXPECT_EQ(randomSceneName(101), "random_0101");
  EXPECT_EQ(randomSceneName(12345), "random_12345");
  EXPECT_EQ(generateRoomScene(7).name, "random_0007");
  EXPECT_EQ(generateBlocksScene(7).name, "random_0007");
}

TEST(RandomScenes, OneSeedGivesTheSameScenesAndFramesByteForByte) {
  for (const std::uint64_t seed : {5, 150}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Scene room = generateRoomScene(seed);
    EXPECT_EQ(sceneJson(room), sceneJson(generateRoomScene(seed)));
    EXPECT_TRUE(
        sameBytes(render(room, SensorModel::kinect, seed), render(generateRoomScene(seed), SensorModel::kinect, seed)));
    const Scene blocks = generateBlocksScene(seed);
    EXPECT_EQ(sceneJson(blocks), sceneJson(generateBlocksScene(seed)));
    EXPECT_TRUE(sameBytes(render(blocks, SensorModel::scanner, seed),
                          render(generateBlocksScene(seed), SensorModel::scanner, seed)));
  }
}

TEST(RandomScenes, DifferentSeedsGiveDifferentScenes) {
  std::set<std::string> rooms;
  std::set<std::string> blocks;
  std::set<std::vector<std::uint32_t>> labels;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    rooms.insert(sceneJson(generateRoomScene(seed)));
    blocks.insert(sceneJson(generateBlocksScene(seed)));
    labels.insert(render(generateBlocksScene(seed), SensorModel::none, seed).labels);
  }
  EXPECT_EQ(rooms.size(), 8U);
  EXPECT_EQ(blocks.size(), 8U);
  EXPECT_EQ(labels.size(), 8U);
  // The room and the blocks of one seed are drawn from separate streams: not the same scene.
  EXPECT_NE(generateRoomScene(3).primitives.size(), 0U);
  EXPECT_NE(sceneJson(generateRoomScene(3)), sceneJson(generateBlocksScene(3)));
}

// Whether `point` (world frame) lies on the curved surface of a sphere or on the side of a
// cylinder of the scene, within `tolerance`.
bool onCurvedSurface(const Scene& scene, const Eigen::Vector3d& point, double tolerance) {
  for (const Primitive& primitive : scene.primitives) {
    if (const auto* sphere = std::get_if<Sphere>(&primitive.shape)) {
      if (std::abs((point - sphere->center).norm() - sphere->radius) <= tolerance) return true;
    } else if (const auto* cylinder = std::get_if<Cylinder>(&primitive.shape)) {
      const Eigen::Vector3d axis = cylinder->axis.normalized();
      const Eigen::Vector3d offset = point - cylinder->base;
      const double along = offset.dot(axis);
      const double across = (offset - along * axis).norm();
      if (std::abs(across - cylinder->radius) <= tolerance && along >= -tolerance &&
          along <= cylinder->height + tolerance) {
        return true;
      }
    }
  }
  return false;
}

// Every labelled pixel of the exact render lies on its ground-truth plane, which faces the
// camera; every unlabelled pixel with a point lies on a curved surface; plane pixel counts match
// the labels.
void expectConsistentGroundTruth(const Scene& scene, std::size_t& curved_pixels) {
  const RenderedFrame frame = render(scene, SensorModel::none, 1);
  std::vector<std::size_t> counts(frame.planes.size() + 1, 0);
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    const Eigen::Vector3f& point = frame.points[i];
    const std::uint32_t label = frame.labels[i];
    ++counts[label];
    if (isNaN(point)) {
      ASSERT_EQ(label, 0U) << "pixel " << i;
      continue;
    }
    if (label == 0) {
      ++curved_pixels;
      // Curved surfaces are measured in the world frame: the camera pose adds round-off.
      const Eigen::Vector3d world = scene.world_from_camera * point.cast<double>();
      ASSERT_TRUE(onCurvedSurface(scene, world, 10.0 * roundOff(point))) << "pixel " << i;
      continue;
    }
    const GroundTruthPlane& plane = frame.planes[label - 1];
    ASSERT_TRUE(plane.faces_camera) << "pixel " << i;
    ASSERT_NEAR(plane.normal.dot(point.cast<double>()) + plane.d, 0.0, roundOff(point))
        << "pixel " << i << " on " << plane.primitive << " " << plane.face;
  }
  for (const GroundTruthPlane& plane : frame.planes) {
    EXPECT_EQ(plane.pixel_count, counts[plane.id]) << plane.primitive << " " << plane.face;
  }
}

TEST(RandomScenes, GroundTruthHoldsForEveryPixelOfTheExactRender) {
  std::size_t curved_pixels = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expectConsistentGroundTruth(generateRoomScene(seed), curved_pixels);
    expectConsistentGroundTruth(generateBlocksScene(seed), curved_pixels);
  }
  EXPECT_GT(curved_pixels, 1000U);  // the check of unlabelled pixels has something to check
}

// The camera centre is at least 0.5 m from every surface (so nothing touches the lens and the
// Kinect's 0.45 m minimum range is respected) and the nearest surface is at most 6 m away; no
// point of the exact render is nearer than 0.5 m; the centre pixel sees a surface 0.5-6 m away.
TEST(RandomScenes, CameraIsHalfAMetreToSixMetresFromTheNearestSurface) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    for (const Scene& scene : {generateRoomScene(seed), generateBlocksScene(seed)}) {
      const Eigen::Vector3d camera = scene.world_from_camera.translation();
      const double clearance = nearestSurfaceDistance(scene, camera);
      EXPECT_GE(clearance, 0.5);
      EXPECT_LE(clearance, 6.0);
      EXPECT_FALSE(insideAnySolid(scene, camera));
      Scene small = scene;
      small.intrinsics = scene.intrinsics.scaledTo(scene.intrinsics.width / 4, scene.intrinsics.height / 4);
      const RenderedFrame frame = render(small, SensorModel::none, seed);
      for (const Eigen::Vector3f& point : frame.points) {
        if (!isNaN(point)) {
          ASSERT_GE(point.norm(), 0.5F);
        }
      }
      const Eigen::Vector3f centre =
          frame.points[frame.points.size() / 2 + static_cast<std::size_t>(small.intrinsics.width / 2)];
      ASSERT_FALSE(isNaN(centre));
      EXPECT_LE(centre.norm(), 6.0F);
    }
  }
}

// A typical room frame shows several planes (at least five with 0.5 % of the pixels each, none
// over 60 %) and has a surface in at least 85 % of its pixels.
TEST(RandomScenes, RoomsShowSeveralPlanesOverMostOfTheImage) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const RenderedFrame frame = render(generateRoomScene(seed), SensorModel::none, seed);
    const auto pixels = static_cast<double>(frame.points.size());
    int planes = 0;
    double largest = 0.0;
    for (const GroundTruthPlane& plane : frame.planes) {
      const double share = static_cast<double>(plane.pixel_count) / pixels;
      planes += share >= 0.005 ? 1 : 0;
      largest = std::max(largest, share);
    }
    const auto hits = std::count_if(frame.points.begin(), frame.points.end(), [](const auto& p) { return !isNaN(p); });
    EXPECT_GE(planes, 5);
    EXPECT_LE(largest, 0.6);
    EXPECT_GE(static_cast<double>(hits) / pixels, 0.85);
  }
}

// The blocks the scanner sees have faces 2-5 cm across that meet at 10-30 degrees: among the
// planes visible in the first scenes, pairs of faces of one block whose normals are 10-30
// degrees apart, and the table under them.
TEST(RandomScenes, BlocksHaveFacesMeetingAtShallowAngles) {
  int shallow_pairs = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const RenderedFrame frame = render(generateBlocksScene(seed), SensorModel::none, seed);
    std::vector<const GroundTruthPlane*> visible;
    for (const GroundTruthPlane& plane : frame.planes) {
      if (plane.pixel_count >= 100) visible.push_back(&plane);
    }
    ASSERT_FALSE(visible.empty());
    EXPECT_EQ(visible.front()->primitive, "table");
    for (std::size_t i = 0; i < visible.size(); ++i) {
      for (std::size_t j = i + 1; j < visible.size(); ++j) {
        if (visible[i]->primitive != visible[j]->primitive) continue;
        const double angle = std::acos(std::clamp(visible[i]->normal.dot(visible[j]->normal), -1.0, 1.0)) * 180.0 / kPi;
        shallow_pairs += angle >= 10.0 && angle <= 30.0 ? 1 : 0;
      }
    }
  }
  EXPECT_GE(shallow_pairs, 3);
}

}  // namespace
