// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Reading PointCloud2 layouts: in place where the library can read them, copied where not,
// and every malformed message rejected with its reason instead of read out of bounds.

#include "cloud_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using floodplane::conversion::CloudView;
using floodplane::conversion::FieldType;
using floodplane::conversion::hasFinitePoint;
using floodplane::conversion::PointField;
using floodplane::conversion::readCloudPoints;

constexpr auto kFloat32 = static_cast<std::uint8_t>(FieldType::float32);
constexpr auto kFloat64 = static_cast<std::uint8_t>(FieldType::float64);

// A cloud message's bytes: width x height points of point_step bytes, x y z of point i at
// the given offsets, (i, 10 i, -i) written as `datatype`, rows row_step apart.
struct Message {
  std::vector<std::uint8_t> data;
  CloudView view;
};

Message message(std::uint32_t width, std::uint32_t height, std::uint32_t point_step, std::vector<PointField> fields,
                std::uint32_t row_padding = 0) {
  Message m;
  m.view.width = width;
  m.view.height = height;
  m.view.point_step = point_step;
  m.view.row_step = width * point_step + row_padding;
  m.view.fields = std::move(fields);
  m.data.assign(static_cast<std::size_t>(m.view.row_step) * height, 0xAB);
  for (std::uint32_t row = 0; row < height; ++row) {
    for (std::uint32_t column = 0; column < width; ++column) {
      const double i = row * width + column;
      const double values[3] = {i, 10.0 * i, -i};
      std::uint8_t* point = m.data.data() + row * m.view.row_step + column * point_step;
      for (const PointField& field : m.view.fields) {
        const int axis = field.name == "x" ? 0 : field.name == "y" ? 1 : field.name == "z" ? 2 : -1;
        const std::uint32_t size = field.datatype == kFloat64 ? 8 : 4;
        if (axis < 0 || field.offset + size > point_step) continue;  // a malformed layout's field
        if (field.datatype == kFloat64) {
          std::memcpy(point + field.offset, &values[axis], 8);
        } else {
          const auto value = static_cast<float>(values[axis]);
          std::memcpy(point + field.offset, &value, 4);
        }
      }
    }
  }
  m.view.data = m.data.data();
  m.view.data_size = m.data.size();
  return m;
}

// PCL's PointXYZRGB as pcl_conversions publishes it: x y z, padding, rgb at 16, 32 bytes.
std::vector<PointField> pclXyzRgb() {
  return {{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}, {"z", 8, kFloat32, 1}, {"rgb", 16, kFloat32, 1}};
}

void expectPoints(const floodplane::PointGrid& grid, std::uint32_t width, std::uint32_t height) {
  ASSERT_EQ(grid.width, static_cast<int>(width));
  ASSERT_EQ(grid.height, static_cast<int>(height));
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const float* p = grid.point(i);
    const auto value = static_cast<double>(i);
    ASSERT_EQ(p[0], static_cast<float>(value)) << "point " << i;
    ASSERT_EQ(p[1], static_cast<float>(10.0 * value)) << "point " << i;
    ASSERT_EQ(p[2], static_cast<float>(-value)) << "point " << i;
  }
}

std::string problemOf(const CloudView& view) {
  try {
    readCloudPoints(view);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(CloudPoints, ReadsPclsPointLayoutInPlace) {
  const Message m = message(4, 3, 32, pclXyzRgb());
  const auto points = readCloudPoints(m.view);
  EXPECT_FALSE(points.copied());
  EXPECT_EQ(reinterpret_cast<const std::uint8_t*>(points.grid().data), m.data.data());
  EXPECT_EQ(points.grid().stride, 8u);
  expectPoints(points.grid(), 4, 3);
}

TEST(CloudPoints, CopiesFloat64Coordinates) {
  const Message m = message(3, 2, 24, {{"x", 0, kFloat64, 1}, {"y", 8, kFloat64, 1}, {"z", 16, kFloat64, 1}});
  const auto points = readCloudPoints(m.view);
  EXPECT_TRUE(points.copied());
  expectPoints(points.grid(), 3, 2);
}

TEST(CloudPoints, CopiesCoordinatesInAnotherOrder) {
  const Message m = message(3, 2, 16, {{"z", 0, kFloat32, 1}, {"x", 4, kFloat32, 1}, {"y", 12, kFloat32, 1}});
  const auto points = readCloudPoints(m.view);
  EXPECT_TRUE(points.copied());
  expectPoints(points.grid(), 3, 2);
}

TEST(CloudPoints, CopiesRowsWithPaddingBetweenThem) {
  const Message m = message(3, 4, 16, {{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}, {"z", 8, kFloat32, 1}}, 8);
  const auto points = readCloudPoints(m.view);
  EXPECT_TRUE(points.copied());
  expectPoints(points.grid(), 3, 4);
}

TEST(CloudPoints, CopiesDataThatIsNotOnFourByteBoundaries) {
  Message m = message(3, 2, 12, {{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}, {"z", 8, kFloat32, 1}});
  std::vector<std::uint8_t> shifted(m.data.size() + 1);
  std::memcpy(shifted.data() + 1, m.data.data(), m.data.size());
  m.view.data = shifted.data() + 1;
  const auto points = readCloudPoints(m.view);
  EXPECT_TRUE(points.copied());
  expectPoints(points.grid(), 3, 2);
}

TEST(CloudPoints, RejectsAnUnorganizedCloud) {
  const Message m = message(12, 1, 32, pclXyzRgb());
  EXPECT_NE(problemOf(m.view).find("not organized"), std::string::npos) << problemOf(m.view);
}

TEST(CloudPoints, ReadsACloudWithoutPointsAsAnEmptyGrid) {
  // No point at all is a frame without points, not an error, also in PCL's unorganized form
  // (height 1); the data need not be there.
  for (const auto& [width, height] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, 0}, {0, 1}, {4, 0}}) {
    Message m = message(width, height, 32, pclXyzRgb());
    m.view.data = nullptr;
    m.view.data_size = 0;
    const auto points = readCloudPoints(m.view);
    EXPECT_EQ(points.grid().width, static_cast<int>(width));
    EXPECT_EQ(points.grid().height, static_cast<int>(height));
    EXPECT_EQ(points.grid().size(), 0u);
    EXPECT_FALSE(hasFinitePoint(points.grid()));
  }
  // Its layout must still be one the points could be read from.
  const Message m = message(0, 0, 16, {{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}});
  EXPECT_EQ(problemOf(m.view), "the cloud has no z field");
}

TEST(CloudPoints, RejectsACloudWithoutZ) {
  const Message m = message(3, 2, 16, {{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}, {"intensity", 8, kFloat32, 1}});
  EXPECT_EQ(problemOf(m.view), "the cloud has no z field");
}

TEST(CloudPoints, RejectsIntegerCoordinates) {
  const Message m = message(
      3, 2, 16,
      {{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}, {"z", 8, static_cast<std::uint8_t>(FieldType::uint16), 1}});
  EXPECT_NE(problemOf(m.view).find("field z has datatype 4"), std::string::npos) << problemOf(m.view);
}

TEST(CloudPoints, RejectsAFieldReachingBeyondItsPoint) {
  const Message m = message(3, 2, 12, {{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}, {"z", 10, kFloat32, 1}});
  EXPECT_NE(problemOf(m.view).find("does not fit in point_step 12"), std::string::npos) << problemOf(m.view);
}

TEST(CloudPoints, RejectsDataShorterThanItsRows) {
  Message m = message(4, 3, 32, pclXyzRgb());
  m.view.data_size -= 1;
  EXPECT_NE(problemOf(m.view).find("row_step x height is 384 bytes"), std::string::npos) << problemOf(m.view);
  m.view.data = nullptr;
  EXPECT_NE(problemOf(m.view).find("holds 0 bytes"), std::string::npos) << problemOf(m.view);
}

TEST(CloudPoints, RejectsARowStepShorterThanItsPoints) {
  Message m = message(4, 3, 32, pclXyzRgb());
  m.view.row_step = 100;
  EXPECT_NE(problemOf(m.view).find("row_step 100 is less than"), std::string::npos) << problemOf(m.view);
}

TEST(CloudPoints, RejectsAZeroPointStep) {
  Message m = message(4, 3, 32, pclXyzRgb());
  m.view.point_step = 0;
  EXPECT_EQ(problemOf(m.view), "the cloud's point_step is 0");
}

TEST(CloudPoints, RejectsBigEndianData) {
  Message m = message(4, 3, 32, pclXyzRgb());
  m.view.is_bigendian = true;
  EXPECT_NE(problemOf(m.view).find("big-endian"), std::string::npos) << problemOf(m.view);
}

TEST(CloudPoints, RejectsSizesWhoseProductsOverflow32Bits) {
  // width x point_step is 2^36: a 32-bit product would wrap to 0 and pass every check.
  Message m = message(4, 3, 32, pclXyzRgb());
  m.view.width = 1u << 31;
  m.view.point_step = 32;
  m.view.row_step = 0;
  EXPECT_NE(problemOf(m.view).find("is less than width x point_step (68719476736 bytes)"), std::string::npos)
      << problemOf(m.view);
  m.view.width = 1;
  m.view.row_step = 1u << 31;
  m.view.height = 1u << 31;
  EXPECT_NE(problemOf(m.view).find("row_step x height is 4611686018427387904 bytes"), std::string::npos)
      << problemOf(m.view);
}

TEST(CloudPoints, FindsAFinitePointOnlyWhereThereIsOne) {
  std::vector<float> xyz(3 * 6, std::numeric_limits<float>::quiet_NaN());
  floodplane::PointGrid grid;
  grid.data = xyz.data();
  grid.width = 3;
  grid.height = 2;
  EXPECT_FALSE(hasFinitePoint(grid));
  xyz[3 * 5 + 0] = xyz[3 * 5 + 1] = 1.0f;  // z still NaN
  EXPECT_FALSE(hasFinitePoint(grid));
  xyz[3 * 5 + 2] = 1.0f;
  EXPECT_TRUE(hasFinitePoint(grid));
}

}  // namespace
