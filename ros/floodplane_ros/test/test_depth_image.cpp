// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Depth images by depth_image_proc's convention: millimetres or metres, no return as NaN, the
// pinhole model of CameraInfo's K through floodplane_io's back-projection, and every
// malformed image or camera rejected with its reason.

#include "depth_image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "floodplane/io/depth_camera.h"

namespace {

using floodplane::conversion::backProjectDepthImage;
using floodplane::conversion::CameraInfoView;
using floodplane::conversion::depthUnitsPerMetre;
using floodplane::conversion::ImageView;

CameraInfoView kinectInfo(std::uint32_t width, std::uint32_t height) {
  CameraInfoView info;
  info.width = width;
  info.height = height;
  info.k = {525.0, 0.0, 319.5, 0.0, 520.0, 239.5, 0.0, 0.0, 1.0};
  return info;
}

template <typename Depth>
ImageView image(const std::vector<Depth>& depths, std::uint32_t width, std::uint32_t height, const char* encoding) {
  ImageView view;
  view.width = width;
  view.height = height;
  view.encoding = encoding;
  view.step = static_cast<std::uint32_t>(width * sizeof(Depth));
  view.data = reinterpret_cast<const std::uint8_t*>(depths.data());
  view.data_size = depths.size() * sizeof(Depth);
  return view;
}

std::string problemOf(const ImageView& view, const CameraInfoView& info) {
  std::vector<float> xyz;
  try {
    backProjectDepthImage(view, info, xyz);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(accepted)";
}

bool isHole(const std::vector<float>& xyz, std::size_t pixel) {
  return std::isnan(xyz[3 * pixel]) && std::isnan(xyz[3 * pixel + 1]) && std::isnan(xyz[3 * pixel + 2]);
}

TEST(DepthImage, BackProjectsMillimetresAsPcdSegmentDoes) {
  const std::uint32_t width = 8, height = 5;
  std::vector<std::uint16_t> depths(width * height);
  for (std::size_t i = 0; i < depths.size(); ++i) depths[i] = static_cast<std::uint16_t>(i % 7 == 3 ? 0 : 900 + 37 * i);
  std::vector<float> xyz;
  backProjectDepthImage(image(depths, width, height, "16UC1"), kinectInfo(width, height), xyz);

  floodplane::io::DepthCamera camera{525.0, 520.0, 319.5, 239.5, 1000.0};
  std::vector<float> expected(3 * depths.size());
  floodplane::io::backProjectDepth(depths.data(), static_cast<int>(width), static_cast<int>(height), camera,
                                   expected.data());
  ASSERT_EQ(xyz.size(), expected.size());
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    if (std::isnan(expected[i])) {
      EXPECT_TRUE(std::isnan(xyz[i])) << i;
    } else {
      EXPECT_EQ(xyz[i], expected[i]) << i;
    }
  }
  EXPECT_TRUE(isHole(xyz, 3));
  EXPECT_FLOAT_EQ(xyz[3 * 1 + 2], 0.937f);
}

TEST(DepthImage, ReadsMono16AsMillimetres) {
  const std::vector<std::uint16_t> depths = {1000, 2000, 0, 1500};
  std::vector<float> a, b;
  backProjectDepthImage(image(depths, 2, 2, "16UC1"), kinectInfo(2, 2), a);
  backProjectDepthImage(image(depths, 2, 2, "mono16"), kinectInfo(2, 2), b);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), 3 * 2 * sizeof(float)), 0);
  EXPECT_EQ(b[3 * 3 + 2], 1.5f);
}

TEST(DepthImage, BackProjectsMetresThroughThePinholeModel) {
  const std::vector<float> depths = {1.5f, 2.25f, 3.0f, 0.75f};
  std::vector<float> xyz;
  CameraInfoView info = kinectInfo(2, 2);
  info.k[2] = 0.5;  // cx: between the two columns
  info.k[5] = 0.0;  // cy: on the first row
  backProjectDepthImage(image(depths, 2, 2, "32FC1"), info, xyz);
  EXPECT_FLOAT_EQ(xyz[0], static_cast<float>(-0.5 * 1.5 / 525.0));
  EXPECT_FLOAT_EQ(xyz[1], 0.0f);
  EXPECT_FLOAT_EQ(xyz[2], 1.5f);
  EXPECT_FLOAT_EQ(xyz[3 * 3 + 0], static_cast<float>(0.5 * 0.75 / 525.0));
  EXPECT_FLOAT_EQ(xyz[3 * 3 + 1], static_cast<float>(1.0 * 0.75 / 520.0));
  EXPECT_FLOAT_EQ(xyz[3 * 3 + 2], 0.75f);
}

TEST(DepthImage, TurnsZeroNanInfiniteAndNegativeDepthIntoNoReturn) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> depths = {0.0f, nan, inf, -1.0f, 2.0f, 0.0f};
  std::vector<float> xyz;
  backProjectDepthImage(image(depths, 3, 2, "32FC1"), kinectInfo(3, 2), xyz);
  for (std::size_t pixel : {0u, 1u, 2u, 3u, 5u}) EXPECT_TRUE(isHole(xyz, pixel)) << pixel;
  EXPECT_EQ(xyz[3 * 4 + 2], 2.0f);
}

TEST(DepthImage, ReadsPaddedRowsAtAnyAlignment) {
  // Rows of 3 pixels in 8 bytes, the image starting at an odd address.
  std::vector<std::uint8_t> bytes(1 + 8 * 2, 0xFF);
  const std::uint16_t depths[6] = {1000, 1100, 1200, 1300, 1400, 1500};
  for (int row = 0; row < 2; ++row) std::memcpy(bytes.data() + 1 + 8 * row, depths + 3 * row, 6);
  ImageView view;
  view.width = 3;
  view.height = 2;
  view.encoding = "16UC1";
  view.step = 8;
  view.data = bytes.data() + 1;
  view.data_size = bytes.size() - 1;
  std::vector<float> xyz;
  backProjectDepthImage(view, kinectInfo(3, 2), xyz);
  for (std::size_t pixel = 0; pixel < 6; ++pixel) EXPECT_FLOAT_EQ(xyz[3 * pixel + 2], depths[pixel] / 1000.0f);
}

TEST(DepthImage, TakesACameraInfoThatGivesNoSize) {
  const std::vector<std::uint16_t> depths = {1000, 2000, 0, 1500};
  EXPECT_EQ(problemOf(image(depths, 2, 2, "16UC1"), kinectInfo(0, 0)), "(accepted)");
}

TEST(DepthImage, RejectsAnEncodingThatIsNotDepth) {
  const std::vector<std::uint8_t> rgb(2 * 2 * 3, 100);
  ImageView view = image(rgb, 2, 2, "rgb8");
  view.step = 6;
  EXPECT_EQ(problemOf(view, kinectInfo(2, 2)),
            "depth image encoding 'rgb8': floodplane reads 16UC1 or mono16 (millimetres) and 32FC1 (metres)");
  EXPECT_THROW(depthUnitsPerMetre("8UC1"), std::invalid_argument);
  EXPECT_EQ(depthUnitsPerMetre("32FC1"), 1.0);
}

TEST(DepthImage, RejectsAnUncalibratedCamera) {
  const std::vector<std::uint16_t> depths = {1000, 2000, 0, 1500};
  CameraInfoView info;  // K all zero, as an uncalibrated driver sends it
  EXPECT_NE(problemOf(image(depths, 2, 2, "16UC1"), info).find("camera_info K: fx must be"), std::string::npos)
      << problemOf(image(depths, 2, 2, "16UC1"), info);
  info = kinectInfo(2, 2);
  info.k[5] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(problemOf(image(depths, 2, 2, "16UC1"), info).find("cy"), std::string::npos);
}

TEST(DepthImage, RejectsACameraInfoOfAnotherSize) {
  const std::vector<std::uint16_t> depths = {1000, 2000, 0, 1500};
  EXPECT_EQ(problemOf(image(depths, 2, 2, "16UC1"), kinectInfo(640, 480)),
            "camera_info is 640x480, the depth image 2x2");
}

TEST(DepthImage, BackProjectsAnImageWithoutPixelsToNoPoints) {
  std::vector<float> xyz(3, 1.0f);
  const std::vector<std::uint16_t> none;
  for (const auto& [width, height] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, 0}, {0, 480}, {640, 0}}) {
    ImageView view = image(none, width, height, "16UC1");
    view.data = nullptr;
    backProjectDepthImage(view, kinectInfo(width, height), xyz);
    EXPECT_TRUE(xyz.empty());
  }
  // Its encoding and camera must still be ones a depth image could be read with.
  EXPECT_NE(problemOf(image(none, 0, 0, "mono8"), kinectInfo(0, 0)).find("encoding 'mono8'"), std::string::npos);
  CameraInfoView uncalibrated = kinectInfo(0, 0);
  uncalibrated.k = {};
  EXPECT_NE(problemOf(image(none, 0, 0, "16UC1"), uncalibrated).find("camera_info K"), std::string::npos);
}

TEST(DepthImage, RejectsImagesWhoseDataDoesNotHoldTheirRows) {
  const std::vector<std::uint16_t> depths = {1000, 2000, 0, 1500};
  ImageView view = image(depths, 2, 2, "16UC1");
  view.data_size = 7;
  EXPECT_EQ(problemOf(view, kinectInfo(2, 2)), "the depth image's data holds 7 bytes, its rows 8");
  view = image(depths, 2, 2, "32FC1");  // 4 bytes a pixel: 16 needed, 8 there
  EXPECT_EQ(problemOf(view, kinectInfo(2, 2)), "the depth image's step 4 is less than its 8 bytes a row");
  view = image(depths, 2, 2, "16UC1");
  view.is_bigendian = true;
  EXPECT_NE(problemOf(view, kinectInfo(2, 2)).find("big-endian"), std::string::npos);
}

}  // namespace
