// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The boards family (issue 26, thin faces): one seed, one scene, byte for byte; boards that are
// boxes 2 cm thick along their own y, inside the room, of the kinds and ranges the header
// names; every face of every board its own ground-truth plane, the edges told apart by
// isBoardEdgeFace; a camera 0.8-3.5 m from a board that sees a 2 cm edge with at least
// pcd_segment's smallest plane of pixels.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "synth/renderer.h"
#include "synth/scene_file.h"
#include "synth/scene_generator.h"
#include "synth/surface_distance.h"

namespace {

using namespace floodplane::synth;

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kMinInliers = 307;  // pcd_segment's default at 640 x 480

RenderedFrame render(const Scene& scene, SensorModel sensor, std::uint64_t seed) {
  RenderSettings settings;
  settings.sensor = sensor;
  settings.seed = seed;
  return renderScene(scene, settings);
}

// "leaning" for "leaning board 2", "" for the room's surfaces.
std::string kindOf(const std::string& name) {
  const std::size_t space = name.find(" board ");
  return space == std::string::npos ? "" : name.substr(0, space);
}

std::vector<const Primitive*> boardsOf(const Scene& scene) {
  std::vector<const Primitive*> boards;
  for (const Primitive& primitive : scene.primitives) {
    if (!kindOf(primitive.name).empty()) boards.push_back(&primitive);
  }
  return boards;
}

std::vector<Eigen::Vector3d> corners(const Box& box) {
  std::vector<Eigen::Vector3d> points;
  for (const double x : {-0.5, 0.5}) {
    for (const double y : {-0.5, 0.5}) {
      for (const double z : {-0.5, 0.5}) {
        points.push_back(box.center + box.rotation * Eigen::Vector3d(x, y, z).cwiseProduct(box.size));
      }
    }
  }
  return points;
}

double angleDegrees(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / kPi;
}

TEST(BoardsScenes, AreNamedApartFromTheRoomsOfTheSameSeed) {
  EXPECT_EQ(boardsSceneName(7), "boards_0007");
  EXPECT_EQ(boardsSceneName(12345), "boards_12345");
  EXPECT_EQ(generateBoardsScene(7).name, "boards_0007");
  EXPECT_NE(generateBoardsScene(7).name, generateRoomScene(7).name);
}

TEST(BoardsScenes, OneSeedGivesTheSameSceneAndFrameByteForByteAndSeedsDiffer) {
  for (const std::uint64_t seed : {3, 150}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Scene scene = generateBoardsScene(seed);
    EXPECT_EQ(sceneJson(scene), sceneJson(generateBoardsScene(seed)));
    const RenderedFrame a = render(scene, SensorModel::kinect, seed);
    const RenderedFrame b = render(generateBoardsScene(seed), SensorModel::kinect, seed);
    EXPECT_EQ(a.labels, b.labels);
    ASSERT_EQ(a.points.size(), b.points.size());
    EXPECT_EQ(std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(Eigen::Vector3f)), 0);
  }
  std::set<std::string> scenes;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) scenes.insert(sceneJson(generateBoardsScene(seed)));
  EXPECT_EQ(scenes.size(), 8U);
}

TEST(BoardsScenes, BoardsAreBoxes2CmThickAlongTheirOwnYInsideTheRoomAsTheirKindSays) {
  std::map<std::string, int> kinds;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Scene scene = generateBoardsScene(seed);
    const std::vector<const Primitive*> boards = boardsOf(scene);
    EXPECT_GE(boards.size(), 2U);
    EXPECT_LE(boards.size(), 5U);
    // The floor's outline bounds the room.
    const auto floor = std::find_if(scene.primitives.begin(), scene.primitives.end(),
                                    [](const Primitive& p) { return p.name == "floor"; });
    ASSERT_NE(floor, scene.primitives.end());
    Eigen::Vector3d low = Eigen::Vector3d::Constant(1e9);
    Eigen::Vector3d high = -low;
    for (const Eigen::Vector3d& v : std::get<Polygon>(floor->shape).vertices) {
      low = low.cwiseMin(v);
      high = high.cwiseMax(v);
    }
    for (const Primitive& primitive : scene.primitives) {
      const bool room =
          primitive.name == "floor" || primitive.name == "ceiling" || primitive.name.rfind("wall ", 0) == 0;
      EXPECT_TRUE(room || !kindOf(primitive.name).empty()) << primitive.name;
    }
    for (const Primitive* board : boards) {
      SCOPED_TRACE(board->name);
      ASSERT_TRUE(std::holds_alternative<Box>(board->shape));
      const Box& box = std::get<Box>(board->shape);
      EXPECT_NEAR(box.size.y(), 0.02, 1e-12);
      EXPECT_GE(box.size.x(), 0.2);
      EXPECT_LE(box.size.x(), 1.0);
      EXPECT_GE(box.size.z(), 0.2);
      EXPECT_LE(box.size.z(), 1.8);
      EXPECT_NEAR((box.rotation.transpose() * box.rotation - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
      EXPECT_NEAR(box.rotation.determinant(), 1.0, 1e-12);
      for (const Eigen::Vector3d& corner : corners(box)) {
        EXPECT_GE(corner.x(), -1e-9);
        EXPECT_GE(corner.y(), -1e-9);
        EXPECT_GE(corner.z(), -1e-9);
        EXPECT_LE(corner.x(), high.x() + 1e-9);
        EXPECT_LE(corner.y(), high.y() + 1e-9);
      }
      double bottom = 1e9;
      for (const Eigen::Vector3d& corner : corners(box)) bottom = std::min(bottom, corner.z());
      const Eigen::Vector3d thickness_axis = box.rotation.col(1);
      const Eigen::Vector3d length_axis = box.rotation.col(2);
      const std::string kind = kindOf(board->name);
      ++kinds[kind];
      if (kind == "standing") {
        EXPECT_NEAR(bottom, 0.0, 1e-9);
        EXPECT_NEAR(angleDegrees(length_axis, Eigen::Vector3d::UnitZ()), 0.0, 1e-6);
      } else if (kind == "hung") {
        EXPECT_GE(bottom, 0.3 - 1e-9);
        EXPECT_NEAR(angleDegrees(length_axis, Eigen::Vector3d::UnitZ()), 0.0, 1e-6);
      } else if (kind == "leaning") {
        EXPECT_NEAR(bottom, 0.0, 1e-9);
        const double lean = angleDegrees(length_axis, Eigen::Vector3d::UnitZ());
        EXPECT_GE(lean, 5.0 - 1e-9);
        EXPECT_LE(lean, 25.0 + 1e-9);
      } else if (kind == "lying") {
        EXPECT_NEAR(bottom, 0.0, 1e-9);
        EXPECT_NEAR(std::abs(thickness_axis.z()), 1.0, 1e-12);
      } else {
        EXPECT_EQ(kind, "shelf");
        EXPECT_GE(bottom, 0.7 - 0.01 - 1e-9);
        EXPECT_NEAR(std::abs(thickness_axis.z()), 1.0, 1e-12);
        EXPECT_LE(box.size.z(), 0.4);
      }
    }
  }
  // Every kind turns up in 30 seeds.
  for (const std::string kind : {"standing", "hung", "leaning", "lying", "shelf"}) {
    EXPECT_GT(kinds[kind], 0) << kind;
  }
}

TEST(BoardsScenes, EveryFaceOfEveryBoardIsItsOwnGroundTruthPlaneAndTheEdgesAreTheFacesAcrossItsThickness) {
  for (const std::uint64_t seed : {1, 2, 3, 4}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Scene scene = generateBoardsScene(seed);
    const RenderedFrame frame = render(scene, SensorModel::none, seed);
    for (const Primitive* board : boardsOf(scene)) {
      SCOPED_TRACE(board->name);
      const Box& box = std::get<Box>(board->shape);
      std::set<std::string> faces;
      std::set<std::uint32_t> ids;
      for (const GroundTruthPlane& plane : frame.planes) {
        if (plane.primitive != board->name) continue;
        faces.insert(plane.face);
        ids.insert(plane.id);
        EXPECT_EQ(plane.merged_into, 0U) << plane.face;
        // The face's normal, in the world: an edge's lies across the board's thickness axis.
        const Eigen::Vector3d normal = scene.world_from_camera.linear() * plane.normal;
        const bool across_thickness = std::abs(normal.dot(box.rotation.col(1))) < 1e-6;
        EXPECT_EQ(isBoardEdgeFace(plane.primitive, plane.face), across_thickness) << plane.face;
      }
      EXPECT_EQ(faces, (std::set<std::string>{"+x", "-x", "+y", "-y", "+z", "-z"}));
      EXPECT_EQ(ids.size(), 6U);
    }
  }
  EXPECT_TRUE(isBoardEdgeFace("leaning board 2", "+x"));
  EXPECT_TRUE(isBoardEdgeFace("shelf board 1", "-z"));
  EXPECT_FALSE(isBoardEdgeFace("leaning board 2", "+y"));
  EXPECT_FALSE(isBoardEdgeFace("leaning board 2", "-y"));
  EXPECT_FALSE(isBoardEdgeFace("wall 1", ""));
  EXPECT_FALSE(isBoardEdgeFace("table 1 top", "+x"));
  EXPECT_FALSE(isBoardEdgeFace("leaning board x", "+x"));
  EXPECT_FALSE(isBoardEdgeFace("leaning board 2 top", "+x"));
}

TEST(BoardsScenes, TheCameraStands08To35MFromABoardAndSeesA2CmEdgeWithAPlanesWorthOfPixels) {
  std::size_t edges_seen = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Scene scene = generateBoardsScene(seed);
    EXPECT_EQ(scene.intrinsics.width, 640);
    EXPECT_EQ(scene.intrinsics.height, 480);
    const Eigen::Vector3d camera = scene.world_from_camera.translation();
    EXPECT_GE(nearestSurfaceDistance(scene, camera), 0.5);
    double nearest_board = 1e9;
    for (const Primitive* board : boardsOf(scene)) {
      nearest_board = std::min(nearest_board, (std::get<Box>(board->shape).center - camera).norm());
    }
    EXPECT_LE(nearest_board, 3.5 + 1.0);  // the camera aims at a point of a board, within 3.5 m
    const RenderedFrame frame = render(scene, SensorModel::none, seed);
    std::size_t largest_edge = 0;
    for (const GroundTruthPlane& plane : frame.planes) {
      if (!isBoardEdgeFace(plane.primitive, plane.face)) continue;
      largest_edge = std::max(largest_edge, plane.pixel_count);
      edges_seen += plane.pixel_count >= kMinInliers ? 1 : 0;
    }
    // The pose check renders at 320 x 240 and asks for 77 pixels: about 308 here.
    EXPECT_GE(largest_edge, kMinInliers - 20);
  }
  EXPECT_GE(edges_seen, 12U);
}

}  // namespace
