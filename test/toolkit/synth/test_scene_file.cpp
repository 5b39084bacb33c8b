// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The scene file format: the keys added for prisms, holes and matrix rotations, clear errors
// for bad values, and scenes written by sceneJson reading back into the same scene exactly.

#include "synth/scene_file.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstring>
#include <string>

#include "synth/renderer.h"

namespace {

using namespace floodplane::synth;

constexpr const char* kCamera = R"("camera": {"position": [3, 0.5, 1.5], "look_at": [0, 0, 0.5]})";

std::string sceneWith(const std::string& primitives) {
  return std::string("{") + kCamera + R"(, "primitives": [)" + primitives + "]}";
}

void expectError(const std::string& text, const std::string& expected_part) {
  try {
    parseScene(text, "scenes/bad.json");
    ADD_FAILURE() << "no error; expected one containing \"" << expected_part << "\"";
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("scenes/bad.json: ", 0), 0U) << message;
    EXPECT_NE(message.find(expected_part), std::string::npos) << message;
  }
}

TEST(SceneFile, ReadsPrismsHolesAndMatrixRotations) {
  const Scene scene = parseScene(sceneWith(R"(
    {"type": "prism", "name": "wedge", "base": [[0, 0, 0], [0.3, 0, 0], [0, 0, 0.1]], "extrusion": [0, 0.2, 0]},
    {"type": "polygon", "name": "wall", "vertices": [[-1, -2, 0], [-1, 2, 0], [-1, 2, 3], [-1, -2, 3]],
     "holes": [[[-1, -0.4, 0], [-1, 0.4, 0], [-1, 0.4, 2], [-1, -0.4, 2]]]},
    {"type": "box", "center": [0, 1, 0.2], "size": [0.4, 0.4, 0.4],
     "rotation": {"matrix": [[0, -1, 0], [1, 0, 0], [0, 0, 1]]}})"),
                                 "scenes/new_keys.json");
  ASSERT_EQ(scene.primitives.size(), 3U);
  const auto& wedge = std::get<Prism>(scene.primitives[0].shape);
  ASSERT_EQ(wedge.base.size(), 3U);
  EXPECT_EQ(wedge.base[1], Eigen::Vector3d(0.3, 0.0, 0.0));
  EXPECT_EQ(wedge.extrusion, Eigen::Vector3d(0.0, 0.2, 0.0));
  const auto& wall = std::get<Polygon>(scene.primitives[1].shape);
  ASSERT_EQ(wall.holes.size(), 1U);
  EXPECT_EQ(wall.holes[0][2], Eigen::Vector3d(-1.0, 0.4, 2.0));
  const auto& box = std::get<Box>(scene.primitives[2].shape);
  EXPECT_EQ(box.rotation * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());  // a quarter turn about z
}

TEST(SceneFile, CameraMayBeGivenByItsRotation) {
  // Axes of world_from_camera as columns: right = -y, down = -z, forward = +x.
  const Scene scene = parseScene(R"({"camera": {"position": [1, 2, 3], "rotation": {"matrix":
      [[0, 0, 1], [-1, 0, 0], [0, -1, 0]]}}, "primitives": []})",
                                 "scenes/pose.json");
  EXPECT_EQ(scene.world_from_camera.translation(), Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_EQ(scene.world_from_camera.linear().col(2), Eigen::Vector3d::UnitX());
  EXPECT_EQ(scene.world_from_camera.linear().col(1), -Eigen::Vector3d::UnitZ());
}

TEST(SceneFile, BadPrismsHolesAndRotationsGiveMessagesNamingTheKey) {
  expectError(sceneWith(R"({"type": "prism", "base": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]})"),
              "primitives[0] (prism): missing \"extrusion\"");
  expectError(sceneWith(R"({"type": "prism", "base": [[0, 0, 0], [1, 0], [0, 1, 0]], "extrusion": [0, 0, 1]})"),
              "\"base[1]\" must be an array of 3 numbers");
  expectError(sceneWith(R"({"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": [[0, 0, 0]]})"),
              "\"holes[0][0]\" must be an array of 3 numbers");
  expectError(sceneWith(R"({"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "holes": 3})"),
              "\"holes\" must be an array of lists");
  expectError(sceneWith(R"({"type": "box", "center": [0, 0, 0], "size": [1, 1, 1],
      "rotation": {"matrix": [[1, 0, 0], [0, 1, 0]]}})"),
              "\"matrix\" must be an array of 3 rows");
  expectError(sceneWith(R"({"type": "box", "center": [0, 0, 0], "size": [1, 1, 1],
      "rotation": {"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "rpy_deg": [0, 0, 0]}})"),
              "give one of");
  expectError(R"({"camera": {"position": [0, 0, 0], "look_at": [1, 0, 0],
      "rotation": {"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}}, "primitives": []})",
              "camera: give either \"look_at\"");
  expectError(R"({"camera": {"position": [0, 0, 0], "rotation": {"matrix": [[2, 0, 0], [0, 1, 0], [0, 0, 1]]}},
      "primitives": []})",
              "camera: rotation is not a rotation matrix");
  expectError(sceneWith(R"({"type": "cone", "base": [0, 0, 0]})"), "or prism)");
}

// A scene with every kind of primitive, a rotated box and an aimed camera, with decimals that
// have no short exact binary form.
Scene everyKindOfPrimitive() {
  Scene scene;
  scene.name = "every";
  scene.source = "test scene";
  scene.description = "every kind of \"primitive\"";
  scene.intrinsics = CameraIntrinsics{}.scaledTo(160, 120);
  scene.world_from_camera = lookAt({3.1, 0.7, 1.3}, {0.1, -0.2, 0.4}, Eigen::Vector3d::UnitZ());
  Polygon wall{{{-1.3, -3, 0}, {-1.3, 3, 0}, {-1.3, 3, 2.7}, {-1.3, -3, 2.7}},
               {{{-1.3, -0.45, 0.3}, {-1.3, 0.45, 0.3}, {-1.3, 0.45, 1.9}, {-1.3, -0.45, 1.9}}}};
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, 0.1, 1.0).normalized()).toRotationMatrix();
  scene.primitives = {
      {"floor", Rectangle{{0, 0, 0}, {8, 0, 0}, {0, 8, 0}}},
      {"wall", wall},
      {"crate", Box{{0.3, 0.9, 0.35}, {0.7, 0.5, 0.7}, turn}},
      {"ball", Sphere{{0.9, -0.8, 0.3}, 0.3}},
      {"can", Cylinder{{0.2, -0.1, 0.0}, {0.1, 0.0, 1.0}, 0.15, 0.45}},
      {"wedge", Prism{{{-0.4, -1.1, 0}, {0.3, -1.1, 0}, {-0.4, -1.1, 0.21}}, {0.05, -0.5, 0}}},
      {"", Rectangle{{-1.2, 1.5, 0.9}, {0, 0.6, 0}, {0, 0, 0.4}}},
  };
  return scene;
}

TEST(SceneFile, WrittenScenesReadBackIntoTheSameSceneAndRenderTheSameBytes) {
  const Scene scene = everyKindOfPrimitive();
  const std::string text = sceneJson(scene);
  const Scene read_back = parseScene(text, "every.json");
  EXPECT_EQ(read_back.description, scene.description);
  EXPECT_TRUE(read_back.world_from_camera.matrix() == scene.world_from_camera.matrix());
  EXPECT_EQ(read_back.intrinsics.width, 160);
  EXPECT_EQ(read_back.intrinsics.cx, scene.intrinsics.cx);
  ASSERT_EQ(read_back.primitives.size(), scene.primitives.size());
  EXPECT_EQ(read_back.primitives[6].name, "");
  EXPECT_EQ(sceneJson(read_back), text);  // a fixed point

  RenderSettings settings;
  settings.sensor = SensorModel::kinect;
  const RenderedFrame original = renderScene(scene, settings);
  const RenderedFrame copy = renderScene(read_back, settings);
  EXPECT_EQ(original.labels, copy.labels);
  ASSERT_EQ(original.points.size(), copy.points.size());
  EXPECT_EQ(std::memcmp(original.points.data(), copy.points.data(), original.points.size() * sizeof(Eigen::Vector3f)),
            0);
  std::size_t labelled = 0;
  for (std::uint32_t label : original.labels) labelled += label > 0 ? 1 : 0;
  EXPECT_GT(labelled, original.labels.size() / 2);  // the comparison is not between two empty frames
}

}  // namespace
