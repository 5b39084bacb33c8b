// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Segmentation metrics on hand-drawn label grids whose answers can be counted by eye.
// Grids are written one string per row: a digit is a label, '.' is label 0; in a mask, 'x'
// marks a pixel whose ground-truth point is NaN.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "eval/segmentation_metrics.h"

namespace {

using floodplane::eval::defaultMinPoints;
using floodplane::eval::evaluateSegmentation;
using floodplane::eval::falsePlaneFraction;
using floodplane::eval::HooverClass;
using floodplane::eval::MetricsOptions;
using floodplane::eval::MissReason;
using floodplane::eval::SegmentationScores;

std::vector<std::uint32_t> grid(const std::vector<std::string>& rows) {
  std::vector<std::uint32_t> labels;
  for (const std::string& row : rows) {
    for (const char c : row) {
      labels.push_back(c == '.' ? 0u : static_cast<std::uint32_t>(c - '0'));
    }
  }
  return labels;
}

std::vector<std::uint8_t> mask(const std::vector<std::string>& rows) {
  std::vector<std::uint8_t> valid;
  for (const std::string& row : rows) {
    for (const char c : row) {
      valid.push_back(c == 'x' ? 0 : 1);
    }
  }
  return valid;
}

std::vector<std::uint8_t> allValid(std::size_t size) { return std::vector<std::uint8_t>(size, 1); }

// Small grids need a small size rule; 1 keeps every region.
MetricsOptions keepAll() {
  MetricsOptions options;
  options.min_points = 1;
  return options;
}

SegmentationScores score(const std::vector<std::string>& gt, const std::vector<std::string>& pred,
                         const MetricsOptions& options = keepAll()) {
  const auto g = grid(gt);
  return evaluateSegmentation(g, grid(pred), allValid(g.size()), options);
}

void expectCounts(const SegmentationScores& s, std::size_t correct, std::size_t over, std::size_t under,
                  std::size_t missed, std::size_t noise) {
  EXPECT_EQ(s.hoover.correct, correct);
  EXPECT_EQ(s.hoover.over, over);
  EXPECT_EQ(s.hoover.under, under);
  EXPECT_EQ(s.hoover.missed, missed);
  EXPECT_EQ(s.hoover.noise, noise);
}

TEST(SegmentationMetrics, IdenticalSegmentationsUnderOtherLabelNumbersAreAllCorrect) {
  const auto s = score({"1111122222", "1111122222"}, {"7777733333", "7777733333"});
  expectCounts(s, 2, 0, 0, 0, 0);
  EXPECT_DOUBLE_EQ(s.mean_iou, 1.0);
  EXPECT_DOUBLE_EQ(s.weighted_iou, 1.0);
  ASSERT_EQ(s.planes.size(), 2u);
  EXPECT_EQ(s.planes[0].best_segment, 7u);
  EXPECT_EQ(s.planes[1].best_segment, 3u);
  EXPECT_EQ(s.planes[0].hoover, HooverClass::correct);
}

TEST(SegmentationMetrics, SegmentCoveringEightyPercentBothWaysIsACorrectDetection) {
  // g: 10 pixels; p: 9 of them plus 2 outside, |p| = 11. O = 9 >= 0.8 * 10 and >= 0.8 * 11.
  const auto t = score({"1111111111..", "............"}, {".22222222222", "............"});
  expectCounts(t, 1, 0, 0, 0, 0);
  EXPECT_DOUBLE_EQ(t.mean_iou, 9.0 / 12.0);
}

TEST(SegmentationMetrics, SegmentCoveringTooLittleOfThePlaneIsMissedAndNoise) {
  // O = 7 < 0.8 * 10: not correct; one segment alone cannot over-segment.
  const auto s = score({"1111111111"}, {"2222222..."});
  expectCounts(s, 0, 0, 0, 1, 1);
  EXPECT_DOUBLE_EQ(s.mean_iou, 0.7);
  EXPECT_EQ(s.planes[0].hoover, HooverClass::missed);
}

TEST(SegmentationMetrics, SegmentSpillingTooFarBeyondThePlaneIsNotCorrect) {
  // O = 10 = |g| but |p| = 14: 10 < 0.8 * 14 = 11.2.
  const auto s = score({"1111111111...."}, {"22222222222222"});
  expectCounts(s, 0, 0, 0, 1, 1);
  EXPECT_DOUBLE_EQ(s.mean_iou, 10.0 / 14.0);
}

TEST(SegmentationMetrics, PlaneSplitIntoTwoSegmentsIsOneOverSegmentation) {
  const auto s = score({"1111111111"}, {"2222233333"});
  expectCounts(s, 0, 1, 0, 0, 0);
  EXPECT_EQ(s.planes[0].hoover, HooverClass::over_segmented);
  EXPECT_DOUBLE_EQ(s.mean_iou, 0.5);
}

TEST(SegmentationMetrics, SplitCoveringTooLittleOfThePlaneIsNoOverSegmentation) {
  // Parts of 4 + 3 = 7 < 0.8 * 10.
  const auto s = score({"1111111111"}, {"2222333..."});
  expectCounts(s, 0, 0, 0, 1, 2);
}

TEST(SegmentationMetrics, TwoPlanesInOneSegmentAreOneUnderSegmentation) {
  const auto s = score({"1111122222"}, {"3333333333"});
  expectCounts(s, 0, 0, 1, 0, 0);
  EXPECT_EQ(s.planes[0].hoover, HooverClass::under_segmented);
  EXPECT_EQ(s.planes[1].hoover, HooverClass::under_segmented);
  EXPECT_DOUBLE_EQ(s.mean_iou, 0.5);
}

TEST(SegmentationMetrics, UnderSegmentationNeedsTheSegmentMostlyOnThePlanes) {
  // Planes 3 + 3 = 6 pixels inside a 10-pixel segment: 6 < 0.8 * 10.
  const auto s = score({"111222...."}, {"3333333333"});
  expectCounts(s, 0, 0, 0, 2, 1);
}

TEST(SegmentationMetrics, PlaneWithNoSegmentIsMissedWithIouZero) {
  const auto s = score({"1111122222"}, {"33333....."});
  expectCounts(s, 1, 0, 0, 1, 0);
  EXPECT_DOUBLE_EQ(s.planes[1].iou, 0.0);
  EXPECT_EQ(s.planes[1].best_segment, 0u);
  EXPECT_DOUBLE_EQ(s.mean_iou, 0.5);
}

TEST(SegmentationMetrics, SegmentOffEveryPlaneIsNoise) {
  const auto s = score({"11111....."}, {"22222.3333"});
  expectCounts(s, 1, 0, 0, 0, 1);
  EXPECT_EQ(s.predicted_segments, 2u);
}

TEST(SegmentationMetrics, CorrectDetectionsAreAssignedBeforeOverSegmentation) {
  // Segments 2 (9 px) and 3 (1 px) would also over-segment plane 1; the correct pair wins
  // and segment 3 is left as noise.
  const auto s = score({"1111111111"}, {"2222222223"});
  expectCounts(s, 1, 0, 0, 0, 1);
}

TEST(SegmentationMetrics, CorrectDetectionsAreAssignedBeforeUnderSegmentation) {
  // Planes 1 (9 px) and 2 (1 px) would also be under-segmented by segment 3; the correct
  // pair wins and plane 2 is missed.
  const auto s = score({"1111111112"}, {"3333333333"});
  expectCounts(s, 1, 0, 0, 1, 0);
}

TEST(SegmentationMetrics, PixelsWithoutGroundTruthPointAreIgnored) {
  // The segment spills over 5 pixels that have no ground-truth point, and plane 2 exists
  // only there: with the mask, plane 1 is matched exactly and plane 2 is not a plane.
  const auto gt = grid({"111111111122222"});
  const auto pred = grid({"444444444444444"});
  const auto valid = mask({"..........xxxxx"});
  const auto s = evaluateSegmentation(gt, pred, valid, keepAll());
  expectCounts(s, 1, 0, 0, 0, 0);
  EXPECT_EQ(s.planes.size(), 1u);
  EXPECT_EQ(s.planes[0].pixels, 10u);
  EXPECT_DOUBLE_EQ(s.mean_iou, 1.0);

  // Without the mask the same labels are an under-segmentation: planes of 10 and 5 pixels
  // lie inside the 15-pixel segment and cover all of it.
  const auto unmasked = evaluateSegmentation(gt, pred, allValid(gt.size()), keepAll());
  expectCounts(unmasked, 0, 0, 1, 0, 0);
}

TEST(SegmentationMetrics, RegionsBelowTheMinimumSizeAreIgnored) {
  MetricsOptions options;
  options.min_points = 5;
  // Plane 2 (3 px) is too small: not averaged, not missed. Segment 5 (4 px) is too small:
  // not noise, and not the best match of plane 1 although its IoU (4/10) beats segment 6's.
  const auto s = score({"1111111111222.."}, {"5555...666..666"}, options);
  ASSERT_EQ(s.planes.size(), 1u);
  EXPECT_EQ(s.planes[0].label, 1u);
  EXPECT_EQ(s.predicted_segments, 1u);
  EXPECT_EQ(s.planes[0].best_segment, 6u);
  EXPECT_DOUBLE_EQ(s.mean_iou, 3.0 / 13.0);
  expectCounts(s, 0, 0, 0, 1, 1);
}

TEST(SegmentationMetrics, MinimumSizeCountsOnlyValidPixels) {
  MetricsOptions options;
  options.min_points = 5;
  // Plane 1 has 6 pixels, but 2 have no point: 4 < 5, so no plane is kept.
  const auto gt = grid({"111111...."});
  const auto s = evaluateSegmentation(gt, grid({"2222222222"}), mask({"xx........"}), options);
  EXPECT_TRUE(s.planes.empty());
  EXPECT_TRUE(std::isnan(s.mean_iou));
  EXPECT_TRUE(std::isnan(s.weighted_iou));
  expectCounts(s, 0, 0, 0, 0, 1);
}

TEST(SegmentationMetrics, WeightedIouWeighsPlanesByTheirSize) {
  // Plane 1 (30 px) found exactly, plane 2 (10 px) not at all.
  const auto s = score({"111111111111111111111111111111", "2222222222...................."},
                       {"333333333333333333333333333333", ".............................."});
  EXPECT_DOUBLE_EQ(s.mean_iou, 0.5);
  EXPECT_DOUBLE_EQ(s.weighted_iou, 0.75);
}

TEST(SegmentationMetrics, IouTakesTheBestOfSeveralOverlappingSegments) {
  // Segment 2: 3/10; segment 3: 6 / (10 + 8 - 6) = 0.5.
  const auto s = score({"1111111111......"}, {"2223333336666.33"});
  EXPECT_EQ(s.planes[0].best_segment, 3u);
  EXPECT_DOUBLE_EQ(s.planes[0].iou, 0.5);
}

TEST(SegmentationMetrics, ToleranceOutsideHooversRangeIsRejected) {
  const auto g = grid({"11"});
  MetricsOptions options = keepAll();
  options.tolerance = 0.5;
  EXPECT_THROW(evaluateSegmentation(g, g, allValid(2), options), std::invalid_argument);
  options.tolerance = 1.01;
  EXPECT_THROW(evaluateSegmentation(g, g, allValid(2), options), std::invalid_argument);
  options.tolerance = 1.0;
  EXPECT_NO_THROW(evaluateSegmentation(g, g, allValid(2), options));
}

TEST(SegmentationMetrics, GridsOfDifferentSizesAreRejected) {
  EXPECT_THROW(evaluateSegmentation(grid({"11"}), grid({"111"}), allValid(2)), std::invalid_argument);
  EXPECT_THROW(evaluateSegmentation(grid({"11"}), grid({"11"}), allValid(3)), std::invalid_argument);
}

// Why a plane is missed, one test per reason (MissReason, in its order).

TEST(SegmentationMetrics, CorrectDetectionHasNoMissReason) {
  const auto s = score({"1111111111.."}, {"222222222..."});
  ASSERT_EQ(s.planes.size(), 1u);
  EXPECT_EQ(s.planes[0].miss, MissReason::none);
  EXPECT_DOUBLE_EQ(s.planes[0].unlabelled_share, 0.1);
  EXPECT_EQ(s.planes[0].main_segment, 2u);
  EXPECT_DOUBLE_EQ(s.planes[0].main_segment_share, 0.9);
  EXPECT_TRUE(s.noise.empty());
}

TEST(SegmentationMetrics, PlaneMostlyUnlabelledIsMissedForNoSegment) {
  // 8 of 10 pixels unlabelled; segment 2 lies inside the plane, alone: noise.
  const auto s = score({"1111111111"}, {"22........"});
  expectCounts(s, 0, 0, 0, 1, 1);
  EXPECT_EQ(s.planes[0].miss, MissReason::no_segment);
  EXPECT_DOUBLE_EQ(s.planes[0].unlabelled_share, 0.8);
  EXPECT_EQ(s.planes[0].main_segment, 2u);
  EXPECT_DOUBLE_EQ(s.planes[0].main_segment_share, 0.2);
  // Half unlabelled is "most" too.
  EXPECT_EQ(score({"1111111111"}, {"22222....."}).planes[0].miss, MissReason::no_segment);
}

TEST(SegmentationMetrics, UnlabelledShareCountsOnlyValidPixels) {
  // 4 of the plane's 6 pixels with a point are unlabelled; the other 4 have no point.
  const auto gt = grid({"1111111111"});
  const auto s = evaluateSegmentation(gt, grid({"22........"}), mask({"..xxxx...."}), keepAll());
  ASSERT_EQ(s.planes.size(), 1u);
  EXPECT_EQ(s.planes[0].pixels, 6u);
  EXPECT_DOUBLE_EQ(s.planes[0].unlabelled_share, 4.0 / 6.0);
}

TEST(SegmentationMetrics, HooversOverAndUnderSegmentationsAreTheirOwnReasons) {
  EXPECT_EQ(score({"1111111111"}, {"2222233333"}).planes[0].miss, MissReason::over_segmented);
  const auto under = score({"1111122222"}, {"3333333333"});
  EXPECT_EQ(under.planes[0].miss, MissReason::under_segmented);
  EXPECT_EQ(under.planes[1].miss, MissReason::under_segmented);
  EXPECT_TRUE(under.noise.empty());
}

TEST(SegmentationMetrics, PlaneSplitAmongSegmentsThatSpillIsMissedAsOverSegmented) {
  // Segments 2 and 3 each hold 4 of the plane's 10 pixels and as many off it: too much spill
  // for Hoover's over-segmentation (4 < 0.8 * 8), and neither holds half of the plane.
  const auto s = score({"....1111111111...."}, {"222222223333..3333"});
  expectCounts(s, 0, 0, 0, 1, 2);
  EXPECT_EQ(s.planes[0].miss, MissReason::over_segmented);
  EXPECT_DOUBLE_EQ(s.planes[0].unlabelled_share, 0.2);
  EXPECT_EQ(s.planes[0].main_segment, 2u);  // a tie: the lower label
  EXPECT_DOUBLE_EQ(s.planes[0].main_segment_share, 0.4);
  // Both segments are noise, half of each on no plane.
  ASSERT_EQ(s.noise.size(), 2u);
  EXPECT_EQ(s.noise[0].label, 2u);
  EXPECT_EQ(s.noise[0].pixels, 8u);
  EXPECT_DOUBLE_EQ(s.noise[0].iou, 4.0 / 14.0);
  EXPECT_DOUBLE_EQ(s.noise[0].off_plane_share, 0.5);
  EXPECT_EQ(s.noise[1].label, 3u);
}

TEST(SegmentationMetrics, PlaneWhoseSegmentRunsOnOverAnotherPlaneIsMissedAsUnderSegmented) {
  // Segment 3 holds all of plane 1 and half of plane 2: not Hoover's under-segmentation (it
  // covers too little of plane 2), but 5 of its 15 pixels lie on another plane, more than
  // (1 - 0.8) * 15. Plane 2 is half unlabelled.
  const auto s = score({"11111111112222222222"}, {"333333333333333....."});
  expectCounts(s, 0, 0, 0, 2, 1);
  EXPECT_EQ(s.planes[0].miss, MissReason::under_segmented);
  EXPECT_DOUBLE_EQ(s.planes[0].main_segment_share, 1.0);
  EXPECT_EQ(s.planes[1].miss, MissReason::no_segment);
  ASSERT_EQ(s.noise.size(), 1u);
  EXPECT_DOUBLE_EQ(s.noise[0].off_plane_share, 0.0);
}

TEST(SegmentationMetrics, PlaneFoundAtALowOverlapIsMissedAsIouBelowT) {
  // Too little of the plane: 7 of 10.
  const auto part = score({"1111111111"}, {"2222222..."});
  EXPECT_EQ(part.planes[0].miss, MissReason::iou_below_t);
  EXPECT_DOUBLE_EQ(part.planes[0].unlabelled_share, 0.3);
  // All of it, but spilling over 4 pixels on no plane: 10 < 0.8 * 14.
  const auto spill = score({"1111111111...."}, {"22222222222222"});
  EXPECT_EQ(spill.planes[0].miss, MissReason::iou_below_t);
  ASSERT_EQ(spill.noise.size(), 1u);
  EXPECT_DOUBLE_EQ(spill.noise[0].off_plane_share, 4.0 / 14.0);
  EXPECT_DOUBLE_EQ(spill.noise[0].iou, 10.0 / 14.0);
  // Spilling onto another plane by no more than 1 - T of the segment is no merge: segment 3
  // (10 px) holds 7 of plane 1 and 2 of plane 2 (2 <= 0.2 * 10, and 1 pixel on no plane).
  const auto small_spill = score({"11111111112222222222."}, {"...333333333........3"});
  EXPECT_EQ(small_spill.planes[0].miss, MissReason::iou_below_t);
}

TEST(SegmentationMetrics, FalsePlaneFractionIsTheShareOfNonPlanePixelsInASegment) {
  // Ground truth 0 at columns 5-9 of both rows (a curved surface): 10 pixels. Segment 3 claims
  // 3 of them in the first row, segment 4 one in the second: 4 / 10.
  const std::vector<std::string> gt = {"11111.....", "11111....."};
  const std::vector<std::string> pred = {"22222333..", "222224...."};
  EXPECT_DOUBLE_EQ(score(gt, pred).false_plane_fraction, 0.4);
  EXPECT_DOUBLE_EQ(falsePlaneFraction(grid(gt), grid(pred), allValid(20), 1), 0.4);
  // Every non-plane pixel in a segment: 1.
  EXPECT_DOUBLE_EQ(score({"11111....."}, {"2222233333"}).false_plane_fraction, 1.0);
  // None: 0, not undefined.
  EXPECT_DOUBLE_EQ(score({"11111....."}, {"22222....."}).false_plane_fraction, 0.0);
}

TEST(SegmentationMetrics, FalsePlaneFractionCountsOnlyValidPixelsAndKeptSegments) {
  // Ground truth 0 at columns 5-10, of which 5 and 6 have no point: 4 valid non-plane pixels.
  // Segment 3 claims columns 5, 6, 7 and 10 (2 of them valid), segment 4 column 8.
  const auto gt = grid({"11111......"});
  const auto pred = grid({"222223334.3"});
  const auto valid = mask({".....xx...."});
  EXPECT_DOUBLE_EQ(falsePlaneFraction(gt, pred, valid, 1), 3.0 / 4.0);
  // Sizes count valid pixels: segment 3 has 2, segment 4 has 1. With a minimum size of 2
  // segment 4 is ignored, with 3 both are.
  EXPECT_DOUBLE_EQ(falsePlaneFraction(gt, pred, valid, 2), 2.0 / 4.0);
  EXPECT_DOUBLE_EQ(falsePlaneFraction(gt, pred, valid, 3), 0.0);
  MetricsOptions options;
  options.min_points = 2;
  EXPECT_DOUBLE_EQ(evaluateSegmentation(gt, pred, valid, options).false_plane_fraction, 2.0 / 4.0);
}

TEST(SegmentationMetrics, FalsePlaneFractionIsUndefinedWithoutNonPlanePixels) {
  // No ground-truth 0 at all.
  EXPECT_TRUE(std::isnan(score({"1111122222"}, {"3333333333"}).false_plane_fraction));
  // Ground-truth 0 only where there is no point.
  const auto gt = grid({"11111..."});
  const auto pred = grid({"22222222"});
  EXPECT_TRUE(std::isnan(falsePlaneFraction(gt, pred, mask({".....xxx"}), 1)));
  EXPECT_TRUE(std::isnan(evaluateSegmentation(gt, pred, mask({".....xxx"}), keepAll()).false_plane_fraction));
  // The IoU and Hoover counts are still there.
  EXPECT_DOUBLE_EQ(evaluateSegmentation(gt, pred, mask({".....xxx"}), keepAll()).mean_iou, 1.0);
}

TEST(SegmentationMetrics, FalsePlaneFractionRejectsGridsOfDifferentSizes) {
  EXPECT_THROW(falsePlaneFraction(grid({"11"}), grid({"111"}), allValid(2), 1), std::invalid_argument);
  EXPECT_THROW(falsePlaneFraction(grid({"11"}), grid({"11"}), allValid(3), 1), std::invalid_argument);
}

TEST(SegmentationMetrics, DefaultMinimumSizeScalesWithThePixelCount) {
  EXPECT_EQ(defaultMinPoints(640, 480), 500u);
  EXPECT_EQ(defaultMinPoints(320, 240), 125u);
  EXPECT_EQ(defaultMinPoints(160, 120), 31u);  // 31.25
  EXPECT_EQ(defaultMinPoints(80, 60), 8u);     // 7.8125
  EXPECT_EQ(defaultMinPoints(1280, 960), 2000u);
  EXPECT_EQ(defaultMinPoints(512, 512), 427u);  // 426.67: the ABW scans' default
}

}  // namespace
