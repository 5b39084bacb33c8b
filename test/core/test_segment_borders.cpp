// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The borders between segments (SegmentBorders): one pass over the segment image collects,
// per pair of touching segments, the pixel pairs across their border, from which the merge
// test reads the step between them (MergeCriterion::continuous).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "flood/segment_borders.h"
#include "models/plane_candidates.h"
#include "support/pinhole_grid.h"

namespace floodplane {
namespace {

constexpr double kFocal = test::kPinholeFocal;

// Segments 1..9 over a pinhole grid from string art ('.' is 0), each with the sums of its
// pixels and the criterion of its plane (sigma_plane 1 cm, no noise).
struct Frame {
  test::PinholeGrid grid;
  std::vector<std::int32_t> labels;
  std::vector<Segment> segments;

  Frame(
      const std::vector<std::string>& art, const std::function<double(int, int)>& depth = [](int, int) { return 2.0; })
      : grid(static_cast<int>(art[0].size()), static_cast<int>(art.size()), depth) {
    for (const std::string& row : art)
      for (const char c : row) labels.push_back(c == '.' ? 0 : c - '0');
    Params params;
    params.distance_threshold = 0.01;
    const Tolerances tolerances(params, {}, 1.0 / kFocal, labels.size());
    segments.assign(static_cast<std::size_t>(*std::max_element(labels.begin(), labels.end()) + 1), Segment());
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (labels[i] != 0) segments[static_cast<std::size_t>(labels[i])].sums.add(grid.point(i));
    for (std::size_t s = 1; s < segments.size(); ++s)
      segments[s].criterion = planeCriterion(segments[s].sums.fit(), tolerances, static_cast<float>(1.0 / kFocal));
  }
  const SegmentBorderMap& collect() {
    borders.collect(grid.grid(), labels, segments);
    return borders.borders();
  }
  SegmentBorders borders;
};

TEST(SegmentBorders, CountsThePixelPairsAcrossEachBorderOnce) {
  Frame frame({"1122",  //
               "1122",  //
               "3333"});
  const SegmentBorderMap& borders = frame.collect();
  ASSERT_EQ(borders.size(), 3u);
  EXPECT_DOUBLE_EQ(borders.at(borderKey(1, 2)).count, 2.0);  // two rows, one pair each
  EXPECT_DOUBLE_EQ(borders.at(borderKey(1, 3)).count, 2.0);  // two columns
  EXPECT_DOUBLE_EQ(borders.at(borderKey(2, 3)).count, 2.0);
  EXPECT_EQ(borders.count(borderKey(2, 1)), 1u);  // the key does not depend on the order
}

TEST(SegmentBorders, IgnoresUnlabelledPixelsAndSegmentsThatDoNotTouch) {
  Frame frame({"11.22",  //
               "11.22"});
  EXPECT_TRUE(frame.collect().empty());
}

TEST(SegmentBorders, MeasuresTheStepAcrossTheBorderFromTheLowLabelToTheHighOne) {
  // Segment 2 (right) 1 cm behind segment 1 (left) at 2 m: both 3-D neighbours (Eq. 3).
  Frame frame({"1122",  //
               "1122"},
              [](int u, int) { return u < 2 ? 2.0 : 2.01; });
  const SegmentBorder& border = frame.collect().at(borderKey(1, 2));
  EXPECT_NEAR(border.meanStep().z(), 0.01, 1e-6);
  // Seen from the other side the step changes sign: a border collected as (2, 1) is the same.
  Frame swapped({"2211",  //
                 "2211"},
                [](int u, int) { return u < 2 ? 2.0 : 2.01; });
  EXPECT_NEAR(swapped.collect().at(borderKey(1, 2)).meanStep().z(), -0.01, 1e-6);
  // The mean point lies between the two sides.
  EXPECT_NEAR(border.meanPoint().z(), 2.005, 1e-6);
}

TEST(SegmentBorders, LeavesOutPixelPairsThatAreNotThreeDNeighbours) {
  // A 50 cm jump between the segments: an occluding edge, not a border.
  Frame frame({"1122",  //
               "1122"},
              [](int u, int) { return u < 2 ? 2.0 : 2.5; });
  EXPECT_TRUE(frame.collect().empty());
}

TEST(SegmentBorder, MergesBordersSeenFromEitherSide) {
  SegmentBorder ab, ba;
  ab.add({0.f, 0.f, 2.f}, {0.f, 0.f, 2.02f});  // low side first
  ba.add({1.f, 0.f, 2.02f}, {1.f, 0.f, 2.f});  // the same kind of pair, sides swapped
  SegmentBorder sum = ab;
  sum.merge(ba, /*flipped=*/true);
  EXPECT_DOUBLE_EQ(sum.count, 2.0);
  EXPECT_NEAR(sum.meanStep().z(), 0.02, 1e-6);
  EXPECT_NEAR(sum.meanPoint().x(), 0.5, 1e-6);
  SegmentBorder unflipped = ab;
  unflipped.merge(ba, /*flipped=*/false);
  EXPECT_NEAR(unflipped.meanStep().z(), 0.0, 1e-6);  // the steps cancel: the sides did not match
}

}  // namespace
}  // namespace floodplane
