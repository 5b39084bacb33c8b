// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Eq. 4: the per-pixel owner and plane distance, and the rule that a flood takes a pixel only
// when its plane fits the pixel better than the current owner's.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "util/distance_buffer.h"

namespace floodplane {
namespace {

TEST(DistanceBuffer, StartsWithEveryPixelUnlabeled) {
  DistanceBuffer buffer;
  buffer.reset(6);
  ASSERT_EQ(buffer.labels().size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(buffer.label(i), 0) << "pixel " << i;
}

TEST(DistanceBuffer, AnUnlabeledPixelFitsAnyDistanceAsIfItWereInfinite) {
  DistanceBuffer buffer;
  buffer.reset(4);
  EXPECT_TRUE(buffer.fitsBetter(2, 0.f));
  EXPECT_TRUE(buffer.fitsBetter(2, 1e30f));
  EXPECT_TRUE(buffer.fitsBetter(2, 1e30f, /*margin=*/1e30f));
}

TEST(DistanceBuffer, ClaimRecordsLabelAndDistanceAndReturnsThePreviousOwner) {
  DistanceBuffer buffer;
  buffer.reset(4);
  EXPECT_EQ(buffer.claim(1, 7, 0.004f), 0);  // nobody owned it
  EXPECT_EQ(buffer.label(1), 7);
  EXPECT_FLOAT_EQ(buffer.distance(1), 0.004f);
  EXPECT_EQ(buffer.claim(1, 9, 0.001f), 7);  // taken from segment 7
  EXPECT_EQ(buffer.label(1), 9);
  EXPECT_FLOAT_EQ(buffer.distance(1), 0.001f);
  // Neighbouring pixels are untouched.
  EXPECT_EQ(buffer.label(0), 0);
  EXPECT_EQ(buffer.label(2), 0);
}

TEST(DistanceBuffer, AnOwnedPixelGoesOnlyToAStrictlyCloserPlane) {
  DistanceBuffer buffer;
  buffer.reset(3);
  buffer.claim(0, 1, 0.005f);
  EXPECT_TRUE(buffer.fitsBetter(0, 0.004f));
  EXPECT_FALSE(buffer.fitsBetter(0, 0.005f));  // a tie keeps the owner
  EXPECT_FALSE(buffer.fitsBetter(0, 0.006f));
}

TEST(DistanceBuffer, MarginDemandsTheNewPlaneBeCloserByMoreThanIt) {
  DistanceBuffer buffer;
  buffer.reset(3);
  buffer.claim(0, 1, 0.005f);
  EXPECT_TRUE(buffer.fitsBetter(0, 0.004f));                      // closer by 1 mm, no margin
  EXPECT_FALSE(buffer.fitsBetter(0, 0.004f, /*margin=*/0.002f));  // but not by 2 mm
  EXPECT_TRUE(buffer.fitsBetter(0, 0.002f, /*margin=*/0.002f));   // closer by 3 mm
}

TEST(DistanceBuffer, ResetClearsLabelsAndResizes) {
  DistanceBuffer buffer;
  buffer.reset(4);
  buffer.claim(0, 3, 0.001f);
  buffer.claim(3, 4, 0.001f);
  buffer.reset(8);
  ASSERT_EQ(buffer.labels().size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(buffer.label(i), 0) << "pixel " << i;
  // The stale distance of a cleared pixel is never read: it fits any new flood.
  EXPECT_TRUE(buffer.fitsBetter(0, 0.5f));
  buffer.reset(2);
  EXPECT_EQ(buffer.labels().size(), 2u);
}

TEST(DistanceBuffer, HandsAPixelToALaterFloodThatFitsItBetter) {
  // Two floods over a row of five pixels. Flood 1 claims all of them; flood 2's plane fits
  // pixels 3 and 4 better and takes them, but not the others.
  DistanceBuffer buffer;
  buffer.reset(5);
  const std::vector<float> flood1 = {0.001f, 0.001f, 0.002f, 0.008f, 0.009f};
  const std::vector<float> flood2 = {0.009f, 0.006f, 0.004f, 0.001f, 0.000f};
  for (std::size_t i = 0; i < 5; ++i)
    if (buffer.fitsBetter(i, flood1[i])) buffer.claim(i, 1, flood1[i]);
  std::vector<std::int32_t> taken_from;
  for (std::size_t i = 0; i < 5; ++i)
    if (buffer.fitsBetter(i, flood2[i])) taken_from.push_back(buffer.claim(i, 2, flood2[i]));
  EXPECT_EQ(buffer.labels(), (std::vector<std::int32_t>{1, 1, 1, 2, 2}));
  EXPECT_EQ(taken_from, (std::vector<std::int32_t>{1, 1}));
  EXPECT_FLOAT_EQ(buffer.distance(3), 0.001f);
  EXPECT_FLOAT_EQ(buffer.distance(2), 0.002f);  // kept by flood 1 at its own distance
}

}  // namespace
}  // namespace floodplane
