// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Prisms and polygons with holes against geometry worked out independently: every pixel of a
// prism lies on the face its label names and inside the solid, each face's plane holds that
// face's corners, faces turned away get no pixels, rays through a concave notch or a hole go on
// to what lies behind, and bad prisms are rejected with a message.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "synth/renderer.h"

namespace {

using namespace floodplane::synth;

constexpr double kPi = 3.14159265358979323846;

// Points are floats: 1e-6 of the distance to the camera bounds their round-off.
double roundOff(const Eigen::Vector3f& point) { return 1e-6 * std::max(1.0, static_cast<double>(point.norm())); }

bool isNaN(const Eigen::Vector3f& point) { return std::isnan(point.x()); }

Scene sceneFrom(const Eigen::Vector3d& position, const Eigen::Vector3d& target, std::vector<Primitive> primitives) {
  Scene scene;
  scene.name = "test";
  scene.source = "test scene";
  scene.world_from_camera = lookAt(position, target, Eigen::Vector3d::UnitZ());
  scene.primitives = std::move(primitives);
  return scene;
}

RenderedFrame renderExact(const Scene& scene) {
  RenderSettings settings;
  settings.sensor = SensorModel::none;
  return renderScene(scene, settings);
}

// A face of a prism worked out from its definition: corners and outward normal (world frame).
struct Face {
  std::vector<Eigen::Vector3d> corners;
  Eigen::Vector3d outward;
};

// A convex base (counter-clockwise seen from above, z = 0.1) swept along an oblique extrusion.
// Faces in the order the renderer numbers them: top, bottom, side 0 ... side n-1.
std::vector<Face> convexPrismFaces(const Prism& prism) {
  std::vector<Face> faces;
  const std::size_t n = prism.base.size();
  std::vector<Eigen::Vector3d> top;
  for (const auto& vertex : prism.base) top.push_back(vertex + prism.extrusion);
  faces.push_back({top, Eigen::Vector3d::UnitZ()});
  faces.push_back({prism.base, -Eigen::Vector3d::UnitZ()});
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = prism.base[i];
    const Eigen::Vector3d& b = prism.base[(i + 1) % n];
    // Counter-clockwise base and upward extrusion: (b - a) x extrusion points out.
    faces.push_back({{a, b, b + prism.extrusion, a + prism.extrusion}, (b - a).cross(prism.extrusion).normalized()});
  }
  return faces;
}

Prism obliqueHexagonalPrism() {
  Prism prism;
  for (int k = 0; k < 6; ++k) {
    const double angle = 2.0 * kPi * k / 6.0 + 0.2;
    // Unequal radii: a convex but irregular hexagon, sides meeting at different angles.
    const double radius = k % 2 == 0 ? 0.30 : 0.26;
    prism.base.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.1);
  }
  prism.extrusion = Eigen::Vector3d(0.08, -0.05, 0.35);  // oblique: the sides are parallelograms
  return prism;
}

TEST(Prism, EveryPixelLiesOnTheFaceItsLabelNamesAndInsideTheSolid) {
  const Prism prism = obliqueHexagonalPrism();
  const std::vector<Face> faces = convexPrismFaces(prism);
  const std::vector<Eigen::Vector3d> cameras{{1.6, -1.2, 1.3}, {-1.4, 0.3, 0.25}, {0.2, 0.1, 2.0}};
  for (const Eigen::Vector3d& position : cameras) {
    SCOPED_TRACE("camera at " + std::to_string(position.x()) + ", " + std::to_string(position.y()) + ", " +
                 std::to_string(position.z()));
    const Scene scene = sceneFrom(position, Eigen::Vector3d(0.0, 0.0, 0.25), {{"block", prism}});
    const RenderedFrame frame = renderExact(scene);
    ASSERT_EQ(frame.planes.size(), faces.size());
    const Eigen::Isometry3d camera_from_world = scene.world_from_camera.inverse();

    std::set<std::uint32_t> facing;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const GroundTruthPlane& plane = frame.planes[f];
      EXPECT_EQ(plane.face, f == 0 ? "top" : f == 1 ? "bottom" : "side " + std::to_string(f - 2));
      // The listed plane holds the face's corners, and faces the camera exactly when the camera
      // is on the outer side of the face.
      for (const auto& corner : faces[f].corners) {
        EXPECT_NEAR(plane.normal.dot(camera_from_world * corner) + plane.d, 0.0, 1e-12) << "face " << f;
      }
      const bool faces_camera = faces[f].outward.dot(position - faces[f].corners[0]) > 0.0;
      EXPECT_EQ(plane.faces_camera, faces_camera) << "face " << f;
      if (faces_camera) facing.insert(plane.id);
    }

    std::set<std::uint32_t> seen;
    for (std::size_t i = 0; i < frame.points.size(); ++i) {
      if (isNaN(frame.points[i])) {
        ASSERT_EQ(frame.labels[i], 0U);
        continue;
      }
      const std::uint32_t label = frame.labels[i];
      ASSERT_GE(label, 1U) << "pixel " << i;
      ASSERT_LE(label, faces.size()) << "pixel " << i;
      seen.insert(label);
      const double tolerance = roundOff(frame.points[i]);
      const Eigen::Vector3d world = scene.world_from_camera * frame.points[i].cast<double>();
      const Face& face = faces[label - 1];
      ASSERT_NEAR(face.outward.dot(world - face.corners[0]), 0.0, tolerance) << "pixel " << i;
      for (const Face& other : faces) {  // inside every face's half-space
        ASSERT_LE(other.outward.dot(world - other.corners[0]), tolerance) << "pixel " << i;
      }
    }
    EXPECT_EQ(seen, facing);
  }
}

// An L-shaped block (non-convex base) seen from the side of its notch: rays into the notch
// pass the block and hit the wall behind it.
TEST(Prism, RaysIntoAConcaveNotchCrossItAndMeetTheFaceAtItsBack) {
  Prism block;
  block.base = {{0.0, 0.0, 0.0}, {0.6, 0.0, 0.0}, {0.6, 0.2, 0.0}, {0.2, 0.2, 0.0}, {0.2, 0.6, 0.0}, {0.0, 0.6, 0.0}};
  block.extrusion = Eigen::Vector3d(0.0, 0.0, 0.3);
  // The wall at x = -1, seen from x = +3 looking along -x, a little above the block.
  const Rectangle wall{Eigen::Vector3d(-1.0, 0.3, 0.5), Eigen::Vector3d(0.0, 8.0, 0.0), Eigen::Vector3d(0.0, 0.0, 8.0)};
  const Scene scene = sceneFrom({3.0, 0.45, 0.15}, {0.0, 0.45, 0.15}, {{"L", block}, {"wall", wall}});
  const RenderedFrame frame = renderExact(scene);
  const std::uint32_t wall_id = static_cast<std::uint32_t>(frame.planes.size());
  ASSERT_EQ(frame.planes[wall_id - 1].primitive, "wall");

  std::size_t notch_rays = 0;
  for (int v = 0; v < scene.intrinsics.height; ++v) {
    for (int u = 0; u < scene.intrinsics.width; ++u) {
      const Eigen::Vector3d ray = scene.world_from_camera.linear() * scene.intrinsics.rayThroughPixel(u, v);
      const Eigen::Vector3d origin = scene.world_from_camera.translation();
      // Rays that stay within y in (0.22, 0.58) and z in (0.02, 0.28) from x = 0.6 to x = 0.2
      // cross the notch (x > 0.2, y > 0.2) and meet the face x = 0.2 of the arm along y.
      const double s0 = (0.6 - origin.x()) / ray.x();
      const double s1 = (0.2 - origin.x()) / ray.x();
      const Eigen::Vector3d enter = origin + s0 * ray;
      const Eigen::Vector3d leave = origin + s1 * ray;
      const bool in_notch = std::min(enter.y(), leave.y()) > 0.22 && std::max(enter.y(), leave.y()) < 0.58 &&
                            std::min(enter.z(), leave.z()) > 0.02 && std::max(enter.z(), leave.z()) < 0.28;
      if (!in_notch) continue;
      ++notch_rays;
      const std::size_t i =
          static_cast<std::size_t>(v) * static_cast<std::size_t>(scene.intrinsics.width) + static_cast<std::size_t>(u);
      // Side 3 runs from vertex 3 (0.2, 0.2) to vertex 4 (0.2, 0.6).
      ASSERT_EQ(frame.planes[frame.labels[i] - 1].face, "side 3") << "pixel " << u << ", " << v;
      const Eigen::Vector3d world = scene.world_from_camera * frame.points[i].cast<double>();
      ASSERT_NEAR(world.x(), 0.2, roundOff(frame.points[i]));
    }
  }
  EXPECT_GT(notch_rays, 1000U);
}

TEST(Polygon, RaysThroughAHoleHitWhatIsBehindIt) {
  // A wall at x = 0 with a 0.8 x 1.2 hole, a back wall at x = -2; camera at x = 3.
  Polygon wall;
  wall.vertices = {{0.0, -3.0, 0.0}, {0.0, 3.0, 0.0}, {0.0, 3.0, 3.0}, {0.0, -3.0, 3.0}};
  wall.holes = {{{0.0, -0.4, 0.6}, {0.0, 0.4, 0.6}, {0.0, 0.4, 1.8}, {0.0, -0.4, 1.8}}};
  const Rectangle back{Eigen::Vector3d(-2.0, 0.0, 1.5), Eigen::Vector3d(0.0, 20.0, 0.0),
                       Eigen::Vector3d(0.0, 0.0, 20.0)};
  const Scene scene = sceneFrom({3.0, 0.1, 1.3}, {0.0, 0.0, 1.2}, {{"wall", wall}, {"back", back}});
  const RenderedFrame frame = renderExact(scene);
  ASSERT_EQ(frame.planes.size(), 2U);
  std::size_t through_hole = 0;
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    ASSERT_FALSE(isNaN(frame.points[i]));
    const Eigen::Vector3d world = scene.world_from_camera * frame.points[i].cast<double>();
    const Eigen::Vector3d origin = scene.world_from_camera.translation();
    const Eigen::Vector3d at_wall = origin + (world - origin) * (origin.x() / (origin.x() - world.x()));
    const double margin = 1e-6;
    const bool in_hole =
        std::abs(at_wall.y()) < 0.4 - margin && at_wall.z() > 0.6 + margin && at_wall.z() < 1.8 - margin;
    const bool on_wall =
        std::abs(at_wall.y()) < 3.0 - margin && at_wall.z() > margin && at_wall.z() < 3.0 - margin &&
        (std::abs(at_wall.y()) > 0.4 + margin || at_wall.z() < 0.6 - margin || at_wall.z() > 1.8 + margin);
    if (in_hole) {
      ++through_hole;
      ASSERT_EQ(frame.labels[i], 2U) << "pixel " << i;
    } else if (on_wall) {
      ASSERT_EQ(frame.labels[i], 1U) << "pixel " << i;
    }
  }
  EXPECT_GT(through_hole, 5000U);
}

void expectSceneError(const Prism& prism, const std::string& expected_part, const Eigen::Vector3d& camera) {
  const Scene scene = sceneFrom(camera, Eigen::Vector3d(0.1, 0.1, 0.1), {{"bad", prism}});
  try {
    renderExact(scene);
    ADD_FAILURE() << "no error; expected one containing \"" << expected_part << "\"";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find(expected_part), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("primitives[0] (prism \"bad\")"), std::string::npos) << error.what();
  }
}

TEST(Prism, BadPrismsAreRejectedWithAMessageNamingThePrimitive) {
  const Eigen::Vector3d far_camera(3.0, 2.0, 2.0);
  Prism flat;  // extrusion in the base's plane
  flat.base = {{0, 0, 0}, {0.3, 0, 0}, {0.3, 0.3, 0}};
  flat.extrusion = Eigen::Vector3d(0.1, 0.1, 0.0);
  expectSceneError(flat, "extrusion must leave the base's plane", far_camera);

  Prism bent = flat;  // one vertex 5 mm off the plane of the others
  bent.base.emplace_back(0.0, 0.3, 0.005);
  bent.extrusion = Eigen::Vector3d(0, 0, 0.2);
  expectSceneError(bent, "not planar", far_camera);

  Prism bow_tie;  // edges 0 and 2 cross
  bow_tie.base = {{0, 0, 0}, {0.4, 0.3, 0}, {0.4, 0, 0}, {0, 0.2, 0}};
  bow_tie.extrusion = Eigen::Vector3d(0, 0, 0.2);
  expectSceneError(bow_tie, "not a simple polygon", far_camera);

  Prism two_points;
  two_points.base = {{0, 0, 0}, {0.3, 0, 0}};
  two_points.extrusion = Eigen::Vector3d(0, 0, 0.2);
  expectSceneError(two_points, "at least 3 vertices", far_camera);

  Prism around_camera;
  around_camera.base = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  around_camera.extrusion = Eigen::Vector3d(0.2, 0, 2.0);  // oblique, and still around (0.1, 0, 1)
  expectSceneError(around_camera, "camera is inside this prism", Eigen::Vector3d(0.1, 0.0, 1.0));
}

}  // namespace
