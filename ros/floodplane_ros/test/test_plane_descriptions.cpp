// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// What a node says about each plane: the segmentation's own fits and counts under the
// published labels, and outlines on the plane's boundary for rviz.

#include "plane_descriptions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/test_scenes.h"
#include "floodplane/segmenter.h"
#include "io/label_palette.h"

namespace {

using floodplane::Segmentation;
using floodplane::Segmenter;
using floodplane::conversion::describePlanes;
using floodplane::conversion::outlinePlane;
using floodplane::conversion::publishedLabels;

// The room corner (floor, back wall, left wall) on a 160 x 120 Kinect grid, exact.
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

TEST(PlaneOutline, IsAClosedLoopOnThePlaneAlongItsBoundary) {
  Corner corner;
  const Segmentation& segmentation = corner.segmentation;
  const floodplane::PointGrid grid = corner.scene.grid();
  for (std::size_t k = 0; k < segmentation.planes.size(); ++k) {
    const auto& fit = segmentation.planes[k].fit;
    const auto outline = outlinePlane(segmentation, grid, k, 4, 40, 0.25);
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
    const auto rgb = floodplane::io::labelColor(4);
    EXPECT_FLOAT_EQ(outline.color[0], rgb[0] / 255.0f);
    EXPECT_FLOAT_EQ(outline.color[2], rgb[2] / 255.0f);
  }
}

TEST(PlaneOutline, RejectsAPlaneItDoesNotHaveAndTooFewPoints) {
  Corner corner;
  EXPECT_THROW(outlinePlane(corner.segmentation, corner.scene.grid(), 3, 1, 40, 0.2), std::invalid_argument);
  EXPECT_THROW(outlinePlane(corner.segmentation, corner.scene.grid(), 0, 1, 2, 0.2), std::invalid_argument);
}

}  // namespace
