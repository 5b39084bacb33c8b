// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The label image: each pixel's published label as a 32SC1 pixel, 0 for no plane.

#include "label_image.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using floodplane::conversion::kLabelImageBytesPerPixel;
using floodplane::conversion::kLabelImageEncoding;
using floodplane::conversion::writeLabelImage;

std::vector<std::int32_t> pixels(const std::vector<std::uint8_t>& bytes) {
  std::vector<std::int32_t> values(bytes.size() / 4);
  std::memcpy(values.data(), bytes.data(), bytes.size());
  return values;
}

TEST(LabelImage, IsSigned32BitOnePixelAPoint) {
  EXPECT_EQ(std::string(kLabelImageEncoding), "32SC1");
  EXPECT_EQ(kLabelImageBytesPerPixel, 4u);
}

TEST(LabelImage, WritesEachPixelsPublishedLabel) {
  // A 3 x 2 label image of two planes and pixels of none.
  const std::vector<std::uint32_t> labels = {1, 1, 0, 2, 0, 1};
  std::vector<std::uint8_t> bytes(labels.size() * kLabelImageBytesPerPixel, 0xAB);
  writeLabelImage(labels, {1, 2}, bytes.data());
  EXPECT_EQ(pixels(bytes), (std::vector<std::int32_t>{1, 1, 0, 2, 0, 1}));
  // Tracking: the planes' track ids, however large.
  writeLabelImage(labels, {70000, 3}, bytes.data());
  EXPECT_EQ(pixels(bytes), (std::vector<std::int32_t>{70000, 70000, 0, 3, 0, 70000}));
}

TEST(LabelImage, RefusesALabelWithoutAPlaneOrBeyondInt32) {
  std::vector<std::uint8_t> bytes(3 * kLabelImageBytesPerPixel);
  EXPECT_THROW(writeLabelImage({0, 2, 1}, {1}, bytes.data()), std::invalid_argument);
  EXPECT_THROW(writeLabelImage({0, 1, 1}, {0x80000000u}, bytes.data()), std::invalid_argument);
  writeLabelImage({0, 1, 1}, {0x7FFFFFFFu}, bytes.data());
  EXPECT_EQ(pixels(bytes).back(), 0x7FFFFFFF);
}

}  // namespace
