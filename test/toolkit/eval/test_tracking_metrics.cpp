// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Tracking metrics on hand-made label sequences whose answers can be counted by eye. A frame
// is one string of labels for the ground truth and one for the track ids: a digit is a label,
// '.' is label 0; in a mask, 'x' marks a pixel whose ground-truth point is NaN.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "eval/tracking_metrics.h"

namespace {

using floodplane::eval::TrackingEvaluator;
using floodplane::eval::TrackingOptions;
using floodplane::eval::TrackingScores;

std::vector<std::uint32_t> labels(const std::string& row) {
  std::vector<std::uint32_t> result;
  for (const char c : row) result.push_back(c == '.' ? 0U : static_cast<std::uint32_t>(c - '0'));
  return result;
}

std::vector<std::uint8_t> mask(const std::string& row) {
  std::vector<std::uint8_t> valid;
  for (const char c : row) valid.push_back(c == 'x' ? 0 : 1);
  return valid;
}

// Frames of 10 pixels; a plane needs 2 of them (20 %) to be present.
TrackingOptions tenPixelFrames() {
  TrackingOptions options;
  options.min_fraction = 0.2;
  return options;
}

struct Frame {
  std::string ground_truth;
  std::string predicted;
};

TrackingScores evaluate(const std::vector<Frame>& frames, const TrackingOptions& options = tenPixelFrames()) {
  TrackingEvaluator evaluator(options);
  for (const Frame& frame : frames) {
    const auto ground_truth = labels(frame.ground_truth);
    evaluator.addFrame(ground_truth, labels(frame.predicted), std::vector<std::uint8_t>(ground_truth.size(), 1));
  }
  return evaluator.scores();
}

// The frames of `frame` repeated `times`.
std::vector<Frame> repeated(const Frame& frame, int times) {
  return std::vector<Frame>(static_cast<std::size_t>(times), frame);
}

std::vector<Frame> joined(std::vector<Frame> first, const std::vector<Frame>& second) {
  first.insert(first.end(), second.begin(), second.end());
  return first;
}

TEST(TrackingMetrics, AConstantSequenceHasNoSwitchesAndNothingLost) {
  const TrackingScores scores = evaluate(repeated({"1111122222", "3333344444"}, 5));
  EXPECT_EQ(scores.frames, 5U);
  EXPECT_EQ(scores.plane_frames, 10U);
  EXPECT_EQ(scores.matched, 10U);
  EXPECT_EQ(scores.id_switches, 0U);
  EXPECT_EQ(scores.lost, 0U);
  EXPECT_EQ(scores.re_entries, 0U);
  EXPECT_EQ(scores.switchesPer100PlaneFrames(), 0.0);
  EXPECT_TRUE(std::isnan(scores.keptShare()));
}

TEST(TrackingMetrics, TwoPlanesSwappingTheirIdsAreTwoSwitches) {
  const TrackingScores scores =
      evaluate({{"1111122222", "3333344444"}, {"1111122222", "4444433333"}, {"1111122222", "4444433333"}});
  EXPECT_EQ(scores.plane_frames, 6U);
  EXPECT_EQ(scores.id_switches, 2U);
  EXPECT_DOUBLE_EQ(scores.switchesPer100PlaneFrames(), 100.0 * 2 / 6);
}

TEST(TrackingMetrics, ANewIdForAPlaneInViewIsOneSwitchAndTheNewIdIsThenItsOwn) {
  const TrackingScores scores = evaluate({{"1111111111", "5555555555"},
                                          {"1111111111", "6666666666"},
                                          {"1111111111", "6666666666"},
                                          {"1111111111", "5555555555"}});
  EXPECT_EQ(scores.id_switches, 2U);
}

TEST(TrackingMetrics, AnUnmatchedPlaneIsLostAndKeepsItsRememberedId) {
  // Frame 2: no prediction; frame 3: a segment too large for IoU 0.5 (4 of 10 pixels of the
  // union); frame 4: the old id again, no switch.
  const TrackingScores scores = evaluate({{"1111......", "5555......"},
                                          {"1111......", ".........."},
                                          {"1111......", "5555555555"},
                                          {"1111......", "5555......"}});
  EXPECT_EQ(scores.plane_frames, 4U);
  EXPECT_EQ(scores.matched, 2U);
  EXPECT_EQ(scores.lost, 2U);
  EXPECT_EQ(scores.id_switches, 0U);
  EXPECT_DOUBLE_EQ(scores.lostPer100PlaneFrames(), 50.0);
}

TEST(TrackingMetrics, APlaneMatchesTheIdOverlappingItMostFromIouOneHalf) {
  const TrackingScores scores = evaluate({{"111111....", "777788...."},    // 7 overlaps most: IoU 4/6
                                          {"111111....", "888777...."},    // a tie: the smaller id, 7, IoU 3/6
                                          {"111111....", "7788888888"}});  // 8 overlaps most: IoU 4/10
  EXPECT_EQ(scores.matched, 2U);
  EXPECT_EQ(scores.lost, 1U);
  EXPECT_EQ(scores.id_switches, 0U);
}

TEST(TrackingMetrics, APlaneReturningWithItsIdIsAKeptReEntry) {
  const TrackingScores scores =
      evaluate(joined(joined(repeated({"1111122222", "5555566666"}, 3), repeated({"2222222222", "6666666666"}, 4)),
                      repeated({"1111122222", "5555566666"}, 2)));
  EXPECT_EQ(scores.re_entries, 1U);
  EXPECT_EQ(scores.re_entries_kept, 1U);
  EXPECT_EQ(scores.re_entries_switched, 0U);
  EXPECT_EQ(scores.id_switches, 0U);
  EXPECT_EQ(scores.plane_frames, 3U * 2 + 4 + 2 * 2);
  EXPECT_DOUBLE_EQ(scores.keptShare(), 1.0);
}

TEST(TrackingMetrics, APlaneReturningWithANewIdIsASwitchedReEntryAndASwitch) {
  const TrackingScores scores = evaluate({{"1111122222", "5555566666"},
                                          {"2222222222", "6666666666"},
                                          {"1111122222", "7777766666"},
                                          {"1111122222", "7777766666"}});
  EXPECT_EQ(scores.re_entries, 1U);
  EXPECT_EQ(scores.re_entries_kept, 0U);
  EXPECT_EQ(scores.re_entries_switched, 1U);
  EXPECT_EQ(scores.id_switches, 1U);
  EXPECT_DOUBLE_EQ(scores.keptShare(), 0.0);
}

TEST(TrackingMetrics, AReEntryIsDecidedAtItsFirstMatchAfterTheReturn) {
  // Back in frame 2 but unmatched (lost), matched with its old id in frame 3: kept.
  const TrackingScores kept = evaluate({{"1111122222", "5555566666"},
                                        {"2222222222", "6666666666"},
                                        {"1111122222", "....666666"},
                                        {"1111122222", "5555566666"}});
  EXPECT_EQ(kept.re_entries, 1U);
  EXPECT_EQ(kept.re_entries_kept, 1U);
  EXPECT_EQ(kept.lost, 1U);
  // Back but never matched before the sequence ends: neither kept nor switched.
  const TrackingScores undecided =
      evaluate({{"1111122222", "5555566666"}, {"2222222222", "6666666666"}, {"1111122222", "....666666"}});
  EXPECT_EQ(undecided.re_entries, 1U);
  EXPECT_EQ(undecided.re_entries_kept + undecided.re_entries_switched, 0U);
}

TEST(TrackingMetrics, APlaneAwayLongerThanTheGapIsForgottenNotSwitched) {
  TrackingOptions options = tenPixelFrames();
  options.max_gap = 3;
  const std::vector<Frame> away_three =
      joined(joined(repeated({"1111122222", "5555566666"}, 1), repeated({"2222222222", "6666666666"}, 3)),
             repeated({"1111122222", "7777766666"}, 1));
  const TrackingScores within = evaluate(away_three, options);
  EXPECT_EQ(within.re_entries, 1U);
  EXPECT_EQ(within.id_switches, 1U);
  const std::vector<Frame> away_four =
      joined(joined(repeated({"1111122222", "5555566666"}, 1), repeated({"2222222222", "6666666666"}, 4)),
             repeated({"1111122222", "7777766666"}, 1));
  const TrackingScores beyond = evaluate(away_four, options);
  EXPECT_EQ(beyond.re_entries, 0U);
  EXPECT_EQ(beyond.id_switches, 0U);
}

TEST(TrackingMetrics, PlanesBelowTheMinimumSizeAreAbsent) {
  // Plane 3 has one pixel (10 %, below 20 %) in frame 1: absent there, so frame 2 is a return.
  const TrackingScores scores =
      evaluate({{"1111133333", "5555577777"}, {"1111111113", "5555555557"}, {"1111133333", "5555577777"}});
  EXPECT_EQ(scores.plane_frames, 5U);
  EXPECT_EQ(scores.re_entries, 1U);
  EXPECT_EQ(scores.re_entries_kept, 1U);
}

TEST(TrackingMetrics, InvalidPixelsCountNowhere) {
  TrackingEvaluator evaluator(tenPixelFrames());
  // Plane 1 has 2 valid pixels: present, and id 5's 6 other pixels are invalid, so IoU 1.
  evaluator.addFrame(labels("11111111.."), labels("55555555.."), mask("xxxxxx...."));
  // Only 1 valid pixel left: absent.
  evaluator.addFrame(labels("11111111.."), labels("55555555.."), mask("xxxxxxx..."));
  EXPECT_EQ(evaluator.scores().plane_frames, 1U);
  EXPECT_EQ(evaluator.scores().matched, 1U);
}

TEST(TrackingMetrics, BadOptionsAndMismatchedSizesAreRejected) {
  TrackingOptions options;
  options.min_fraction = 0.0;
  EXPECT_THROW(TrackingEvaluator{options}, std::invalid_argument);
  options = TrackingOptions();
  options.min_iou = 1.5;
  EXPECT_THROW(TrackingEvaluator{options}, std::invalid_argument);
  options = TrackingOptions();
  options.max_gap = -1;
  EXPECT_THROW(TrackingEvaluator{options}, std::invalid_argument);
  TrackingEvaluator evaluator;
  EXPECT_THROW(evaluator.addFrame(labels("11"), labels("1"), mask("..")), std::invalid_argument);
  EXPECT_THROW(evaluator.addFrame(labels("11"), labels("11"), mask("...")), std::invalid_argument);
}

}  // namespace
