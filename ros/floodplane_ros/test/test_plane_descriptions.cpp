// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// What a node says about each plane: the segmentation's own fits and counts under the
// published labels, the library's classes and heights when it has an up direction, and
// outlines on the plane's boundary for rviz, coloured by class or by label.

#include "plane_descriptions.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/test_scenes.h"
#include "floodplane/io/label_palette.h"
#include "floodplane/plane_classes.h"
#include "floodplane/segmenter.h"
#include "up_direction.h"

namespace {

using floodplane::PlaneClass;
using floodplane::Segmentation;
using floodplane::Segmenter;
using floodplane::conversion::describePlanes;
using floodplane::conversion::markerColor;
using floodplane::conversion::outlinePlane;
using floodplane::conversion::planeClassColor;
using floodplane::conversion::publishedLabels;
using floodplane::conversion::UpDirection;

// The room corner (floor y = 1, back wall z = 4, left wall x = -1.5) on a 160 x 120 Kinect
// grid, exact: a level camera 1 m above the floor, y down.
struct Corner {
  floodplane::test::RenderedGrid scene =
      floodplane::test::render(floodplane::test::kinectView(160, 120), floodplane::test::roomCorner());
  Segmenter segmenter;
  const Segmentation& segmentation = segmenter.segment(scene.grid());
};

TEST(PlaneDescriptions, AreTheSegmentationsPlanesNumberedBySize) {
  Corner corner;
  const Segmentation& segmentation = corner.segmentation;
  ASSERT_EQ(segmentation.planes.size(), 3u);
  const auto planes = describePlanes(segmentation, {});
  ASSERT_EQ(planes.size(), 3u);
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const auto& fit = segmentation.planes[k].fit;
    EXPECT_EQ(planes[k].label, k + 1);
    EXPECT_EQ(planes[k].track_id, 0u);
    EXPECT_EQ(planes[k].coefficients[0], fit.normal.x());
    EXPECT_EQ(planes[k].coefficients[1], fit.normal.y());
    EXPECT_EQ(planes[k].coefficients[2], fit.normal.z());
    EXPECT_EQ(planes[k].coefficients[3], fit.offset);
    EXPECT_EQ(planes[k].centroid[0], fit.centroid.x());
    EXPECT_EQ(planes[k].centroid[2], fit.centroid.z());
    EXPECT_EQ(planes[k].inlier_count, segmentation.planes[k].inlier_count);
    EXPECT_EQ(planes[k].mean_squared_error, fit.mean_squared_error);
  }
  // The back wall z = 4 faces the camera: n = (0 0 -1), d = 4.
  bool found_back_wall = false;
  for (const auto& plane : planes) {
    if (std::abs(plane.coefficients[2] + 1.0) < 1e-6) {
      EXPECT_NEAR(plane.coefficients[3], 4.0, 1e-5);
      found_back_wall = true;
    }
  }
  EXPECT_TRUE(found_back_wall);
}

TEST(PlaneDescriptions, CarryTrackIdsAsLabelsWhenTracking) {
  Corner corner;
  const auto planes = describePlanes(corner.segmentation, {5, 2, 9});
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_EQ(planes[0].label, 5u);
  EXPECT_EQ(planes[0].track_id, 5u);
  EXPECT_EQ(planes[2].label, 9u);
  EXPECT_EQ(publishedLabels(3, {}), (std::vector<std::uint32_t>{1, 2, 3}));
  EXPECT_THROW(publishedLabels(3, {1, 2}), std::invalid_argument);
}

constexpr UpDirection kUp{0.0, -1.0, 0.0};

TEST(PlaneDescriptions, AreClassedByTheUpDirectionAsTheLibraryClassesThem) {
  Corner corner;
  const Segmentation& segmentation = corner.segmentation;
  ASSERT_EQ(segmentation.planes.size(), 3u);
  const auto planes = describePlanes(segmentation, {}, kUp);
  const auto library = floodplane::describePlanes(segmentation.planes, Eigen::Vector3d(0, -1, 0));
  ASSERT_EQ(planes.size(), 3u);
  ASSERT_EQ(library.size(), 3u);
  int floors = 0, walls = 0;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    EXPECT_EQ(planes[k].plane_class, library[k].plane_class);
    EXPECT_EQ(planes[k].height_above_floor, library[k].height_above_floor);
    const auto& fit = segmentation.planes[k].fit;
    // Each is what it is in the scene: the floor's normal is up (0 -1 0), the walls' level.
    if (fit.normal.y() < -0.99) {
      ++floors;
      EXPECT_EQ(planes[k].plane_class, PlaneClass::kFloor);
      EXPECT_NEAR(planes[k].height_above_floor, 0.0, 1e-6);
    } else {
      ++walls;
      EXPECT_EQ(planes[k].plane_class, PlaneClass::kWall);
      // Along up from the floor (y = 1) to the wall's centroid, within the floor's fit to the
      // grid's float points.
      EXPECT_NEAR(planes[k].height_above_floor, 1.0 - fit.centroid.y(), 1e-4);
      EXPECT_GT(planes[k].height_above_floor, 0.0);
    }
  }
  EXPECT_EQ(floors, 1);
  EXPECT_EQ(walls, 2);
  // The length of up does not matter.
  const auto scaled = describePlanes(segmentation, {}, UpDirection{0.0, -9.81, 0.0});
  for (std::size_t k = 0; k < planes.size(); ++k) EXPECT_EQ(scaled[k].plane_class, planes[k].plane_class);
}

TEST(PlaneDescriptions, AreOtherWithoutHeightsWithoutAnUpDirection) {
  Corner corner;
  for (const auto& plane : describePlanes(corner.segmentation, {})) {
    EXPECT_EQ(plane.plane_class, PlaneClass::kOther);
    EXPECT_TRUE(std::isnan(plane.height_above_floor));
  }
}

TEST(PlaneDescriptions, HaveNoHeightsWithoutAFloor) {
  // Up along +z, as if the camera looked straight up: no plane faces up (the back wall z = 4
  // faces down, the scene's floor and left wall are vertical), so none is the floor and none
  // has a height.
  Corner corner;
  const auto planes = describePlanes(corner.segmentation, {}, UpDirection{0.0, 0.0, 1.0});
  ASSERT_EQ(planes.size(), 3u);
  for (std::size_t k = 0; k < planes.size(); ++k) {
    EXPECT_TRUE(std::isnan(planes[k].height_above_floor));
    const double facing_up = corner.segmentation.planes[k].fit.normal.z();
    if (std::abs(facing_up) < 0.01) {
      EXPECT_EQ(planes[k].plane_class, PlaneClass::kWall);
    }
    EXPECT_NE(planes[k].plane_class, PlaneClass::kFloor);
  }
}

TEST(PlaneDescriptions, RefuseAnUpDirectionThatIsNone) {
  Corner corner;
  EXPECT_THROW(describePlanes(corner.segmentation, {}, UpDirection{0.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(describePlanes(corner.segmentation, {}, UpDirection{0.0, std::numeric_limits<double>::quiet_NaN(), 1.0}),
               std::invalid_argument);
}

TEST(MarkerColor, IsTheClasssWhenClassedAndTheLabelsWhenNot) {
  floodplane::conversion::PlaneDescription plane;
  plane.label = 7;
  plane.plane_class = PlaneClass::kWall;
  EXPECT_EQ(markerColor(plane, true), planeClassColor(PlaneClass::kWall));
  const auto rgb = floodplane::io::labelColor(7);
  const std::array<float, 3> label_color{rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f};
  EXPECT_EQ(markerColor(plane, false), label_color);
  // The label does not change a classed plane's colour, its class does.
  plane.label = 8;
  EXPECT_EQ(markerColor(plane, true), planeClassColor(PlaneClass::kWall));
  plane.plane_class = PlaneClass::kFloor;
  EXPECT_EQ(markerColor(plane, true), planeClassColor(PlaneClass::kFloor));
}

TEST(MarkerColor, TellsTheFiveClassesApart) {
  const std::vector<PlaneClass> classes = {PlaneClass::kOther, PlaneClass::kFloor, PlaneClass::kCeiling,
                                           PlaneClass::kWall, PlaneClass::kHorizontalSurface};
  for (std::size_t i = 0; i < classes.size(); ++i) {
    const auto a = planeClassColor(classes[i]);
    for (const float channel : a) {
      EXPECT_GE(channel, 0.0f);
      EXPECT_LE(channel, 1.0f);
    }
    for (std::size_t j = 0; j < i; ++j) {
      const auto b = planeClassColor(classes[j]);
      const double distance = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
      EXPECT_GT(distance, 0.3) << floodplane::planeClassName(classes[i]) << " and "
                               << floodplane::planeClassName(classes[j]) << " look alike";
    }
  }
  // A value outside the enumeration is drawn as other.
  EXPECT_EQ(planeClassColor(static_cast<PlaneClass>(9)), planeClassColor(PlaneClass::kOther));
}

TEST(PlaneOutline, IsAClosedLoopOnThePlaneAlongItsBoundary) {
  Corner corner;
  const Segmentation& segmentation = corner.segmentation;
  const floodplane::PointGrid grid = corner.scene.grid();
  for (std::size_t k = 0; k < segmentation.planes.size(); ++k) {
    const auto& fit = segmentation.planes[k].fit;
    const std::array<float, 3> color{0.25f, 0.5f, 1.0f};
    const auto outline = outlinePlane(segmentation, grid, k, color, 40, 0.25);
    ASSERT_GE(outline.points.size(), 4u);
    EXPECT_LE(outline.points.size(), 40u);
    EXPECT_EQ(outline.points.front(), outline.points.back());
    std::vector<int> contour;
    segmentation.boundary(k, contour);
    for (const auto& p : outline.points) {
      const Eigen::Vector3d point(p[0], p[1], p[2]);
      EXPECT_NEAR(fit.normal.dot(point) + fit.offset, 0.0, 1e-5);
      // Each outline point is the projection of a boundary pixel's point onto the plane.
      double nearest = 1e9;
      for (int pixel : contour) {
        const float* q = grid.point(static_cast<std::size_t>(pixel));
        const Eigen::Vector3d boundary(q[0], q[1], q[2]);
        const Eigen::Vector3d projection = boundary - (fit.normal.dot(boundary) + fit.offset) * fit.normal;
        nearest = std::min(nearest, (point - projection).norm());
      }
      EXPECT_LT(nearest, 1e-5);
    }
    const Eigen::Vector3d start(outline.normal_start[0], outline.normal_start[1], outline.normal_start[2]);
    const Eigen::Vector3d end(outline.normal_end[0], outline.normal_end[1], outline.normal_end[2]);
    EXPECT_LT((start - fit.centroid).norm(), 1e-5);
    EXPECT_LT((end - start - 0.25 * fit.normal).norm(), 1e-5);
    EXPECT_EQ(outline.color, color);
  }
}

TEST(PlaneOutline, RejectsAPlaneItDoesNotHaveAndTooFewPoints) {
  Corner corner;
  const std::array<float, 3> grey{0.5f, 0.5f, 0.5f};
  EXPECT_THROW(outlinePlane(corner.segmentation, corner.scene.grid(), 3, grey, 40, 0.2), std::invalid_argument);
  EXPECT_THROW(outlinePlane(corner.segmentation, corner.scene.grid(), 0, grey, 2, 0.2), std::invalid_argument);
}

}  // namespace
