// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "io/label_palette.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace {

double colorDistance(std::uint32_t a, std::uint32_t b) {
  const auto ca = floodplane::io::labelColor(a);
  const auto cb = floodplane::io::labelColor(b);
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double diff = static_cast<double>(ca[c]) - static_cast<double>(cb[c]);
    sum += diff * diff;
  }
  return std::sqrt(sum);
}

double minimumDistanceAmongFirst(std::uint32_t count) {
  double minimum = 1e9;
  for (std::uint32_t a = 1; a <= count; ++a) {
    for (std::uint32_t b = a + 1; b <= count; ++b) {
      minimum = std::min(minimum, colorDistance(a, b));
    }
  }
  return minimum;
}

TEST(LabelPalette, DrawsLabelZeroNearBlack) {
  const auto color = floodplane::io::labelColor(0);
  EXPECT_LE(*std::max_element(color.begin(), color.end()), 40);
}

TEST(LabelPalette, DrawsEveryPlaneLabelBright) {
  for (std::uint32_t label = 1; label <= 1000; ++label) {
    const auto color = floodplane::io::labelColor(label);
    EXPECT_GE(*std::max_element(color.begin(), color.end()), 200) << "label " << label;
  }
}

TEST(LabelPalette, KeepsTheFirstThirtyTwoLabelsClearlyDistinct) { EXPECT_GE(minimumDistanceAmongFirst(32), 40.0); }

TEST(LabelPalette, KeepsTheFirstHundredTwentyEightLabelsDistinguishable) {
  EXPECT_GE(minimumDistanceAmongFirst(128), 20.0);
}

TEST(LabelPalette, GivesConsecutiveLabelsVeryDifferentColors) {
  for (std::uint32_t label = 1; label < 1000; ++label) {
    EXPECT_GE(colorDistance(label, label + 1), 100.0) << "labels " << label << ", " << label + 1;
  }
}

TEST(LabelPalette, ColorsAGridPixelByPixelInRowMajorOrder) {
  const std::vector<std::uint32_t> labels{0, 1, 2, 3, 4, 5};
  const auto image = floodplane::io::labelImage(labels, 3, 2);
  ASSERT_EQ(image.width, 3U);
  ASSERT_EQ(image.height, 2U);
  ASSERT_EQ(image.pixels.size(), 18U);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto expected = floodplane::io::labelColor(labels[i]);
    EXPECT_EQ(image.pixels[i * 3 + 0], expected[0]);
    EXPECT_EQ(image.pixels[i * 3 + 1], expected[1]);
    EXPECT_EQ(image.pixels[i * 3 + 2], expected[2]);
  }
}

TEST(LabelPalette, RejectsAGridWhoseSizeDoesNotMatch) {
  EXPECT_THROW(floodplane::io::labelImage(std::vector<std::uint32_t>(5), 3, 2), std::invalid_argument);
}

}  // namespace
