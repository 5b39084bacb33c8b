// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The scene renderer against geometry worked out by hand: the pinhole camera, a plane, a box,
// a sphere and a cylinder in the exact model, the Kinect model's statistics and its bend,
// determinism, quirks that change nothing while off, and every scene file in data/scenes.

#include "synth/renderer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "floodplane/io/pcd_file.h"
#include "synth/ground_truth_json.h"
#include "synth/point_cloud.h"
#include "synth/scene_file.h"

namespace {

namespace fs = std::filesystem;
using namespace floodplane::synth;

constexpr double kPi = 3.14159265358979323846;

// Points are stored as floats: half an ulp is 6e-8 of a coordinate, so 1e-6 of the distance
// to the camera bounds the round-off of any point with room to spare.
double roundOff(const Eigen::Vector3f& point) { return 1e-6 * std::max(1.0, static_cast<double>(point.norm())); }

bool isNaN(const Eigen::Vector3f& point) {
  return std::isnan(point.x()) && std::isnan(point.y()) && std::isnan(point.z());
}

std::size_t pixelIndex(const CameraIntrinsics& intrinsics, int u, int v) {
  return static_cast<std::size_t>(v) * static_cast<std::size_t>(intrinsics.width) + static_cast<std::size_t>(u);
}

// A scene whose world frame is the camera frame (x right, y down, z forward).
Scene sceneInCameraFrame(std::vector<Primitive> primitives) {
  Scene scene;
  scene.name = "test";
  scene.source = "test scene";
  scene.primitives = std::move(primitives);
  return scene;
}

// A rectangle facing the camera at depth z, centred on the optical axis.
Primitive rectangleFacingCamera(double z, double width, double height) {
  return {"wall",
          Rectangle{Eigen::Vector3d(0.0, 0.0, z), Eigen::Vector3d(width, 0.0, 0.0), Eigen::Vector3d(0.0, height, 0.0)}};
}

RenderedFrame render(const Scene& scene, SensorModel sensor, std::uint64_t seed = 1) {
  RenderSettings settings;
  settings.sensor = sensor;
  settings.seed = seed;
  return renderScene(scene, settings);
}

// A ground-truth plane as the JSON side file lists it.
struct ListedPlane {
  std::uint32_t id;
  Eigen::Vector3d normal;
  double d;
  std::size_t pixels;
  bool faces_camera;
};

std::vector<ListedPlane> listedPlanes(const RenderedFrame& frame) {
  const nlohmann::json document = nlohmann::json::parse(groundTruthJson(frame));
  std::vector<ListedPlane> planes;
  for (const auto& entry : document.at("planes")) {
    const auto normal = entry.at("normal").get<std::vector<double>>();
    planes.push_back({entry.at("id").get<std::uint32_t>(), Eigen::Vector3d(normal.at(0), normal.at(1), normal.at(2)),
                      entry.at("d").get<double>(), entry.at("pixels").get<std::size_t>(),
                      entry.at("faces_camera").get<bool>()});
  }
  return planes;
}

std::vector<std::size_t> labelCounts(const RenderedFrame& frame) {
  std::vector<std::size_t> counts(frame.planes.size() + 1, 0);
  for (std::uint32_t label : frame.labels) {
    ++counts.at(label);
  }
  return counts;
}

// ---- Camera ----------------------------------------------------------------------------

TEST(Camera, PrincipalPointRayHitsThePointStraightAhead) {
  Scene scene = sceneInCameraFrame({rectangleFacingCamera(2.0, 20.0, 20.0)});
  // An odd image size puts the principal point on a pixel centre; fx != fy catches a swap.
  scene.intrinsics = {641, 481, 500.0, 550.0, 320.0, 240.0};
  EXPECT_EQ(scene.intrinsics.rayThroughPixel(320, 240), Eigen::Vector3d(0.0, 0.0, 1.0));

  const RenderedFrame frame = render(scene, SensorModel::none);
  EXPECT_EQ(frame.points[pixelIndex(scene.intrinsics, 320, 240)], Eigen::Vector3f(0.0F, 0.0F, 2.0F));
  // Every point projects back onto the centre of its own pixel.
  for (int v = 0; v < scene.intrinsics.height; v += 7) {
    for (int u = 0; u < scene.intrinsics.width; u += 7) {
      const Eigen::Vector3f& point = frame.points[pixelIndex(scene.intrinsics, u, v)];
      EXPECT_NEAR(500.0 * point.x() / point.z() + 320.0, u, 1e-3);
      EXPECT_NEAR(550.0 * point.y() / point.z() + 240.0, v, 1e-3);
    }
  }
}

TEST(Camera, ScalingKeepsThePrincipalPointAtTheSamePlaceInTheImage) {
  const CameraIntrinsics kinect;  // 640x480, f = 525, principal point at the image centre
  const CameraIntrinsics half = kinect.scaledTo(320, 240);
  EXPECT_DOUBLE_EQ(half.fx, 262.5);
  EXPECT_DOUBLE_EQ(half.fy, 262.5);
  EXPECT_DOUBLE_EQ(half.cx, 159.5);
  EXPECT_DOUBLE_EQ(half.cy, 119.5);
  const CameraIntrinsics twice = kinect.scaledTo(1280, 960);
  EXPECT_DOUBLE_EQ(twice.cx, 639.5);
  EXPECT_DOUBLE_EQ(twice.cy, 479.5);
  EXPECT_THROW(kinect.scaledTo(0, 240), std::invalid_argument);
}

TEST(Camera, LookAtPointsTheOpticalAxisAtTheTargetWithUpUpInTheImage) {
  const Eigen::Vector3d position(1.0, 2.0, 3.0);
  const Eigen::Vector3d target(4.0, 6.0, 3.0);
  const Eigen::Isometry3d world_from_camera = lookAt(position, target, Eigen::Vector3d::UnitZ());
  EXPECT_TRUE(world_from_camera.translation().isApprox(position));
  EXPECT_TRUE(world_from_camera.linear().col(2).isApprox(Eigen::Vector3d(0.6, 0.8, 0.0)));
  // Image y points down, so the camera's y axis is world -z here; x = y cross z.
  EXPECT_TRUE(world_from_camera.linear().col(1).isApprox(-Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(world_from_camera.linear().col(0).isApprox(Eigen::Vector3d(0.8, -0.6, 0.0)));
  EXPECT_THROW(lookAt(position, position, Eigen::Vector3d::UnitZ()), std::invalid_argument);
  EXPECT_THROW(lookAt(position, position + Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()), std::invalid_argument);
}

// ---- Exact geometry (sensor model none) ------------------------------------------------

TEST(Renderer, PlaneFacingTheCameraHasDepthOneAndOneLabelWhereverItCoversAPixel) {
  // 0.61 m x 0.41 m at z = 1: its edges fall between pixel centres (160.125 and 107.625 px
  // from the principal point), so it covers 2 * 160 columns and 2 * 108 rows.
  const Scene scene = sceneInCameraFrame({rectangleFacingCamera(1.0, 0.61, 0.41)});
  const RenderedFrame frame = render(scene, SensorModel::none);

  ASSERT_EQ(frame.planes.size(), 1U);
  const GroundTruthPlane& plane = frame.planes[0];
  EXPECT_EQ(plane.id, 1U);
  EXPECT_TRUE(plane.normal.isApprox(Eigen::Vector3d(0.0, 0.0, -1.0), 1e-12));  // towards camera
  EXPECT_NEAR(plane.d, 1.0, 1e-12);
  EXPECT_TRUE(plane.faces_camera);

  std::size_t covered = 0;
  for (int v = 0; v < scene.intrinsics.height; ++v) {
    for (int u = 0; u < scene.intrinsics.width; ++u) {
      const Eigen::Vector3d ray = scene.intrinsics.rayThroughPixel(u, v);
      const std::size_t i = pixelIndex(scene.intrinsics, u, v);
      const Eigen::Vector3f& point = frame.points[i];
      if (std::abs(ray.x()) < 0.305 && std::abs(ray.y()) < 0.205) {
        ++covered;
        ASSERT_EQ(frame.labels[i], 1U) << "pixel " << u << ", " << v;
        ASSERT_NEAR(point.z(), 1.0, 1e-6) << "pixel " << u << ", " << v;
        ASSERT_NEAR(point.x(), ray.x(), 1e-6) << "pixel " << u << ", " << v;
        ASSERT_NEAR(point.y(), ray.y(), 1e-6) << "pixel " << u << ", " << v;
      } else {
        ASSERT_TRUE(isNaN(point)) << "pixel " << u << ", " << v;
        ASSERT_EQ(frame.labels[i], 0U) << "pixel " << u << ", " << v;
      }
    }
  }
  EXPECT_EQ(covered, 320U * 216U);
  EXPECT_EQ(plane.pixel_count, covered);
}

// A box of size 0.8 x 0.5 x 0.7, turned 25 degrees about the vertical, seen by cameras from
// three places: straight in front of its +x face (one face visible), in front and above (two
// faces) and from a corner (three). A face is visible exactly when the camera is outside the
// face's slab on the face's side.
TEST(Renderer, BoxShowsAtMostThreeFacesAndEachPixelLiesOnTheFaceItsLabelNames) {
  const Eigen::Vector3d center(0.0, 0.0, 0.35);
  const Eigen::Vector3d half_size(0.4, 0.25, 0.35);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(25.0 * kPi / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d box_x = rotation.col(0);
  struct View {
    Eigen::Vector3d position;
    int expected_faces;
  };
  const std::vector<View> views{{center + 3.0 * box_x, 1},
                                {center + 3.0 * box_x + Eigen::Vector3d(0.0, 0.0, 1.5), 2},
                                {Eigen::Vector3d(2.0, -1.6, 1.5), 3}};

  for (const View& view : views) {
    SCOPED_TRACE("camera at " + std::to_string(view.position.x()) + ", " + std::to_string(view.position.y()) + ", " +
                 std::to_string(view.position.z()));
    Scene scene = sceneInCameraFrame({{"crate", Box{center, 2.0 * half_size, rotation}}});
    scene.world_from_camera = lookAt(view.position, center, Eigen::Vector3d::UnitZ());
    const RenderedFrame frame = render(scene, SensorModel::none);
    const std::vector<ListedPlane> planes = listedPlanes(frame);
    ASSERT_EQ(planes.size(), 6U);

    Eigen::Isometry3d world_from_box = Eigen::Isometry3d::Identity();
    world_from_box.linear() = rotation;
    world_from_box.translation() = center;
    const Eigen::Isometry3d camera_from_box = scene.world_from_camera.inverse() * world_from_box;
    const Eigen::Vector3d camera_in_box = camera_from_box.inverse().translation();

    // Faces in the order +x, -x, +y, -y, +z, -z, ids 1 to 6.
    std::set<std::uint32_t> visible;
    for (int face = 0; face < 6; ++face) {
      const int axis = face / 2;
      const double sign = face % 2 == 0 ? 1.0 : -1.0;
      const Eigen::Vector3d outward = sign * camera_from_box.linear().col(axis);
      const Eigen::Vector3d face_center = camera_from_box.translation() + half_size[axis] * outward;
      const ListedPlane& plane = planes[static_cast<std::size_t>(face)];
      EXPECT_EQ(plane.id, static_cast<std::uint32_t>(face + 1));
      EXPECT_NEAR(std::abs(plane.normal.dot(outward)), 1.0, 1e-12) << "face " << face;
      EXPECT_NEAR(plane.normal.dot(face_center) + plane.d, 0.0, 1e-12) << "face " << face;
      EXPECT_GE(plane.d, 0.0) << "face " << face;
      const bool faces_camera = sign * camera_in_box[axis] > half_size[axis];
      EXPECT_EQ(plane.faces_camera, faces_camera) << "face " << face;
      if (faces_camera) {
        visible.insert(plane.id);
      }
    }
    EXPECT_EQ(static_cast<int>(visible.size()), view.expected_faces);

    std::set<std::uint32_t> seen;
    const std::vector<std::size_t> counts = labelCounts(frame);
    for (std::size_t i = 0; i < frame.points.size(); ++i) {
      const Eigen::Vector3f& point = frame.points[i];
      if (isNaN(point)) {
        ASSERT_EQ(frame.labels[i], 0U);
        continue;
      }
      // Only the box is in the scene, so every point is on one of its faces.
      ASSERT_GE(frame.labels[i], 1U);
      ASSERT_LE(frame.labels[i], 6U);
      seen.insert(frame.labels[i]);
      const ListedPlane& plane = planes[frame.labels[i] - 1];
      const Eigen::Vector3d p = point.cast<double>();
      ASSERT_NEAR(plane.normal.dot(p) + plane.d, 0.0, roundOff(point)) << "pixel " << i;
      const Eigen::Vector3d in_box = camera_from_box.inverse() * p;
      ASSERT_TRUE((in_box.array().abs() <= half_size.array() + roundOff(point)).all())
          << "pixel " << i << " at " << in_box.transpose() << " in box coordinates";
    }
    EXPECT_EQ(seen, visible);
    for (const ListedPlane& plane : planes) {
      EXPECT_EQ(plane.pixels, counts[plane.id]) << "face id " << plane.id;
    }
  }
}

TEST(Renderer, FacesFlushInOnePlaneAreOneGroundTruthPlaneApartTheyAreTwo) {
  // Two rectangles side by side at z = 2, touching at x = 0: one surface, one label. Two more
  // at z = 3 with a gap between them: two planes.
  const auto panel = [](double x, double z, double width) {
    return Primitive{"panel", Rectangle{Eigen::Vector3d(x, -0.2, z), Eigen::Vector3d(width, 0.0, 0.0),
                                        Eigen::Vector3d(0.0, 0.3, 0.0)}};
  };
  const Scene scene =
      sceneInCameraFrame({panel(-0.2, 2.0, 0.4), panel(0.2, 2.0, 0.4), panel(-0.4, 3.0, 0.2), panel(0.4, 3.0, 0.2)});
  const RenderedFrame frame = render(scene, SensorModel::none);
  std::map<std::uint32_t, std::size_t> pixels;
  for (const std::uint32_t label : frame.labels) ++pixels[label];
  EXPECT_GT(pixels[1], 0u);
  EXPECT_EQ(pixels[2], 0u);  // flush with panel 1: its label
  EXPECT_EQ(frame.planes[1].merged_into, 1u);
  EXPECT_EQ(frame.planes[1].pixel_count, 0u);
  EXPECT_EQ(frame.planes[0].pixel_count, pixels[1]);
  EXPECT_GT(pixels[3], 0u);  // coplanar, but a gap apart: two planes
  EXPECT_GT(pixels[4], 0u);
  EXPECT_EQ(frame.planes[2].merged_into, 0u);
  EXPECT_EQ(frame.planes[3].merged_into, 0u);
}

TEST(Renderer, SpherePointsLieOnTheSphereAndAreNotPlanar) {
  const Eigen::Vector3d center(0.1, -0.05, 2.0);
  const double radius = 0.4;
  const Scene scene = sceneInCameraFrame({{"ball", Sphere{center, radius}}});
  const RenderedFrame frame = render(scene, SensorModel::none);
  EXPECT_TRUE(frame.planes.empty());

  std::size_t hits = 0;
  for (int v = 0; v < scene.intrinsics.height; ++v) {
    for (int u = 0; u < scene.intrinsics.width; ++u) {
      const Eigen::Vector3d ray = scene.intrinsics.rayThroughPixel(u, v).normalized();
      const std::size_t i = pixelIndex(scene.intrinsics, u, v);
      const Eigen::Vector3f& point = frame.points[i];
      EXPECT_EQ(frame.labels[i], 0U);
      // The ray hits the sphere when it passes the centre closer than the radius.
      const double miss_distance = center.cross(ray).norm();
      if (std::abs(miss_distance - radius) < 1e-9) {
        continue;  // grazing: either answer is right
      }
      if (miss_distance > radius) {
        ASSERT_TRUE(isNaN(point)) << "pixel " << u << ", " << v;
        continue;
      }
      ++hits;
      const Eigen::Vector3d p = point.cast<double>();
      ASSERT_NEAR((p - center).norm(), radius, roundOff(point)) << "pixel " << u << ", " << v;
      // The near side: the surface normal there faces the camera.
      ASSERT_LE((p - center).dot(ray), roundOff(point)) << "pixel " << u << ", " << v;
    }
  }
  EXPECT_GT(hits, 1000U);
}

// A cylinder standing below the camera's eye level (y points down), radius 0.25, from
// y = 0.5 up to y = 0.2, 2 m ahead: the camera sees its curved side and its top cap.
TEST(Renderer, CylinderSidePointsAreNotPlanarAndItsTopCapIsAPlane) {
  const Eigen::Vector3d base(0.0, 0.5, 2.0);
  const Eigen::Vector3d axis(0.0, -1.0, 0.0);
  const double radius = 0.25;
  const double height = 0.3;
  const Scene scene = sceneInCameraFrame({{"can", Cylinder{base, axis, radius, height}}});
  const RenderedFrame frame = render(scene, SensorModel::none);

  ASSERT_EQ(frame.planes.size(), 2U);
  const GroundTruthPlane& top = frame.planes[0];
  const GroundTruthPlane& bottom = frame.planes[1];
  EXPECT_EQ(top.face, "top");
  EXPECT_EQ(bottom.face, "bottom");
  // Both caps are planes y = const; their normals point up, towards the camera.
  EXPECT_TRUE(top.normal.isApprox(axis, 1e-12));
  EXPECT_NEAR(top.d, 0.2, 1e-12);
  EXPECT_TRUE(top.faces_camera);
  EXPECT_TRUE(bottom.normal.isApprox(axis, 1e-12));
  EXPECT_NEAR(bottom.d, 0.5, 1e-12);
  EXPECT_FALSE(bottom.faces_camera);

  std::size_t side_pixels = 0;
  std::size_t top_pixels = 0;
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    const Eigen::Vector3f& point = frame.points[i];
    if (isNaN(point)) {
      ASSERT_EQ(frame.labels[i], 0U);
      continue;
    }
    const Eigen::Vector3d offset = point.cast<double>() - base;
    const double along = offset.dot(axis);
    const double across = (offset - along * axis).norm();
    const double tolerance = roundOff(point);
    ASSERT_GE(along, -tolerance) << "pixel " << i;
    ASSERT_LE(along, height + tolerance) << "pixel " << i;
    if (frame.labels[i] == 0) {
      ++side_pixels;
      ASSERT_NEAR(across, radius, tolerance) << "pixel " << i;
    } else {
      ASSERT_EQ(frame.labels[i], top.id) << "pixel " << i;
      ++top_pixels;
      ASSERT_NEAR(along, height, tolerance) << "pixel " << i;
      ASSERT_LE(across, radius + tolerance) << "pixel " << i;
    }
  }
  EXPECT_GT(side_pixels, 1000U);
  EXPECT_GT(top_pixels, 1000U);
  EXPECT_EQ(top.pixel_count, top_pixels);
  EXPECT_EQ(bottom.pixel_count, 0U);
}

// ---- The Kinect model --------------------------------------------------------------------

struct DepthStatistics {
  std::size_t returns = 0;
  std::size_t lost = 0;
  double mean_error = 0.0;  // of the measured depth minus the true depth
  double spread = 0.0;      // sample standard deviation of that error
  float nearest = INFINITY;
  float farthest = -INFINITY;
};

// Renders a wall filling the whole image at depth z with the Kinect model. Checks on the way
// that the noise moves each point along its pixel's ray.
DepthStatistics measureWall(double z, std::uint64_t seed = 1) {
  const Scene scene = sceneInCameraFrame({rectangleFacingCamera(z, 40.0, 40.0)});
  const RenderedFrame frame = render(scene, SensorModel::kinect, seed);
  DepthStatistics statistics;
  double sum = 0.0;
  double sum_of_squares = 0.0;
  for (int v = 0; v < scene.intrinsics.height; ++v) {
    for (int u = 0; u < scene.intrinsics.width; ++u) {
      const Eigen::Vector3f& point = frame.points[pixelIndex(scene.intrinsics, u, v)];
      if (isNaN(point)) {
        ++statistics.lost;
        continue;
      }
      const Eigen::Vector3d ray = scene.intrinsics.rayThroughPixel(u, v);
      EXPECT_NEAR(point.x() / point.z(), ray.x(), 1e-6);
      EXPECT_NEAR(point.y() / point.z(), ray.y(), 1e-6);
      ++statistics.returns;
      const double error = static_cast<double>(point.z()) - z;
      sum += error;
      sum_of_squares += error * error;
      statistics.nearest = std::min(statistics.nearest, point.z());
      statistics.farthest = std::max(statistics.farthest, point.z());
    }
  }
  if (statistics.returns > 1) {
    const auto n = static_cast<double>(statistics.returns);
    statistics.mean_error = sum / n;
    const double mean = statistics.mean_error;
    statistics.spread = std::sqrt((sum_of_squares - n * mean * mean) / (n - 1.0));
  }
  return statistics;
}

// Nguyen, Izadi and Lovell (2012): the axial spread of Kinect depth.
double nguyenSigma(double z) { return 0.0012 + 0.0019 * (z - 0.4) * (z - 0.4); }

// At 1 m the depth step of the 1/8 px disparity lattice (q = z^2 / (8 f b) = 3.2 mm) is under
// twice sigma_z (1.9 mm), so the measured depths take several lattice values. At 3 m the step
// (28.6 mm) is twice sigma_z (14.0 mm): quantization dominates and nearly all returns are z or
// z +- one step. The model narrows its Gaussian to leave room for the rounding and promises
// the spread of the quantized depth within about 9 % of sigma_z; at 3 m, a lattice depth,
// rounding a Gaussian 0.40 steps wide gives 0.457 steps = 13.1 mm, 7 % under sigma_z.
TEST(Kinect, DepthSpreadMatchesNguyenEtAlAtOneAndThreeMetres) {
  for (double z : {1.0, 3.0}) {
    SCOPED_TRACE("wall at " + std::to_string(z) + " m");
    const DepthStatistics statistics = measureWall(z);
    ASSERT_GT(statistics.returns, 300000U);
    const double sigma = nguyenSigma(z);
    EXPECT_NEAR(statistics.spread, sigma, 0.10 * sigma);
    EXPECT_NEAR(statistics.mean_error, 0.0, 0.05 * sigma);  // noise and rounding are unbiased
  }
}

TEST(Kinect, ReportsOnlyDepthsOnTheDisparityLattice) {
  const Scene scene = sceneInCameraFrame({rectangleFacingCamera(3.0, 40.0, 40.0)});
  const RenderedFrame frame = render(scene, SensorModel::kinect);
  std::set<float> depths;
  for (const Eigen::Vector3f& point : frame.points) {
    if (!isNaN(point)) {
      // 8 f b / z is a whole number of eighth pixels (f b = 525 * 0.075).
      const double eighths = 8.0 * 525.0 * 0.075 / point.z();
      ASSERT_NEAR(eighths, std::round(eighths), 1e-4) << "z = " << point.z();
      depths.insert(point.z());
    }
  }
  EXPECT_GE(depths.size(), 3U);  // 3 m and a step either side at least
}

TEST(Kinect, NoReturnsNearerThan45CentimetresOrBeyond8Metres) {
  // Walls inside the range limits by 2 mm (1.7 sigma_z) and 0.1 m (0.9 sigma_z) lose part of
  // their returns to the limits; walls well outside lose all.
  for (double z : {0.40, 0.452, 7.9, 12.0}) {
    SCOPED_TRACE("wall at " + std::to_string(z) + " m");
    const DepthStatistics statistics = measureWall(z);
    if (statistics.returns > 0) {
      EXPECT_GE(statistics.nearest, 0.45F);
      EXPECT_LE(statistics.farthest, 8.0F);
    }
    const double lost =
        static_cast<double>(statistics.lost) / static_cast<double>(statistics.lost + statistics.returns);
    if (z < 0.45 || z > 8.0) {
      EXPECT_EQ(statistics.returns, 0U);
    } else {
      EXPECT_GT(statistics.returns, 0U);
      EXPECT_GT(lost, 0.01);  // more than the dropouts alone
    }
  }
}

TEST(Kinect, DropsAboutHalfAPercentOfReturnsInRange) {
  const DepthStatistics statistics = measureWall(1.0);  // 10 sigma_z inside both limits
  const double lost = static_cast<double>(statistics.lost) / static_cast<double>(statistics.lost + statistics.returns);
  // 0.5 % of 307200 pixels: 1536 +- 39 expected.
  EXPECT_GT(lost, 0.003);
  EXPECT_LT(lost, 0.007);
}

// The bend: a wall facing the camera at depth Z, rendered with kappa = 0.02 /m, fitted with
// z = a X^2 + b X Y + c Y^2 + d X + e Y + f over its measured points: the Hessian
// [2a b; b 2c] is kappa Z / 3.5 m times the identity (a round bowl), to within 5 % at 3.5 m and
// 1.75 m and 8 % at 5 m: the points move along their rays, which stretches X and Y at the
// corners by e / Z, 2 % at 3.5 m and 4 % at 5 m, and flattens the bowl there by twice that. At
// 3.5 m with the full Kinect model, whose depths stay on the disparity lattice (the bend comes
// before it); at 1.75 m and 5 m, where the bowl's depth is within one or two lattice steps of
// noise only 0.4-0.5 steps wide (rounding then shapes the mean), without the lattice. Without
// the bend the curvature is nil.
Eigen::Matrix2d wallHessian(const RenderedFrame& frame) {
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3f& point : frame.points) {
    if (!isNaN(point)) points.push_back(point.cast<double>());
  }
  Eigen::MatrixXd design(points.size(), 6);
  Eigen::VectorXd depth(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double x = points[k].x();
    const double y = points[k].y();
    design.row(static_cast<Eigen::Index>(k)) << x * x, x * y, y * y, x, y, 1.0;
    depth(static_cast<Eigen::Index>(k)) = points[k].z();
  }
  const Eigen::VectorXd quadric = (design.transpose() * design).ldlt().solve(design.transpose() * depth);
  Eigen::Matrix2d hessian;
  hessian << 2.0 * quadric(0), quadric(1), quadric(1), 2.0 * quadric(2);
  return hessian;
}

TEST(Kinect, BendGivesAWallFacingTheCameraACurvatureOfKappaAt3Point5MetresGrowingWithDepth) {
  for (const double z : {3.5, 1.75, 5.0}) {
    SCOPED_TRACE("wall at " + std::to_string(z) + " m");
    const Scene scene = sceneInCameraFrame({rectangleFacingCamera(z, 40.0, 40.0)});
    RenderSettings settings;
    settings.sensor = SensorModel::kinect;
    settings.seed = 3;
    const bool lattice = z == 3.5;
    if (!lattice) settings.kinect.disparity_step = 0.0;
    const Eigen::Matrix2d flat = wallHessian(renderScene(scene, settings));
    EXPECT_LT(flat.cwiseAbs().maxCoeff(), 0.002);
    settings.kinect.bend_curvature = 0.02;
    const RenderedFrame frame = renderScene(scene, settings);
    const Eigen::Matrix2d bent = wallHessian(frame);
    const double expected = 0.02 * z / 3.5;
    const double tolerance = (z == 5.0 ? 0.08 : 0.05) * expected;
    EXPECT_NEAR(bent(0, 0), expected, tolerance);
    EXPECT_NEAR(bent(1, 1), expected, tolerance);
    EXPECT_NEAR(bent(0, 1), 0.0, tolerance);
    for (const Eigen::Vector3f& point : frame.points) {
      if (isNaN(point) || !lattice) continue;
      const double eighths = 8.0 * 525.0 * 0.075 / point.z();
      ASSERT_NEAR(eighths, std::round(eighths), 1e-4) << "z = " << point.z();
    }
    EXPECT_EQ(frame.quirks.bend_curvature, 0.02);
  }
}

// ---- Determinism -----------------------------------------------------------------------

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A temporary path unique to the running test and process (ctest runs tests in parallel).
fs::path uniqueTempPath(const std::string& suffix) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return fs::temp_directory_path() / (std::string("floodplane_") + info->test_suite_name() + "_" + info->name() + "_" +
                                      std::to_string(::getpid()) + suffix);
}

bool sameBytes(const RenderedFrame& a, const RenderedFrame& b) {
  return a.points.size() == b.points.size() && a.labels == b.labels &&
         std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(Eigen::Vector3f)) == 0;
}

Scene tabletopScene() { return loadScene(std::string(FLOODPLANE_SOURCE_DIR) + "/data/scenes/tabletop.json"); }

TEST(Renderer, SameSceneAndSeedGiveIdenticalBytes) {
  const Scene scene = tabletopScene();
  const RenderedFrame first = render(scene, SensorModel::kinect, 7);
  const RenderedFrame second = render(scene, SensorModel::kinect, 7);
  EXPECT_TRUE(sameBytes(first, second));
  EXPECT_EQ(groundTruthJson(first), groundTruthJson(second));

  // The PCD files pcd_synth writes, byte for byte.
  const fs::path first_path = uniqueTempPath("_first.pcd");
  const fs::path second_path = uniqueTempPath("_second.pcd");
  floodplane::io::savePcd(first_path.string(), toPointCloud(first));
  floodplane::io::savePcd(second_path.string(), toPointCloud(second));
  const std::string first_bytes = fileBytes(first_path);
  EXPECT_FALSE(first_bytes.empty());
  EXPECT_TRUE(first_bytes == fileBytes(second_path));
  fs::remove(first_path);
  fs::remove(second_path);
}

TEST(Renderer, AnotherSeedGivesAnotherNoisyCloudButTheSameExactOne) {
  const Scene scene = tabletopScene();
  const RenderedFrame seven = render(scene, SensorModel::kinect, 7);
  const RenderedFrame eight = render(scene, SensorModel::kinect, 8);
  std::size_t returns = 0;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < seven.points.size(); ++i) {
    if (!isNaN(seven.points[i])) {
      ++returns;
      differing += seven.points[i] != eight.points[i] ? 1 : 0;
    }
  }
  // Two draws of the noise round to the same lattice depth about half the time or less.
  EXPECT_GT(differing, returns / 4);

  EXPECT_TRUE(sameBytes(render(scene, SensorModel::none, 7), render(scene, SensorModel::none, 8)));
}

// The quirks' parameters do nothing while their quirk is off, and the exact model has none:
// such renders are the plain ones bit for bit, and their ground truth names no quirk. A frame
// with quirks lists them in its ground truth.
TEST(Renderer, QuirkParametersChangeNothingWhileTheirQuirkIsOff) {
  const Scene scene = tabletopScene();
  for (const SensorModel sensor : {SensorModel::none, SensorModel::kinect, SensorModel::scanner}) {
    SCOPED_TRACE(sensorModelName(sensor));
    RenderSettings plain;
    plain.sensor = sensor;
    plain.seed = 5;
    RenderSettings inert = plain;
    inert.warp.seed = 99;  // amplitude 0
    inert.kinect.bend_reference_depth = 1.0;
    inert.scanner.range_code_near = 0.2;
    inert.scanner.range_code_far = 0.4;
    inert.scanner.speckle_stripe_probability = 1.0;
    inert.scanner.speckle_spurious_probability = 1.0;
    if (sensor == SensorModel::none) {
      // The exact model takes no quirk at all.
      inert.warp.amplitude = 0.003;
      inert.kinect.bend_curvature = 0.5;
      inert.scanner.range_bits = 4;
      inert.scanner.speckle = true;
    }
    const RenderedFrame a = renderScene(scene, plain);
    const RenderedFrame b = renderScene(scene, inert);
    EXPECT_TRUE(sameBytes(a, b));
    EXPECT_EQ(groundTruthJson(a), groundTruthJson(b));
    EXPECT_EQ(nlohmann::json::parse(groundTruthJson(b)).count("sensor_quirks"), 0U);
  }
  RenderSettings quirky;
  quirky.sensor = SensorModel::scanner;
  quirky.seed = 5;
  quirky.warp = {0.002, 7};
  quirky.scanner.range_bits = 8;
  quirky.scanner.speckle = true;
  quirky.kinect.bend_curvature = 0.02;  // not the scanner's: not listed
  const nlohmann::json listed = nlohmann::json::parse(groundTruthJson(renderScene(scene, quirky))).at("sensor_quirks");
  EXPECT_EQ(listed.at("quantize_bits").get<int>(), 8);
  EXPECT_EQ(listed.at("range_code_window"), nlohmann::json::array({0.7, 1.5}));
  EXPECT_DOUBLE_EQ(listed.at("warp_mm").get<double>(), 2.0);
  EXPECT_EQ(listed.at("warp_seed").get<int>(), 7);
  EXPECT_TRUE(listed.at("speckle").get<bool>());
  EXPECT_EQ(listed.count("bend_per_m"), 0U);
  quirky.sensor = SensorModel::kinect;
  const nlohmann::json kinect = nlohmann::json::parse(groundTruthJson(renderScene(scene, quirky))).at("sensor_quirks");
  EXPECT_DOUBLE_EQ(kinect.at("bend_per_m").get<double>(), 0.02);
  EXPECT_DOUBLE_EQ(kinect.at("bend_reference_depth").get<double>(), 3.5);
  EXPECT_DOUBLE_EQ(kinect.at("warp_mm").get<double>(), 2.0);
  EXPECT_EQ(kinect.count("quantize_bits"), 0U);
  EXPECT_EQ(kinect.count("speckle"), 0U);
}

// ---- The scene files -------------------------------------------------------------------

TEST(Scenes, EveryFileLoadsAndRendersWithGroundTruthPlanesInBothSensorModels) {
  std::vector<fs::path> files;
  const fs::path scene_dir = fs::path(FLOODPLANE_SOURCE_DIR) / "data" / "scenes";
  for (const auto& entry : fs::directory_iterator(scene_dir)) {
    if (entry.path().extension() == ".json") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());

  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    Scene scene;
    ASSERT_NO_THROW(scene = loadScene(file.string()));
    for (SensorModel sensor : {SensorModel::none, SensorModel::kinect}) {
      SCOPED_TRACE(sensorModelName(sensor));
      RenderedFrame frame;
      ASSERT_NO_THROW(frame = render(scene, sensor));
      ASSERT_EQ(frame.points.size(),
                static_cast<std::size_t>(scene.intrinsics.width) * static_cast<std::size_t>(scene.intrinsics.height));
      const std::vector<std::size_t> counts = labelCounts(frame);
      std::size_t planes_with_pixels = 0;
      for (std::size_t k = 0; k < frame.planes.size(); ++k) {
        EXPECT_EQ(frame.planes[k].id, k + 1);
        EXPECT_EQ(frame.planes[k].pixel_count, counts[k + 1]);
        planes_with_pixels += frame.planes[k].pixel_count > 0 ? 1 : 0;
      }
      EXPECT_GE(planes_with_pixels, 1U);
      EXPECT_EQ(listedPlanes(frame).size(), frame.planes.size());

      for (std::size_t i = 0; i < frame.points.size(); ++i) {
        const Eigen::Vector3f& point = frame.points[i];
        const std::uint32_t label = frame.labels[i];
        if (isNaN(point)) {
          ASSERT_EQ(label, 0U) << "pixel " << i;
        } else if (sensor == SensorModel::kinect) {
          ASSERT_GE(point.z(), 0.45F) << "pixel " << i;
          ASSERT_LE(point.z(), 8.0F) << "pixel " << i;
        } else if (label > 0) {
          const GroundTruthPlane& plane = frame.planes[label - 1];
          ASSERT_TRUE(plane.faces_camera) << "pixel " << i;
          ASSERT_NEAR(plane.normal.dot(point.cast<double>()) + plane.d, 0.0, roundOff(point))
              << "pixel " << i << " on plane " << label;
        }
      }
    }
  }
}

}  // namespace
