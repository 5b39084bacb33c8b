// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The candidate planes' numbering: renumbering by size, regrouping, dropping, and the deferred
// renumbering that region output reads the labels through after refinement.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "stages/plane_candidates.h"

namespace floodplane {
namespace {

// Candidates with the given inlier counts (numbers 1..n in this order).
PlaneCandidates withCounts(const std::vector<double>& counts) {
  PlaneCandidates planes;
  for (const double count : counts) {
    PlaneCandidate candidate;
    candidate.sums.count = count;
    planes.list().push_back(candidate);
  }
  return planes;
}

// A label image whose runs cross row ends and where planes alternate.
std::vector<std::uint32_t> image() {
  return {1, 1, 2, 2, 2, 0, 3, 3, 4, 4, 1, 1, 0, 0, 2, 3, 3, 3, 4, 1, 1, 1, 0, 2, 2, 4, 4, 4, 3, 3};
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

// Reading the image through the deferred renumbering, and rewriting it once at the end, must
// give what renumbering the image after each step gives.
TEST(PlaneCandidates, DeferredRenumberingEqualsRenumberingAfterEachStep) {
  PlaneCandidates now = withCounts({10, 30, 20, 5}), later = withCounts({10, 30, 20, 5});
  std::vector<std::uint32_t> renumbered = image(), deferred = image();

  ASSERT_TRUE(now.sortBySize(0, nullptr));
  now.renumberImage(renumbered);
  ASSERT_TRUE(later.sortBySize(0, nullptr));
  later.deferRenumbering(true);
  for (std::size_t i = 0; i < renumbered.size(); ++i) ASSERT_EQ(later.labels(deferred)[i], renumbered[i]) << i;

  // Planes 1 and 3 (image numbers 2 and 1) become one; then plane 2 (image number 3) is
  // dropped.
  const std::vector<std::uint32_t> group = {0, 1, 2, 1, 4};
  ASSERT_TRUE(now.regroup(group));
  now.renumberImage(renumbered);
  ASSERT_TRUE(later.regroup(group));
  later.composeRenumbering();
  for (std::size_t i = 0; i < renumbered.size(); ++i) ASSERT_EQ(later.labels(deferred)[i], renumbered[i]) << i;

  const std::vector<bool> drop = {false, false, true, false};
  ASSERT_TRUE(now.drop(drop));
  now.renumberImage(renumbered);
  ASSERT_TRUE(later.drop(drop));
  later.composeRenumbering();
  for (std::size_t i = 0; i < renumbered.size(); ++i) ASSERT_EQ(later.labels(deferred)[i], renumbered[i]) << i;

  later.applyRenumbering(deferred);
  EXPECT_EQ(deferred, renumbered);
  ASSERT_EQ(later.list().size(), now.list().size());
  for (std::uint32_t k = 1; k <= now.list().size(); ++k) EXPECT_EQ(later[k].sums.count, now[k].sums.count);
}

TEST(PlaneCandidates, NothingPendingLeavesTheImageAsItIs) {
  PlaneCandidates planes = withCounts({30, 20, 10, 5});
  ASSERT_FALSE(planes.sortBySize(0, nullptr));
  planes.deferRenumbering(false);
  std::vector<std::uint32_t> labels = image();
  for (std::size_t i = 0; i < labels.size(); ++i) EXPECT_EQ(planes.labels(labels)[i], labels[i]);
  planes.applyRenumbering(labels);
  EXPECT_EQ(labels, image());
}

}  // namespace
}  // namespace floodplane
