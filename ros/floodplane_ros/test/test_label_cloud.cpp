// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The label cloud: its fields, and each point's coordinates, published label and colour.

#include "label_cloud.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "floodplane/io/label_palette.h"

namespace {

using floodplane::conversion::FieldType;
using floodplane::conversion::kLabelCloudPointStep;
using floodplane::conversion::labelCloudFields;
using floodplane::conversion::packedLabelColor;
using floodplane::conversion::writeLabelCloud;

template <typename T>
T read(const std::vector<std::uint8_t>& bytes, std::size_t point, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + point * kLabelCloudPointStep + offset, sizeof value);
  return value;
}

TEST(LabelCloud, HasXyzRgbAndLabelFieldsWithinItsPointStep) {
  const auto fields = labelCloudFields();
  ASSERT_EQ(fields.size(), 5u);
  const char* names[] = {"x", "y", "z", "rgb", "label"};
  for (std::size_t i = 0; i < fields.size(); ++i) {
    EXPECT_EQ(fields[i].name, names[i]);
    EXPECT_EQ(fields[i].offset, 4 * i);
    EXPECT_EQ(fields[i].count, 1u);
    EXPECT_EQ(fields[i].datatype, static_cast<std::uint8_t>(i == 4 ? FieldType::uint32 : FieldType::float32));
  }
  EXPECT_EQ(kLabelCloudPointStep, fields.back().offset + 4);
}

TEST(LabelCloud, PacksTheLabelPalettesColourAsPclDoes) {
  for (std::uint32_t label : {0u, 1u, 2u, 17u, 1000u}) {
    const auto rgb = floodplane::io::labelColor(label);
    const float packed = packedLabelColor(label);
    std::uint32_t bits;
    std::memcpy(&bits, &packed, sizeof bits);
    EXPECT_EQ(bits, (std::uint32_t{rgb[0]} << 16) | (std::uint32_t{rgb[1]} << 8) | rgb[2]) << label;
  }
}

TEST(LabelCloud, WritesEachPointWithItsPlanesPublishedLabelAndColour) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // A 3 x 2 grid with stride 4 (PCL's PointXYZ), one point without a return.
  const std::vector<float> points = {0, 1, 2, 9, 3, 4, 5, 9, nan, nan, nan, 9, 6, 7, 8, 9, 9, 10, 11, 9, 12, 13, 14, 9};
  floodplane::PointGrid grid;
  grid.data = points.data();
  grid.stride = 4;
  grid.width = 3;
  grid.height = 2;
  const std::vector<std::uint32_t> labels = {1, 2, 0, 1, 0, 2};
  const std::vector<std::uint32_t> plane_labels = {7, 3};  // track ids
  std::vector<std::uint8_t> cloud(grid.size() * kLabelCloudPointStep);
  writeLabelCloud(grid, labels, plane_labels, cloud.data());

  const std::uint32_t expected_labels[] = {7, 3, 0, 7, 0, 3};
  for (std::size_t i = 0; i < grid.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      const float expected = points[4 * i + static_cast<std::size_t>(axis)];
      const float written = read<float>(cloud, i, 4 * static_cast<std::size_t>(axis));
      if (std::isnan(expected)) {
        EXPECT_TRUE(std::isnan(written)) << i;
      } else {
        EXPECT_EQ(written, expected) << i;
      }
    }
    EXPECT_EQ(read<std::uint32_t>(cloud, i, 16), expected_labels[i]) << i;
    const float color = read<float>(cloud, i, 12);
    const float expected_color = packedLabelColor(expected_labels[i]);
    EXPECT_EQ(std::memcmp(&color, &expected_color, sizeof color), 0) << i;
  }
}

TEST(LabelCloud, RejectsLabelsThatDoNotFitTheGridOrItsPlanes) {
  const std::vector<float> points(3 * 4, 1.0f);
  floodplane::PointGrid grid;
  grid.data = points.data();
  grid.width = 2;
  grid.height = 2;
  std::vector<std::uint8_t> cloud(grid.size() * kLabelCloudPointStep);
  EXPECT_THROW(writeLabelCloud(grid, {0, 1, 1}, {1}, cloud.data()), std::invalid_argument);
  EXPECT_THROW(writeLabelCloud(grid, {0, 1, 2, 1}, {1}, cloud.data()), std::invalid_argument);
}

}  // namespace
