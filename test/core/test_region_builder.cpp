// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The last stage: from merged segments to the planes a user gets. Clusters smaller than
// min_inliers are dropped, planes are numbered by size (largest first, 1..K), and the fits are
// those of the caller's measured points. Hand-made segment images over pinhole grids of frontal
// planes at different depths. (Sub-sampling: the coarse pass only claims pixels before the fine
// pass, which is what this stage sees: test_coarse_planes.cpp, test_segmenter.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "regions/region_builder.h"
#include "support/pinhole_grid.h"
#include "support/stage_fixture.h"

namespace floodplane {
namespace {

using Grid = test::PinholeGrid;
using test::kNaN;
using test::kPinholePitch;

// What the merging hands over: a frame, the grid that was segmented (the frame), a segment per
// point, each segment its own cluster unless `root` says otherwise, and each root's sums over
// its cluster's points.
struct Merged {
  Grid full;
  PointGrid segmented;
  std::vector<std::int32_t> labels;
  std::vector<std::int32_t> root;
  std::vector<PlaneSums> sums;
  Params params;
  HoleFilling holes;  // none filled
  RegionBuilder builder;
  Segmentation out;

  Merged(Grid frame, const std::function<std::int32_t(int, int)>& segment, std::uint32_t min_inliers = 1)
      : full(std::move(frame)) {
    params = test::exactParams();
    params.min_inliers = min_inliers;
    segmented = full.grid();
    std::int32_t count = 1;
    for (int v = 0; v < segmented.height; ++v)
      for (int u = 0; u < segmented.width; ++u) {
        labels.push_back(segment(u, v));
        count = std::max(count, labels.back() + 1);
      }
    root.resize(static_cast<std::size_t>(count));
    for (std::int32_t k = 0; k < count; ++k) root[static_cast<std::size_t>(k)] = k;
  }

  // Segment b merged into segment a.
  void mergeInto(std::int32_t a, std::int32_t b) { root[static_cast<std::size_t>(b)] = a; }

  const Segmentation& build(bool refine = false) { return buildWith(full.grid(), refine); }
  // With `measured` as the caller's grid (at s = 1, full as the smoothed one).
  const Segmentation& buildWith(const PointGrid& measured, bool refine = false) {
    sums.assign(root.size(), PlaneSums());
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (labels[i] != 0)
        sums[static_cast<std::size_t>(root[static_cast<std::size_t>(labels[i])])].add(Vec3::load(segmented.point(i)));
    MergedSegments merged;
    merged.labels = labels.data();
    merged.root = root.data();
    merged.sums = sums.data();
    merged.segment_count = root.size();
    PreparedFrame frame;
    frame.measured = measured;
    frame.grid = segmented;
    frame.pitch = kPinholePitch;
    frame.tolerances = Tolerances(params, {}, frame.pitch, full.data.size() / full.stride);
    frame.measured_tolerances = frame.tolerances;
    frame.holes = &holes;
    builder.assemble(frame, merged, params, refine);
    builder.write(frame, out);
    return out;
  }

  std::uint32_t label(int u, int v) const { return out.labels[full.index(u, v)]; }
  // How many pixels carry label k.
  std::size_t pixels(std::uint32_t k) const {
    std::size_t n = 0;
    for (const std::uint32_t l : out.labels) n += l == k ? 1 : 0;
    return n;
  }
};

// Three vertical bands of frontal planes: 5 columns at 2 m, 15 at 2.5 m, 10 at 3 m.
double bands(int u, int) { return u < 5 ? 2.0 : u < 20 ? 2.5 : 3.0; }
std::int32_t bandSegments(int u, int) { return u < 5 ? 1 : u < 20 ? 2 : 3; }

TEST(RegionBuilder, NumbersThePlanesBySizeLargestFirst) {
  Merged m(Grid(30, 12, bands), bandSegments);
  const Segmentation& out = m.build();
  EXPECT_EQ(out.width, 30);
  EXPECT_EQ(out.height, 12);
  ASSERT_EQ(out.labels.size(), 360u);
  ASSERT_EQ(out.planes.size(), 3u);
  EXPECT_EQ(out.planes[0].inlier_count, 180u);
  EXPECT_EQ(out.planes[1].inlier_count, 120u);
  EXPECT_EQ(out.planes[2].inlier_count, 60u);
  for (int v = 0; v < 12; ++v)
    for (int u = 0; u < 30; ++u) ASSERT_EQ(m.label(u, v), u < 5 ? 3u : u < 20 ? 1u : 2u) << u << ", " << v;
  // Each plane's fit and first pixel are its own.
  EXPECT_NEAR(out.planes[0].fit.offset, 2.5, 1e-5);
  EXPECT_NEAR(out.planes[1].fit.offset, 3.0, 1e-5);
  EXPECT_NEAR(out.planes[2].fit.offset, 2.0, 1e-5);
  EXPECT_NEAR(out.planes[0].fit.normal.z(), -1.0, 1e-6);  // towards the sensor
  EXPECT_EQ(out.planes[0].first_pixel, 5u);
  EXPECT_EQ(out.planes[1].first_pixel, 20u);
  EXPECT_EQ(out.planes[2].first_pixel, 0u);
}

TEST(RegionBuilder, DropsPlanesBelowMinInliers) {
  // 60 pixels is enough for min_inliers 60 ...
  Merged enough(Grid(30, 12, bands), bandSegments, 60);
  EXPECT_EQ(enough.build().planes.size(), 3u);
  // ... and one too few for 61: the smallest band goes, its pixels unlabelled.
  Merged too_few(Grid(30, 12, bands), bandSegments, 61);
  const Segmentation& out = too_few.build();
  ASSERT_EQ(out.planes.size(), 2u);
  EXPECT_EQ(out.planes[0].inlier_count, 180u);
  EXPECT_EQ(out.planes[1].inlier_count, 120u);
  for (int v = 0; v < 12; ++v)
    for (int u = 0; u < 5; ++u) EXPECT_EQ(too_few.label(u, v), 0u);
  EXPECT_EQ(too_few.pixels(1), 180u);
  EXPECT_EQ(too_few.pixels(2), 120u);
}

TEST(RegionBuilder, ReportsAMergedClusterAsOnePlane) {
  // Segments 1 and 2 are two halves of one wall that merged; 3 is a plane in front.
  const auto depth = [](int u, int) { return u < 20 ? 3.0 : 2.0; };
  Merged m(Grid(30, 10, depth), [](int u, int) { return u < 10 ? 1 : u < 20 ? 2 : 3; });
  m.mergeInto(1, 2);
  const Segmentation& out = m.build();
  ASSERT_EQ(out.planes.size(), 2u);
  EXPECT_EQ(out.planes[0].inlier_count, 200u);
  EXPECT_NEAR(out.planes[0].fit.offset, 3.0, 1e-5);
  EXPECT_EQ(m.pixels(1), 200u);
  EXPECT_EQ(m.label(0, 0), 1u);
  EXPECT_EQ(m.label(19, 9), 1u);
  EXPECT_EQ(m.label(20, 0), 2u);
}

TEST(RegionBuilder, GivesAnUnsegmentedPixelNoLabel) {
  Merged m(Grid(30, 12, bands), [](int u, int v) { return v == 3 && u == 25 ? 0 : bandSegments(u, v); });
  const Segmentation& out = m.build();
  EXPECT_EQ(m.label(25, 3), 0u);
  EXPECT_EQ(out.planes[1].inlier_count, 119u);
}

TEST(RegionBuilder, FitsThePlanesToTheMeasuredPoints) {
  // The caller's points are 1 mm behind the smoothed ones that were segmented.
  const Grid measured(30, 12, [](int u, int v) { return bands(u, v) + 0.001; });
  Merged m(Grid(30, 12, bands), bandSegments);
  const Segmentation& out = m.buildWith(measured.grid());
  ASSERT_EQ(out.planes.size(), 3u);
  EXPECT_NEAR(out.planes[0].fit.offset, 2.501, 1e-5);
  EXPECT_NEAR(out.planes[0].fit.centroid.z(), 2.501, 1e-5);
  EXPECT_EQ(out.planes[0].inlier_count, 180u);
}

TEST(RegionBuilder, RefinesIntoUnsegmentedPixelsAndNumbersByTheNewSizes) {
  // The 2 m plane's segment covers 5 of its 25 columns, less than the 2.5 m plane's 15; refined,
  // it is the largest.
  const auto depth = [](int u, int) { return u < 25 ? 2.0 : 2.5; };
  const auto segment = [](int u, int) { return u < 5 ? 1 : u < 25 ? 0 : 2; };
  Merged m(Grid(40, 6, depth), segment);
  const Segmentation& plain = m.build(false);
  ASSERT_EQ(plain.planes.size(), 2u);
  EXPECT_EQ(plain.planes[0].inlier_count, 90u);
  EXPECT_EQ(m.label(0, 0), 2u);
  EXPECT_EQ(m.label(10, 0), 0u);
  const Segmentation& refined = m.build(true);
  ASSERT_EQ(refined.planes.size(), 2u);
  EXPECT_EQ(refined.planes[0].inlier_count, 150u);
  EXPECT_EQ(refined.planes[1].inlier_count, 90u);
  EXPECT_EQ(m.pixels(1), 150u);
  EXPECT_EQ(m.label(0, 0), 1u);
  EXPECT_EQ(m.label(24, 5), 1u);
  EXPECT_EQ(m.label(25, 5), 2u);
}

TEST(RegionBuilder, JoinsPiecesOfAWallSeenAroundAnOccluder) {
  // Two segments of a wall at 3 m that did not merge (they do not touch), a column at 2 m
  // between them (no plane: no segment): one plane.
  const auto segment = [](int u, int) { return u < 10 ? 1 : u < 20 ? 0 : 2; };
  Merged occluded(Grid(30, 8, [](int u, int) { return u >= 10 && u < 20 ? 2.0 : 3.0; }), segment);
  const Segmentation& out = occluded.build();
  ASSERT_EQ(out.planes.size(), 1u);
  EXPECT_EQ(out.planes[0].inlier_count, 160u);
  EXPECT_EQ(out.planes[0].first_pixel, 0u);
  EXPECT_EQ(occluded.label(0, 0), 1u);
  EXPECT_EQ(occluded.label(29, 7), 1u);
  // With the floor seen between them (behind the wall's plane) they stay two.
  Merged apart(Grid(30, 8, [](int u, int) { return u >= 10 && u < 20 ? 4.0 : 3.0; }), segment);
  EXPECT_EQ(apart.build().planes.size(), 2u);
  EXPECT_EQ(apart.label(0, 0), 1u);
  EXPECT_EQ(apart.label(29, 7), 2u);
}

TEST(RegionBuilder, GivesEmptyOutputsForAnEmptyFrame) {
  Merged m(Grid(0, 0, bands), bandSegments);
  const Segmentation& out = m.build();
  EXPECT_EQ(out.width, 0);
  EXPECT_EQ(out.height, 0);
  EXPECT_TRUE(out.labels.empty());
  EXPECT_TRUE(out.planes.empty());
}

TEST(RegionBuilder, LabelsNothingInAFrameWithoutReturns) {
  Merged m(Grid(
               17, 9, [](int, int) { return kNaN; }, 4),
           [](int, int) { return 0; });
  const Segmentation& out = m.build(true);
  ASSERT_EQ(out.labels.size(), 153u);
  for (const std::uint32_t l : out.labels) EXPECT_EQ(l, 0u);
  EXPECT_TRUE(out.planes.empty());
}

TEST(RegionBuilder, ReportsNoPlaneOfFewerThanThreePoints) {
  Merged one(Grid(1, 1, bands), [](int, int) { return 1; });
  const Segmentation& out = one.build(true);
  ASSERT_EQ(out.labels.size(), 1u);
  EXPECT_EQ(out.labels[0], 0u);
  EXPECT_TRUE(out.planes.empty());
}

TEST(RegionBuilder, GivesTheSameResultForTheSameFrameAgain) {
  Merged m(Grid(30, 12, bands), bandSegments);
  const std::vector<std::uint32_t> first = m.build(true).labels;
  const std::size_t planes = m.out.planes.size();
  EXPECT_EQ(m.build(true).labels, first);
  EXPECT_EQ(m.out.planes.size(), planes);
}

}  // namespace
}  // namespace floodplane
