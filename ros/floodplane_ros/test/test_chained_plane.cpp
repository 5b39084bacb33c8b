// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// What a node publishes for pcl_ros's filters: the largest plane's pixels as indices into the
// input cloud and its coefficients, as SACSegmentation publishes its model; nothing for a frame
// without a plane.

#include "chained_plane.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/test_scenes.h"
#include "floodplane/segmenter.h"

namespace {

using floodplane::Segmentation;
using floodplane::conversion::chainedPlane;
using floodplane::conversion::planeIndices;

TEST(ChainedPlane, IsTheLargestPlanesPixelsAndCoefficients) {
  // The room corner (floor, back wall, left wall) on a 160 x 120 Kinect grid, exact.
  const auto scene = floodplane::test::render(floodplane::test::kinectView(160, 120), floodplane::test::roomCorner());
  floodplane::Segmenter segmenter;
  const Segmentation& segmentation = segmenter.segment(scene.grid());
  ASSERT_EQ(segmentation.planes.size(), 3u);

  const auto chained = chainedPlane(segmentation);
  const auto& largest = segmentation.planes[0];
  ASSERT_EQ(chained.indices.size(), largest.inlier_count);
  EXPECT_TRUE(std::is_sorted(chained.indices.begin(), chained.indices.end()));
  for (const std::int32_t i : chained.indices) {
    ASSERT_EQ(segmentation.labels[static_cast<std::size_t>(i)], 1u) << i;
    // An index into the grid, row-major: the pixel's point lies on the plane.
    const float* p = scene.grid().point(static_cast<std::size_t>(i));
    const double distance = largest.fit.normal.dot(Eigen::Vector3d(p[0], p[1], p[2])) + largest.fit.offset;
    ASSERT_NEAR(distance, 0.0, 1e-4) << i;
  }
  ASSERT_EQ(chained.coefficients.size(), 4u);
  EXPECT_FLOAT_EQ(chained.coefficients[0], static_cast<float>(largest.fit.normal.x()));
  EXPECT_FLOAT_EQ(chained.coefficients[1], static_cast<float>(largest.fit.normal.y()));
  EXPECT_FLOAT_EQ(chained.coefficients[2], static_cast<float>(largest.fit.normal.z()));
  EXPECT_FLOAT_EQ(chained.coefficients[3], static_cast<float>(largest.fit.offset));

  // Every plane's indices, together with the pixels of no plane, cover the grid once.
  std::size_t covered = 0;
  for (std::size_t k = 0; k < segmentation.planes.size(); ++k) {
    const auto indices = planeIndices(segmentation, k);
    EXPECT_EQ(indices.size(), segmentation.planes[k].inlier_count) << k;
    covered += indices.size();
  }
  covered += static_cast<std::size_t>(std::count(segmentation.labels.begin(), segmentation.labels.end(), 0u));
  EXPECT_EQ(covered, segmentation.labels.size());
}

TEST(ChainedPlane, IsEmptyForAFrameWithoutAPlane) {
  Segmentation none;
  none.width = 4;
  none.height = 2;
  none.labels.assign(8, 0);
  const auto chained = chainedPlane(none);
  EXPECT_TRUE(chained.indices.empty());
  EXPECT_TRUE(chained.coefficients.empty());
}

TEST(ChainedPlane, RefusesAPlaneTheSegmentationDoesNotHave) {
  Segmentation one;
  one.width = 2;
  one.height = 2;
  one.labels = {1, 1, 0, 1};
  one.planes.resize(1);
  one.planes[0].inlier_count = 3;
  EXPECT_EQ(planeIndices(one, 0), (std::vector<std::int32_t>{0, 1, 3}));
  EXPECT_THROW(planeIndices(one, 1), std::invalid_argument);
}

}  // namespace
