// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/label_palette.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

TEST(LabelPalette, DrawsNoPlaneNearBlackAndHolesWhite) {
  const auto no_plane = floodplane::io::labelColor(0);
  EXPECT_EQ(no_plane, floodplane::io::kNoPlaneColor);
  EXPECT_LE(*std::max_element(no_plane.begin(), no_plane.end()), 40);
  EXPECT_EQ(floodplane::io::kHoleColor, (std::array<std::uint8_t, 3>{255, 255, 255}));
}

// A label image tells a plane, "no plane" and a hole apart: no plane's colour comes near
// either of the other two.
TEST(LabelPalette, KeepsEveryPlaneColourFarFromNoPlaneAndFromHoles) {
  for (std::uint32_t label = 1; label <= 1000; ++label) {
    const auto color = floodplane::io::labelColor(label);
    EXPECT_LE(*std::min_element(color.begin(), color.end()), 102) << "label " << label << " is not near white";
    EXPECT_GE(*std::max_element(color.begin(), color.end()), 200) << "label " << label << " is not near black";
  }
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

TEST(LabelPalette, ColorsAGridPixelByPixelInRowMajorOrderWithHolesWhite) {
  const std::vector<std::uint32_t> labels{0, 1, 2, 3, 4, 5};
  const std::vector<std::uint8_t> has_point{1, 1, 0, 1, 0, 1};
  const auto image = floodplane::io::labelImage(labels, has_point, 3, 2);
  ASSERT_EQ(image.width, 3U);
  ASSERT_EQ(image.height, 2U);
  ASSERT_EQ(image.pixels.size(), 18U);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto expected = has_point[i] != 0 ? floodplane::io::labelColor(labels[i]) : floodplane::io::kHoleColor;
    EXPECT_EQ(image.pixels[i * 3 + 0], expected[0]) << i;
    EXPECT_EQ(image.pixels[i * 3 + 1], expected[1]) << i;
    EXPECT_EQ(image.pixels[i * 3 + 2], expected[2]) << i;
  }
}

TEST(LabelPalette, RejectsAGridWhoseSizeDoesNotMatch) {
  EXPECT_THROW(floodplane::io::labelImage(std::vector<std::uint32_t>(5), std::vector<std::uint8_t>(6, 1), 3, 2),
               std::invalid_argument);
  EXPECT_THROW(floodplane::io::labelImage(std::vector<std::uint32_t>(6), std::vector<std::uint8_t>(5, 1), 3, 2),
               std::invalid_argument);
}

// Planes half their colour, half the frame's; no plane the frame's own; holes white.
TEST(OverlayImage, BlendsPlaneColoursHalfOverTheFrameAndPaintsHolesWhite) {
  floodplane::io::RgbImage frame;
  frame.width = 2;
  frame.height = 2;
  frame.pixels = {10, 20, 30, 200, 100, 0, 7, 8, 9, 255, 255, 255};
  const std::vector<std::uint32_t> labels{3, 0, 5, 1};
  const std::vector<std::uint8_t> has_point{1, 1, 0, 1};
  const auto image = floodplane::io::overlayImage(labels, has_point, frame);
  ASSERT_EQ(image.width, 2U);
  ASSERT_EQ(image.height, 2U);
  ASSERT_EQ(image.pixels.size(), 12U);
  for (const std::size_t i : {std::size_t{0}, std::size_t{3}}) {
    const auto color = floodplane::io::labelColor(labels[i]);
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(image.pixels[i * 3 + c], (frame.pixels[i * 3 + c] + color[c] + 1) / 2) << i << " " << c;
    }
  }
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(image.pixels[1 * 3 + c], frame.pixels[1 * 3 + c]);
    EXPECT_EQ(image.pixels[2 * 3 + c], floodplane::io::kHoleColor[c]);
  }
  EXPECT_THROW(floodplane::io::overlayImage(std::vector<std::uint32_t>(3), has_point, frame), std::invalid_argument);
  frame.pixels.pop_back();
  EXPECT_THROW(floodplane::io::overlayImage(labels, has_point, frame), std::invalid_argument);
}

}  // namespace
