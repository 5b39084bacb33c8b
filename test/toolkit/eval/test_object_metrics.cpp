// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The object scores (osd_scores.py --objects) on hand-drawn label grids whose answers can be
// counted by eye. Ground truth in mOSD's coding: 'T' the table (label 1), 'a' and 'b' two parts
// of the first object (20, 21), 'c' the second object (30), '.' nothing; predicted objects are
// digits, '.' no object.

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "eval/object_metrics.h"

namespace {

using floodplane::eval::evaluateObjects;
using floodplane::eval::ObjectMetricsOptions;
using floodplane::eval::ObjectScores;

std::vector<std::uint32_t> truth(const std::string& pixels) {
  std::vector<std::uint32_t> labels;
  for (const char c : pixels) {
    labels.push_back(c == 'T' ? 1u : c == 'a' ? 20u : c == 'b' ? 21u : c == 'c' ? 30u : 0u);
  }
  return labels;
}

std::vector<std::uint32_t> objects(const std::string& pixels) {
  std::vector<std::uint32_t> labels;
  for (const char c : pixels) labels.push_back(c == '.' ? 0u : static_cast<std::uint32_t>(c - '0'));
  return labels;
}

// Grids this small need a small size rule: 1 keeps every object.
ObjectMetricsOptions keepAll() {
  ObjectMetricsOptions options;
  options.min_object_pixels = 1;
  return options;
}

ObjectScores score(const std::string& gt, const std::string& predicted,
                   const ObjectMetricsOptions& options = keepAll()) {
  return evaluateObjects(truth(gt), objects(predicted), options);
}

TEST(ObjectMetrics, AnObjectSpillingOntoTheTableAndOneMissingAnEdge) {
  // Rows of 8: the table on the left, object a over c on the right. Output 1 is a and two
  // table pixels (IoU 8/10: found, just), output 2 is 6 of c's 8 (IoU 0.75: not found).
  const auto s = score(
      "TTTTaaaa"
      "TTTTaaaa"
      "TTTTcccc"
      "TTTTcccc",
      "..111111"
      "....1111"
      "....2222"
      "....22..");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].label, 20u);
  EXPECT_EQ(s.objects[0].best, 1u);
  EXPECT_DOUBLE_EQ(s.objects[0].iou, 0.8);
  EXPECT_TRUE(s.objects[0].found);
  EXPECT_EQ(s.objects[1].best, 2u);
  EXPECT_DOUBLE_EQ(s.objects[1].iou, 0.75);
  EXPECT_FALSE(s.objects[1].found);
  EXPECT_DOUBLE_EQ(s.object_iou, 0.775);
  EXPECT_DOUBLE_EQ(s.objects_found, 0.5);
  EXPECT_DOUBLE_EQ(s.over, 0.0);
  EXPECT_DOUBLE_EQ(s.under, 0.0);
  EXPECT_DOUBLE_EQ(s.support_in_objects, 2.0 / 16.0);
  EXPECT_EQ(s.output_objects, 2u);
}

TEST(ObjectMetrics, TwoObjectsInOneOutputObjectAreBothMerged) {
  const auto s = score(
      "aaaacccc"
      "aaaacccc",
      "11111111"
      "11111111");
  EXPECT_DOUBLE_EQ(s.object_iou, 0.5);
  EXPECT_DOUBLE_EQ(s.objects_found, 0.0);
  EXPECT_DOUBLE_EQ(s.under, 1.0);
  EXPECT_DOUBLE_EQ(s.over, 0.0);
  EXPECT_DOUBLE_EQ(s.support_in_objects, 0.0);  // no table: nothing over max(1, 0)
}

TEST(ObjectMetrics, AnObjectIsCutWhenTwoOutputObjectsHoldAFifthEach) {
  // 2 of 10 pixels is a fifth: cut; 1 of 10 is not.
  EXPECT_DOUBLE_EQ(score("aaaaaaaaaa", "1111111122").over, 1.0);
  EXPECT_DOUBLE_EQ(score("aaaaaaaaaa", "1111111112").over, 0.0);
  // Halves: cut, and the tie goes to the lower label whichever comes first.
  const auto s = score("aaaaaaaaaa", "2222211111");
  EXPECT_DOUBLE_EQ(s.over, 1.0);
  EXPECT_EQ(s.objects[0].best, 1u);
  EXPECT_DOUBLE_EQ(s.object_iou, 0.5);
}

TEST(ObjectMetrics, MergedOnlyWhereTheBestOutputObjectHoldsAFifthOfAnother) {
  // Output 1 is all of a and 3 of c's 10 pixels: a is merged (1 holds 30 % of c); c's best is
  // output 2 (7 pixels), which holds none of a: c is cut (3 and 7 pixels), not merged.
  const auto s = score("aaaaaaaaaacccccccccc", "11111111111112222222");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_TRUE(s.objects[0].under);
  EXPECT_FALSE(s.objects[0].over);
  EXPECT_DOUBLE_EQ(s.objects[0].iou, 10.0 / 13.0);
  EXPECT_FALSE(s.objects[1].under);
  EXPECT_TRUE(s.objects[1].over);
  EXPECT_EQ(s.objects[1].best, 2u);
  EXPECT_DOUBLE_EQ(s.objects[1].iou, 0.7);
  EXPECT_DOUBLE_EQ(s.under, 0.5);
  EXPECT_DOUBLE_EQ(s.over, 0.5);
  EXPECT_DOUBLE_EQ(s.objects_found, 0.0);
}

TEST(ObjectMetrics, EachLabelOfAnObjectIsScoredApartAndSmallOnesAreLeftOut) {
  // a (20) and b (21) are two parts of the first object, scored as two objects as mOSD labels
  // them: one output object over both merges them.
  EXPECT_DOUBLE_EQ(score("aaaabbbb", "11111111").under, 1.0);
  // With the size rule at 2, b's one pixel is no object: nothing to merge a with.
  ObjectMetricsOptions options;
  options.min_object_pixels = 2;
  const auto s = score("aaaab", "11111", options);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].label, 20u);
  EXPECT_FALSE(s.objects[0].under);
  EXPECT_DOUBLE_EQ(s.object_iou, 0.8);
}

TEST(ObjectMetrics, AMissedObjectScoresZeroAndAFrameWithoutObjectsScoresZero) {
  const auto missed = score("TTaacc", "..11..");
  EXPECT_EQ(missed.objects[1].best, 0u);
  EXPECT_DOUBLE_EQ(missed.objects[1].iou, 0.0);
  EXPECT_FALSE(missed.objects[1].under);
  EXPECT_DOUBLE_EQ(missed.object_iou, 0.5);
  EXPECT_DOUBLE_EQ(missed.objects_found, 0.5);
  const auto none = score("TTTT", "11..");
  EXPECT_TRUE(none.objects.empty());
  EXPECT_DOUBLE_EQ(none.object_iou, 0.0);
  EXPECT_DOUBLE_EQ(none.objects_found, 0.0);
  EXPECT_DOUBLE_EQ(none.support_in_objects, 0.5);
}

TEST(ObjectMetrics, RejectsGridsOfTwoSizesAndBadOptions) {
  EXPECT_THROW(evaluateObjects(truth("aa"), objects("1")), std::invalid_argument);
  ObjectMetricsOptions options;
  options.last_support_label = 20;  // reaches the objects
  EXPECT_THROW(evaluateObjects(truth("aa"), objects("11"), options), std::invalid_argument);
  options = ObjectMetricsOptions();
  options.hold_share = 0.0;
  EXPECT_THROW(evaluateObjects(truth("aa"), objects("11"), options), std::invalid_argument);
}

}  // namespace
