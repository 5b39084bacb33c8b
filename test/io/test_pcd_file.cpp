// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/pcd_file.h"
#include "temp_path.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

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

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The ASCII encoding made in memory is what PCL's writeASCII writes with 9 digits, byte for
// byte: floats, NaN, labels, a float rgb field as the integer of its bits, an rgba field.
template <typename PointT>
void expectAsciiAsPcl(pcl::PointCloud<PointT> cloud) {
  cloud.sensor_orientation_ = Eigen::Quaternionf(0.5F, -0.5F, 0.5F, -0.5F);
  const fs::path path = floodplane::test::uniqueTempPath(".pcd");
  ASSERT_EQ(pcl::PCDWriter().writeASCII(path.string(), cloud, 9), 0);
  const std::string written = fileBytes(path);
  fs::remove(path);
  EXPECT_EQ(floodplane::io::encodePcd(cloud, floodplane::io::PcdEncoding::ascii), written);
}

TEST(PcdFileEncoding, AsciiIsWhatPclsAsciiWriterWrites) {
  expectAsciiAsPcl(smallOrganizedCloud());
  pcl::PointCloud<pcl::PointXYZRGB> rgb(2, 2);
  pcl::PointCloud<pcl::PointXYZRGBA> rgba(2, 2);
  pcl::PointCloud<pcl::PointNormal> normals(2, 2);
  for (std::size_t i = 0; i < 4; ++i) {
    const float f = 0.1F * static_cast<float>(i) - 1.0F / 3.0F;
    rgb[i].x = rgba[i].x = normals[i].x = f;
    rgb[i].y = rgba[i].y = normals[i].y = -2.0F * f;
    rgb[i].z = rgba[i].z = normals[i].z = 1e-7F + f;
    rgb[i].rgba = rgba[i].rgba = 0xFF000000u | (0x123456u * static_cast<std::uint32_t>(i + 1));
    normals[i].normal_x = normals[i].curvature = f;
  }
  rgb[3].x = rgba[3].y = normals[3].normal_z = std::numeric_limits<float>::quiet_NaN();
  expectAsciiAsPcl(rgb);
  expectAsciiAsPcl(rgba);
  expectAsciiAsPcl(normals);
}

// The binary_compressed encoding made from whole buffers: the header PCL's
// writeBinaryCompressed writes, and what PCL's reader reads back from it the same cloud, point
// for point and bit for bit (NaN included), pose and grid kept.
template <typename PointT>
void expectBinaryCompressedAsPcl(pcl::PointCloud<PointT> cloud) {
  cloud.sensor_origin_ = Eigen::Vector4f(0.5F, -1.0F, 2.0F, 0.0F);
  cloud.sensor_orientation_ = Eigen::Quaternionf(0.5F, -0.5F, 0.5F, -0.5F);
  const fs::path pcl_path = floodplane::test::uniqueTempPath(".pcd");
  ASSERT_EQ(pcl::PCDWriter().writeBinaryCompressed(pcl_path.string(), cloud), 0);
  const std::string by_pcl = fileBytes(pcl_path);
  fs::remove(pcl_path);
  const std::string ours = floodplane::io::encodePcd(cloud, floodplane::io::PcdEncoding::binary_compressed);
  const std::string data_line = "DATA binary_compressed\n";
  ASSERT_NE(by_pcl.find(data_line), std::string::npos);
  const std::size_t header = by_pcl.find(data_line) + data_line.size();
  EXPECT_EQ(ours.substr(0, header), by_pcl.substr(0, header));
  EXPECT_EQ(ours.substr(header + 4, 4), by_pcl.substr(header + 4, 4)) << "the uncompressed size";
  const fs::path path = floodplane::test::uniqueTempPath(".pcd");
  std::ofstream(path, std::ios::binary) << ours;
  pcl::PointCloud<PointT> read;
  ASSERT_EQ(pcl::io::loadPCDFile(path.string(), read), 0);
  fs::remove(path);
  ASSERT_EQ(read.width, cloud.width);
  ASSERT_EQ(read.height, cloud.height);
  EXPECT_EQ(read.is_dense, cloud.is_dense);
  EXPECT_EQ(read.sensor_origin_, cloud.sensor_origin_);
  EXPECT_EQ(read.sensor_orientation_.coeffs(), cloud.sensor_orientation_.coeffs());
  std::vector<pcl::PCLPointField> fields;
  pcl::getFields<PointT>(fields);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    for (const pcl::PCLPointField& field : fields) {
      if (field.name == "_") continue;
      const std::size_t bytes = field.count * pcl::getFieldSize(field.datatype);
      EXPECT_EQ(std::memcmp(reinterpret_cast<const char*>(&read[i]) + field.offset,
                            reinterpret_cast<const char*>(&cloud[i]) + field.offset, bytes),
                0)
          << "point " << i << ", field " << field.name;
    }
  }
}

TEST(PcdFileEncoding, BinaryCompressedIsWhatPclsReaderReadsAsWritten) {
  expectBinaryCompressedAsPcl(smallOrganizedCloud());
  // A frame's size, with a frame's structure (planes of labels, holes), and colours.
  pcl::PointCloud<pcl::PointXYZRGBL> frame(640, 480);
  for (std::uint32_t v = 0; v < frame.height; ++v) {
    for (std::uint32_t u = 0; u < frame.width; ++u) {
      auto& p = frame.at(u, v);
      p.z = 1.0F + 0.001F * static_cast<float>(v);
      p.x = (static_cast<float>(u) - 320.0F) * p.z / 525.0F;
      p.y = (static_cast<float>(v) - 240.0F) * p.z / 525.0F;
      p.rgba = 0xFF000000u | (u * 2654435761u % 0xFFFFFFu);
      p.label = u < 300 ? 1 : (v < 200 ? 2 : 0);
      if ((u * 7 + v * 3) % 97 == 0) p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN();
    }
  }
  frame.is_dense = false;
  expectBinaryCompressedAsPcl(frame);
  pcl::PointCloud<pcl::PointNormal> normals(5, 1);
  for (std::size_t i = 0; i < normals.size(); ++i)
    normals[i].x = normals[i].normal_y = normals[i].curvature = 0.5F * static_cast<float>(i);
  expectBinaryCompressedAsPcl(normals);
}

// A write that fails part-way (here the file size limit, as a full disk would) is reported with
// the system's reason for the ASCII encoding too, and leaves no file: PCL's own ASCII writer
// did not check its writes.
TEST(PcdFileEncoding, AsciiWriteThatFailsIsReportedAndLeavesNoFile) {
  pcl::PointCloud<pcl::PointXYZL> cloud(100, 100);
  const fs::path path = floodplane::test::uniqueTempPath(".pcd");
  struct rlimit before {};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &before), 0);
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = before;
  small.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    floodplane::io::savePcd(path.string(), cloud, floodplane::io::PcdEncoding::ascii);
  } catch (const std::runtime_error& error) {
    message = error.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &before);
  std::signal(SIGXFSZ, previous);
  EXPECT_EQ(message, "cannot write '" + path.string() + "': File too large");
  EXPECT_FALSE(fs::exists(path));
  const std::string temporary = "." + path.filename().string() + ".tmp.";
  for (const auto& entry : fs::directory_iterator(path.parent_path())) {
    EXPECT_NE(entry.path().filename().string().rfind(temporary, 0), 0u) << "a temporary left: " << entry.path();
  }
}

TEST(PcdFileEncoding, ReportsAnUnwritableDirectoryAsARuntimeError) {
  EXPECT_THROW(floodplane::io::savePcd("/nonexistent_directory/x.pcd", smallOrganizedCloud()), std::runtime_error);
}

}  // namespace
