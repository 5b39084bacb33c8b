// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// What the 3-D views draw and from where, without drawing: the cameras (a point of the grid
// projects onto its own pixel in the sensor view; the oblique view keeps the scene in sight)
// and the plane markers made from labels.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "floodplane/io/label_palette.h"
#include "view/plane_scene.h"

namespace {

using floodplane::view::CameraView;
using floodplane::view::PlaneScene;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

constexpr int kWidth = 160;
constexpr int kHeight = 120;
constexpr double kFocal = 525.0 / 4.0;  // a Kinect's, scaled to the grid

// A pinhole view of a floor at y = 0.6 m below a wall at z = 2.5 m (rows go down, along +y),
// seen from `origin`, with a NaN block.
Cloud pinholeScene(const Eigen::Vector3f& origin = Eigen::Vector3f::Zero()) {
  Cloud cloud(kWidth, kHeight);
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const double rx = (u - (kWidth - 1) / 2.0) / kFocal;
      const double ry = (v - (kHeight - 1) / 2.0) / kFocal;
      double t = 2.5;
      if (ry > 0.0) t = std::min(t, 0.6 / ry);
      pcl::PointXYZ& p = cloud.at(u, v);
      p.x = static_cast<float>(t * rx) + origin.x();
      p.y = static_cast<float>(t * ry) + origin.y();
      p.z = static_cast<float>(t) + origin.z();
    }
  }
  for (int v = 5; v < 9; ++v)
    for (int u = 7; u < 11; ++u) cloud.at(u, v).x = std::numeric_limits<float>::quiet_NaN();
  cloud.sensor_origin_ = Eigen::Vector4f(origin.x(), origin.y(), origin.z(), 0.0f);
  return cloud;
}

PlaneScene sceneOf(const Cloud& cloud) {
  PlaneScene scene;
  scene.cloud = std::make_shared<Cloud>(cloud);
  scene.colour_labels.assign(cloud.size(), 0);
  return scene;
}

bool isFinite(const pcl::PointXYZ& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

TEST(SensorCamera, ProjectsEveryPointOfThePinholeGridOntoItsOwnPixel) {
  const Cloud cloud = pinholeScene();
  const floodplane::view::Camera camera = floodplane::view::sceneCamera(sceneOf(cloud), CameraView::sensor);
  EXPECT_TRUE(camera.position.isZero());
  EXPECT_NEAR(camera.view_angle_deg, 2.0 * std::atan(kHeight / 2.0 / kFocal) * 180.0 / M_PI, 1e-3);
  double worst = 0.0;
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const pcl::PointXYZ& p = cloud.at(u, v);
      if (!isFinite(p)) continue;
      const auto pixel = floodplane::view::projectToPixel(camera, p.getVector3fMap().cast<double>(), kWidth, kHeight);
      ASSERT_TRUE(pixel.has_value());
      worst = std::max(worst, (*pixel - Eigen::Vector2d(u, v)).norm());
    }
  }
  EXPECT_LT(worst, 0.01);
}

TEST(SensorCamera, StandsAtTheSensorOriginOfTheCloud) {
  const Eigen::Vector3f origin(1.0f, -2.0f, 0.5f);
  const Cloud cloud = pinholeScene(origin);
  const floodplane::view::Camera camera = floodplane::view::sceneCamera(sceneOf(cloud), CameraView::sensor);
  EXPECT_LT((camera.position - origin.cast<double>()).norm(), 1e-6);
  const auto pixel =
      floodplane::view::projectToPixel(camera, cloud.at(100, 90).getVector3fMap().cast<double>(), kWidth, kHeight);
  ASSERT_TRUE(pixel.has_value());
  EXPECT_NEAR(pixel->x(), 100.0, 0.01);
  EXPECT_NEAR(pixel->y(), 90.0, 0.01);
}

TEST(ProjectToPixel, SeesNothingBehindTheCamera) {
  const floodplane::view::Camera camera = floodplane::view::sceneCamera(sceneOf(pinholeScene()), CameraView::sensor);
  EXPECT_FALSE(floodplane::view::projectToPixel(camera, Eigen::Vector3d(0.0, 0.0, -1.0), kWidth, kHeight));
}

TEST(ObliqueCamera, LooksFromAboveAndRightOfTheSensorAndKeepsTheSceneInView) {
  const Cloud cloud = pinholeScene();
  const PlaneScene scene = sceneOf(cloud);
  const floodplane::view::Camera sensor = floodplane::view::sceneCamera(scene, CameraView::sensor);
  const floodplane::view::Camera oblique = floodplane::view::sceneCamera(scene, CameraView::oblique);
  EXPECT_GT(oblique.position.x(), sensor.position.x() + 0.5);  // right: +x in the image
  EXPECT_LT(oblique.position.y(), sensor.position.y() - 0.5);  // up: -y in the image
  std::size_t inside = 0, finite = 0;
  for (const pcl::PointXYZ& p : cloud) {
    if (!isFinite(p)) continue;
    ++finite;
    const auto pixel = floodplane::view::projectToPixel(oblique, p.getVector3fMap().cast<double>(), kWidth, kHeight);
    if (pixel && pixel->x() >= 0 && pixel->x() < kWidth && pixel->y() >= 0 && pixel->y() < kHeight) ++inside;
  }
  EXPECT_GT(static_cast<double>(inside), 0.97 * static_cast<double>(finite));
  // Deterministic: a function of the cloud alone.
  const floodplane::view::Camera again = floodplane::view::sceneCamera(scene, CameraView::oblique);
  EXPECT_EQ(again.position, oblique.position);
  EXPECT_EQ(again.focal_point, oblique.focal_point);
}

TEST(SceneCamera, RefusesACloudWithoutFinitePoints) {
  Cloud cloud(8, 8);
  for (pcl::PointXYZ& p : cloud) p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(floodplane::view::sceneCamera(sceneOf(cloud), CameraView::sensor), std::invalid_argument);
}

TEST(ParseCameraView, KnowsSensorAndObliqueOnly) {
  EXPECT_EQ(floodplane::view::parseCameraView("sensor"), CameraView::sensor);
  EXPECT_EQ(floodplane::view::parseCameraView("oblique"), CameraView::oblique);
  EXPECT_FALSE(floodplane::view::parseCameraView("top"));
}

TEST(PointColour, IsThePalettesExceptGreyForNoPlane) {
  const auto grey = floodplane::view::pointColour(0);
  EXPECT_EQ(grey, floodplane::view::kUnlabelledColour);
  EXPECT_EQ(grey[0], grey[1]);
  EXPECT_EQ(grey[1], grey[2]);
  EXPECT_EQ(floodplane::view::pointColour(3), floodplane::io::labelColor(3));
}

TEST(PlaneMarkersFromLabels, FitCentroidNormalAndSizeTowardsTheSensor) {
  const Cloud cloud = pinholeScene();
  std::vector<std::uint32_t> labels(cloud.size(), 0), colours(cloud.size(), 0);
  std::size_t wall = 0, floor = 0;
  Eigen::Vector3d wall_sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!isFinite(cloud[i])) continue;
    const bool on_wall = std::abs(cloud[i].z - 2.5f) < 1e-4f;
    labels[i] = on_wall ? 1 : 2;
    colours[i] = on_wall ? 7 : 9;
    if (on_wall) {
      ++wall;
      wall_sum += cloud[i].getVector3fMap().cast<double>();
    } else {
      ++floor;
    }
  }
  colours[0] = 5;  // one dissenting colour: the majority decides
  const auto markers = floodplane::view::planeMarkersFromLabels(cloud, labels, colours, 10);
  ASSERT_EQ(markers.size(), 2u);
  EXPECT_EQ(markers[0].id, 1u);
  EXPECT_EQ(markers[0].colour_label, 7u);
  EXPECT_EQ(markers[0].inliers, wall);
  EXPECT_LT((markers[0].centroid.cast<double>() - wall_sum / static_cast<double>(wall)).norm(), 1e-4);
  EXPECT_GT(-markers[0].normal.z(), 0.9999f);  // towards the sensor at the origin
  EXPECT_GT(-markers[1].normal.y(), 0.9999f);  // the floor's faces up, to the sensor above it
  EXPECT_EQ(markers[1].inliers, floor);
  // Size: the root-mean-square distance of the wall's points from their centroid.
  double squares = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (labels[i] == 1) squares += (cloud[i].getVector3fMap() - markers[0].centroid).squaredNorm();
  }
  EXPECT_NEAR(markers[0].size, std::sqrt(squares / static_cast<double>(wall)), 1e-4);
  EXPECT_TRUE(markers[0].outline.empty());
  // A label below min_points gets no marker.
  EXPECT_EQ(floodplane::view::planeMarkersFromLabels(cloud, labels, colours, floor + 1).size(), 1u);
}

TEST(PlaneMarkersFromLabels, RefusesLabelsOfAnotherSize) {
  const Cloud cloud = pinholeScene();
  const std::vector<std::uint32_t> short_labels(cloud.size() - 1, 0), labels(cloud.size(), 0);
  EXPECT_THROW(floodplane::view::planeMarkersFromLabels(cloud, short_labels, labels, 1), std::invalid_argument);
  EXPECT_THROW(floodplane::view::planeMarkersFromLabels(cloud, labels, short_labels, 1), std::invalid_argument);
}

}  // namespace
