// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The candidate planes' numbering and their label image: renumbering by size, regrouping,
// dropping, each recorded once against the image, whichever way it is read or written after.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "models/plane_candidates.h"

namespace floodplane {
namespace {

constexpr int kWidth = 6, kHeight = 5;

// A label image whose runs cross row ends and where planes alternate.
std::vector<std::uint32_t> image() {
  return {1, 1, 2, 2, 2, 0,  //
          3, 3, 4, 4, 1, 1,  //
          0, 0, 2, 3, 3, 3,  //
          4, 1, 1, 1, 0, 2,  //
          2, 4, 4, 4, 3, 3};
}

// image() with every label k replaced by number[k], by hand.
std::vector<std::uint32_t> withNumbers(const std::vector<std::uint32_t>& number) {
  std::vector<std::uint32_t> labels = image();
  for (std::uint32_t& label : labels) label = number[label];
  return labels;
}

// Candidates with the given inlier counts (numbers 1..n in this order), and image() as their
// labels. Plane k's first pixel is that of label k in image().
PlaneCandidates withCounts(const std::vector<double>& counts) {
  PlaneCandidates planes;
  for (const double count : counts) {
    PlaneCandidate candidate;
    candidate.sums.count = count;
    planes.list().push_back(candidate);
  }
  const std::vector<std::uint32_t> labels = image();
  std::copy(labels.begin(), labels.end(), planes.newImage(kWidth, kHeight));
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (labels[i] != 0 && planes[labels[i]].first_pixel == kNoPixel) planes[labels[i]].first_pixel = i;
  return planes;
}

// The labels as read through the planes.
std::vector<std::uint32_t> readLabels(const PlaneCandidates& planes) {
  std::vector<std::uint32_t> labels;
  for (std::size_t i = 0; i < image().size(); ++i) labels.push_back(planes.labels()[i]);
  return labels;
}

TEST(PlaneCandidates, SortBySizeNumbersTheLargestFirst) {
  PlaneCandidates planes = withCounts({10, 30, 20, 5});
  EXPECT_TRUE(planes.sortBySize(0, nullptr));
  EXPECT_EQ(planes.remap(1), 3u);
  EXPECT_EQ(planes.remap(2), 1u);
  EXPECT_EQ(planes.remap(3), 2u);
  EXPECT_EQ(planes.remap(4), 4u);
  EXPECT_FALSE(planes.sortBySize(0, nullptr));  // already in order
  EXPECT_TRUE(planes.sortBySize(8, nullptr));   // the smallest goes
  EXPECT_EQ(planes.list().size(), 3u);
  EXPECT_EQ(planes.remap(4), 0u);
}

// Sort, merge, drop: after each, the labels read through the planes are image() in the numbers
// worked out by hand, each step applied once (no step lost, none applied twice: no step here is its own inverse),
// and so is the image asked for writable at the end, and what is read after that.
TEST(PlaneCandidates, EveryRenumberingIsRecordedOnceAgainstTheImage) {
  PlaneCandidates planes = withCounts({10, 30, 20, 5});
  ASSERT_TRUE(planes.sortBySize(0, nullptr));
  // Image 1 -> 3, 2 -> 1, 3 -> 2, 4 -> 4.
  EXPECT_EQ(readLabels(planes), withNumbers({0, 3, 1, 2, 4}));

  // Planes 1 and 3 (images 2 and 1) merge into the largest, 40; plane 2 (image 3) follows.
  ASSERT_TRUE(planes.regroup({0, 1, 2, 1, 4}));
  EXPECT_EQ(readLabels(planes), withNumbers({0, 1, 1, 2, 3}));
  EXPECT_EQ(planes[1].sums.count, 40.0);
  // The merged plane's first pixel is the first of its pieces'.
  EXPECT_EQ(planes[1].first_pixel, 0u);
  EXPECT_EQ(planes[2].first_pixel, 6u);
  EXPECT_EQ(planes[3].first_pixel, 8u);

  // Plane 2 (image 3) is dropped; plane 3 (image 4) becomes 2.
  ASSERT_TRUE(planes.drop({false, false, true, false}));
  const std::vector<std::uint32_t> expected = withNumbers({0, 1, 1, 0, 2});
  EXPECT_EQ(readLabels(planes), expected);
  EXPECT_EQ(planes[2].first_pixel, 8u);

  const std::uint32_t* written = planes.writableImage();
  EXPECT_EQ(std::vector<std::uint32_t>(written, written + expected.size()), expected);
  EXPECT_EQ(readLabels(planes), expected);
  planes.writableImage();  // nothing changed since: the image stays
  std::vector<std::uint32_t> out;
  planes.releaseImage(out);
  EXPECT_EQ(out, expected);
}

// A renumbering after the image was written, and one before it was, both count.
TEST(PlaneCandidates, RenumberingsBeforeAndAfterAWriteCombine) {
  PlaneCandidates planes = withCounts({10, 30, 20, 5});
  ASSERT_TRUE(planes.sortBySize(0, nullptr));
  planes.writableImage();
  ASSERT_TRUE(planes.drop({false, true, false, false, false}));  // image 2, plane 1 now
  const std::vector<std::uint32_t> expected = withNumbers({0, 2, 0, 1, 3});
  EXPECT_EQ(readLabels(planes), expected);
  std::vector<std::uint32_t> out;
  planes.releaseImage(out);
  EXPECT_EQ(out, expected);
}

// Row by row, the rows around the one visited are in the current numbers, and so is the whole
// image afterwards; a label written in the current numbers stays as written.
TEST(PlaneCandidates, WritableRowsAreInTheCurrentNumbers) {
  PlaneCandidates planes = withCounts({10, 30, 20, 5});
  ASSERT_TRUE(planes.sortBySize(0, nullptr));
  std::vector<std::uint32_t> expected = withNumbers({0, 3, 1, 2, 4});
  int rows = 0;
  planes.forEachWritableRow([&](std::uint32_t* labels, int y) {
    const std::size_t first = static_cast<std::size_t>(std::max(0, y - 1) * kWidth);
    const std::size_t last = static_cast<std::size_t>(std::min(kHeight, y + 2) * kWidth);
    for (std::size_t i = first; i < last; ++i) ASSERT_EQ(labels[i], expected[i]) << "row " << y << ", pixel " << i;
    if (y == 2) labels[12] = expected[12] = 4;  // an unlabelled pixel joins plane 4
    ++rows;
  });
  EXPECT_EQ(rows, kHeight);
  EXPECT_EQ(readLabels(planes), expected);
  std::vector<std::uint32_t> out;
  planes.releaseImage(out);
  EXPECT_EQ(out, expected);
}

TEST(PlaneCandidates, NothingRenumberedLeavesTheImageAsItIs) {
  PlaneCandidates planes = withCounts({30, 20, 10, 5});
  ASSERT_FALSE(planes.sortBySize(0, nullptr));
  EXPECT_EQ(readLabels(planes), image());
  std::vector<std::uint32_t> out;
  planes.releaseImage(out);
  EXPECT_EQ(out, image());
}

}  // namespace
}  // namespace floodplane
