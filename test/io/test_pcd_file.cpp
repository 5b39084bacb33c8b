// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "io/pcd_file.h"
#include "temp_path.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace floodplane::io {
namespace {

std::string encodingName(PcdEncoding encoding) {
  switch (encoding) {
    case PcdEncoding::binary_compressed:
      return "BinaryCompressed";
    case PcdEncoding::binary:
      return "Binary";
    case PcdEncoding::ascii:
      return "Ascii";
  }
  return "Unknown";
}

}  // namespace

// Lets GoogleTest print the parameter by name instead of as raw bytes.
void PrintTo(PcdEncoding encoding, std::ostream* out) { *out << encodingName(encoding); }

}  // namespace floodplane::io

namespace {

namespace fs = std::filesystem;
using floodplane::io::encodingName;

pcl::PointCloud<pcl::PointXYZL> smallOrganizedCloud() {
  pcl::PointCloud<pcl::PointXYZL> cloud(3, 2);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    auto& point = cloud[i];
    point.x = 0.1F * static_cast<float>(i);
    point.y = -0.25F * static_cast<float>(i);
    point.z = 1.0F + 0.5F * static_cast<float>(i);
    point.label = static_cast<std::uint32_t>(i % 3);
  }
  cloud[4].x = cloud[4].y = cloud[4].z = std::numeric_limits<float>::quiet_NaN();
  cloud[4].label = 0;
  cloud.is_dense = false;
  return cloud;
}

std::string firstLines(const fs::path& path, int count) {
  std::ifstream in(path);
  std::string text;
  std::string line;
  for (int i = 0; i < count && std::getline(in, line); ++i) {
    text += line + "\n";
  }
  return text;
}

class PcdFile : public ::testing::TestWithParam<floodplane::io::PcdEncoding> {};

TEST_P(PcdFile, RoundTripsAnOrganizedCloudWithNaNs) {
  const auto cloud = smallOrganizedCloud();
  const fs::path path = floodplane::test::uniqueTempPath(".pcd");
  floodplane::io::savePcd(path.string(), cloud, GetParam());
  pcl::PointCloud<pcl::PointXYZL> read;
  ASSERT_EQ(pcl::io::loadPCDFile(path.string(), read), 0);
  fs::remove(path);
  ASSERT_EQ(read.width, 3U);
  ASSERT_EQ(read.height, 2U);
  EXPECT_FALSE(read.is_dense);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (std::isnan(cloud[i].z)) {
      EXPECT_TRUE(std::isnan(read[i].z));
    } else {
      EXPECT_EQ(read[i].x, cloud[i].x);
      EXPECT_EQ(read[i].y, cloud[i].y);
      EXPECT_EQ(read[i].z, cloud[i].z);
    }
    EXPECT_EQ(read[i].label, cloud[i].label);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryEncoding, PcdFile,
                         ::testing::Values(floodplane::io::PcdEncoding::binary_compressed,
                                           floodplane::io::PcdEncoding::binary, floodplane::io::PcdEncoding::ascii),
                         [](const auto& param_info) { return encodingName(param_info.param); });

TEST(PcdFileEncoding, IsBinaryCompressedByDefault) {
  const fs::path path = floodplane::test::uniqueTempPath(".pcd");
  floodplane::io::savePcd(path.string(), smallOrganizedCloud());
  const std::string header = firstLines(path, 11);
  fs::remove(path);
  EXPECT_NE(header.find("DATA binary_compressed"), std::string::npos) << header;
}

TEST(PcdFileEncoding, ReportsAnUnwritableDirectoryAsARuntimeError) {
  EXPECT_THROW(floodplane::io::savePcd("/nonexistent_directory/x.pcd", smallOrganizedCloud()), std::runtime_error);
}

}  // namespace
