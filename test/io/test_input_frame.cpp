// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Reading input frames: what an organized PCD file gives, and a clear one-line error (never a
// crash, never a huge allocation) for every kind of bad file. These run under AddressSanitizer
// in CI, which would see PCL reading past a truncated file.

#include "floodplane/io/input_frame.h"

#include <gtest/gtest.h>
#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "floodplane/io/depth_png.h"
#include "support/files.h"
#include "support/one_line_error.h"
#include "temp_path.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;
using floodplane::io::loadInputFrame;

// A 6x4 grid of points on the plane z = 2 with one NaN pixel.
pcl::PointCloud<pcl::PointXYZ> smallGrid() {
  pcl::PointCloud<pcl::PointXYZ> cloud(6, 4);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    cloud[i].x = 0.1f * static_cast<float>(i % 6);
    cloud[i].y = 0.1f * static_cast<float>(i / 6);
    cloud[i].z = 2.0f;
  }
  cloud[7].x = cloud[7].y = cloud[7].z = std::numeric_limits<float>::quiet_NaN();
  cloud.is_dense = false;
  return cloud;
}

class InputFrame : public ::testing::Test {
 protected:
  void TearDown() override { fs::remove(path_); }

  // Loads `path_` expecting a std::runtime_error that contains `reason`.
  void expectRejected(const std::string& reason) const {
    expectOneLineError([&] { loadInputFrame(path_.string()); }, reason);
  }

  // A header of x y z floats announcing `width` x `height` points, then `data`.
  void writeHeader(const std::string& encoding, int width, int height, const std::string& data) const {
    writeFile(path_, "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH " + std::to_string(width) +
                         "\nHEIGHT " + std::to_string(height) + "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
                         std::to_string(width * height) + "\nDATA " + encoding + "\n" + data);
  }

  const fs::path path_ = uniqueTempPath(".pcd");
};

TEST_F(InputFrame, ReadsThePointsOnTheirGridWithTheSensorPose) {
  pcl::PointCloud<pcl::PointXYZ> cloud = smallGrid();
  cloud.sensor_origin_ = Eigen::Vector4f(0.5f, -1.0f, 2.0f, 0.0f);
  cloud.sensor_orientation_ = Eigen::Quaternionf(0.0f, 1.0f, 0.0f, 0.0f);
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(path_.string(), cloud), 0);
  const auto frame = loadInputFrame(path_.string());
  ASSERT_EQ(frame.xyz.width, 6u);
  ASSERT_EQ(frame.xyz.height, 4u);
  EXPECT_FALSE(frame.xyz.is_dense);
  EXPECT_TRUE(std::isnan(frame.xyz[7].z));
  EXPECT_EQ(frame.xyz[13].x, cloud[13].x);
  EXPECT_EQ(frame.xyz[13].y, cloud[13].y);
  EXPECT_EQ(frame.xyz[13].z, 2.0f);
  EXPECT_TRUE(frame.xyz.sensor_origin_.isApprox(cloud.sensor_origin_));
  EXPECT_TRUE(frame.xyz.sensor_orientation_.isApprox(cloud.sensor_orientation_));
  EXPECT_FALSE(frame.xyzrgb.has_value());
  EXPECT_FALSE(frame.labels.has_value());
}

TEST_F(InputFrame, ReadsTheColourOfAnRgbField) {
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  pcl::copyPointCloud(smallGrid(), cloud);
  for (std::size_t i = 0; i < cloud.size(); ++i) cloud[i].r = static_cast<std::uint8_t>(10 * i);
  ASSERT_EQ(pcl::io::savePCDFileBinary(path_.string(), cloud), 0);
  const auto frame = loadInputFrame(path_.string());
  ASSERT_TRUE(frame.xyzrgb.has_value());
  ASSERT_EQ(frame.xyzrgb->size(), cloud.size());
  EXPECT_EQ(frame.xyzrgb->width, 6u);
  for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_EQ((*frame.xyzrgb)[i].r, cloud[i].r) << i;
  EXPECT_EQ((*frame.xyzrgb)[13].x, cloud[13].x);
}

TEST_F(InputFrame, ReadsTheLabelFieldAsGroundTruth) {
  pcl::PointCloud<pcl::PointXYZL> cloud;
  pcl::copyPointCloud(smallGrid(), cloud);
  for (std::size_t i = 0; i < cloud.size(); ++i) cloud[i].label = static_cast<std::uint32_t>(i % 3 + 1000000 * (i % 2));
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(path_.string(), cloud), 0);
  const auto frame = loadInputFrame(path_.string());
  ASSERT_TRUE(frame.labels.has_value());
  ASSERT_EQ(frame.labels->size(), cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_EQ((*frame.labels)[i], cloud[i].label) << i;
  EXPECT_FALSE(frame.xyzrgb.has_value());
}

TEST_F(InputFrame, IgnoresALabelFieldThatIsNotAnUnsignedInteger) {
  std::string text =
      "VERSION 0.7\nFIELDS x y z label\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\nWIDTH 2\n"
      "HEIGHT 2\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA ascii\n";
  for (int i = 0; i < 4; ++i) text += "0 0 1 2.5\n";
  writeFile(path_, text);
  const auto frame = loadInputFrame(path_.string());
  EXPECT_EQ(frame.xyz.size(), 4u);
  EXPECT_FALSE(frame.labels.has_value());
}

TEST_F(InputFrame, ReadsDoublePrecisionCoordinates) {
  std::string text =
      "VERSION 0.7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\nHEIGHT 3\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 12\nDATA ascii\n";
  for (int i = 0; i < 12; ++i) text += std::to_string(0.25 * i) + " 0.5 1.5\n";
  writeFile(path_, text);
  const auto frame = loadInputFrame(path_.string());
  ASSERT_EQ(frame.xyz.size(), 12u);
  EXPECT_FLOAT_EQ(frame.xyz[5].x, 1.25f);
  EXPECT_FLOAT_EQ(frame.xyz[5].z, 1.5f);
  EXPECT_TRUE(frame.xyz.is_dense);
}

TEST_F(InputFrame, RejectsAMissingFile) { expectRejected("cannot read file"); }

TEST_F(InputFrame, RejectsAnEmptyFile) {
  writeFile(path_, "");
  expectRejected("empty file");
}

TEST_F(InputFrame, RejectsAFileThatIsNotAPcd) {
  writeFile(path_, "this is not a point cloud\n");
  expectRejected("not a PCD file");
}

TEST_F(InputFrame, RejectsATruncatedFileOfEveryEncoding) {
  for (const auto& [encoding, save] :
       {std::pair{"binary_compressed", &pcl::io::savePCDFileBinaryCompressed<pcl::PointXYZ>},
        std::pair{"binary", &pcl::io::savePCDFileBinary<pcl::PointXYZ>}}) {
    SCOPED_TRACE(encoding);
    ASSERT_EQ(save(path_.string(), smallGrid()), 0);
    const std::string full = readFile(path_);
    writeFile(path_, full.substr(0, full.size() * 2 / 3));
    expectRejected("truncated");
  }
  ASSERT_EQ(pcl::io::savePCDFileASCII(path_.string(), smallGrid()), 0);
  const std::string ascii = readFile(path_);
  writeFile(path_, ascii.substr(0, ascii.size() * 2 / 3));
  expectRejected("truncated");
}

TEST_F(InputFrame, RejectsCompressedDataThatUnpacksToTheWrongSize) {
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(path_.string(), smallGrid()), 0);
  std::string bytes = readFile(path_);
  const std::size_t data = bytes.find("DATA binary_compressed\n") + 23;
  ASSERT_LT(data + 8, bytes.size());
  bytes[data + 4] = static_cast<char>(bytes[data + 4] + 1);  // the uncompressed size
  writeFile(path_, bytes);
  expectRejected("corrupt");
}

TEST_F(InputFrame, RejectsAHeaderThatAnnouncesMorePointsThanTheFileHolds) {
  for (const char* encoding : {"ascii", "binary", "binary_compressed"}) {
    SCOPED_TRACE(encoding);
    writeHeader(encoding, 20000, 20000, std::string(1000, '\0'));
    expectRejected("cannot hold");
  }
}

TEST_F(InputFrame, RejectsACloudWithoutPoints) {
  writeHeader("binary", 5, 0, "");
  expectRejected("no points");
}

TEST_F(InputFrame, RejectsAnUnorganizedCloud) {
  pcl::PointCloud<pcl::PointXYZ> flat = smallGrid();
  flat.width = static_cast<std::uint32_t>(flat.size());
  flat.height = 1;
  ASSERT_EQ(pcl::io::savePCDFileBinary(path_.string(), flat), 0);
  expectRejected("needs an organized cloud");
}

TEST_F(InputFrame, RejectsACloudWithoutXyz) {
  pcl::PointCloud<pcl::Normal> normals(4, 3);
  ASSERT_EQ(pcl::io::savePCDFileBinary(path_.string(), normals), 0);
  expectRejected("no x y z");
}

// Found by fuzz_pcd_loader: PCL's header parser takes any line starting with "DATA" for the
// DATA line and reads its second word with at(), which throws std::out_of_range when the line
// is one word; the reader must turn that into its own error, as for every broken header.
TEST_F(InputFrame, RejectsADataLineOfOneWord) {
  const std::string header =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 2\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\n";
  const std::string points = "1 2 3\n1 2 3\n1 2 3\n1 2 3\n";
  for (const std::string& data_line : {std::string("DATAascii\n"), std::string("DATA\x8b\0\0compressed\n", 17)}) {
    SCOPED_TRACE(data_line);
    writeFile(path_, header + data_line + points);
    expectRejected("PCD");
  }
}

// Found by fuzz_pcd_loader: PCL reads COUNT with >> into an int, so an overflowing value
// became a count near 2^31 and PCL asked for 25 GB before reading the six points of this
// file; a large but valid COUNT in an ASCII file did the same (the size check counted one
// value per field).
TEST_F(InputFrame, RefusesCountsAndSizesThatOverflowOrThatTheFileCannotHold) {
  const std::string points = "1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n";
  const auto header = [](const std::string& count, const std::string& width, const std::string& points_line) {
    return "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT " + count + "\nWIDTH " + width +
           "\nHEIGHT 2\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + points_line + "\nDATA ascii\n";
  };
  const std::string overflow(120, '9');
  for (const std::string& text :
       {header(overflow + "1 1 1", "3", "6"), header("100000000 1 1", "3", "6"), header("-1 1 1", "3", "6"),
        header("1 1 1", overflow, "6"), header("1 1 1", "3", "-6"), header("1 1 1", "2147483647", "6")}) {
    SCOPED_TRACE(text);
    writeFile(path_, text + points);
    expectRejected("header");  // refused from the header, before PCL allocates
  }
}

// Found by fuzz_pcd_loader as heap corruption: PCL lets a later header line override an
// earlier one and reads the body with what is left. A SIZE line after TYPE put 4-byte floats
// into 1-byte slots; a second header after DATA (parsed as header too) resized the points
// after their buffer was allocated. PCL wrote past the buffer; now the header is refused.
TEST_F(InputFrame, RefusesHeadersWhoseFieldsDoNotFitTheirPoints) {
  const std::string fields = "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\n";
  const std::string grid = "WIDTH 2\nHEIGHT 2\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\n";
  const std::string values = "1 2 3 4\n1 2 3 4\n1 2 3 4\n1 2 3 4\n";
  for (const std::string& text :
       {fields + "SIZECOUNT 1 1 1 1\n" + grid + "DATA ascii\n" + values,
        fields + "COUNT 1 1 1 1\n" + grid + "SIZE 8 8 8 8\nDATA ascii\n" + values,
        fields + "COUNT 1 1 1 1\n" + grid + "DATA ascii\nSIZE 1 1 1 1\n" + values,
        fields + "COUNT 1 1 1 1\n" + grid + "COUNT 2 2 2 2\nDATA ascii\n" + values + values}) {
    SCOPED_TRACE(text);
    writeFile(path_, text);
    expectRejected("corrupt PCD header");
  }
}

// PCL goes on parsing header lines after DATA, and takes "POINTSx" for POINTS: a POINTS line
// there allocated its buffer (24 GB here) before anything was read.
TEST_F(InputFrame, RefusesABufferAnnouncedAfterTheDataLine) {
  const std::string header =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 2\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA ascii\n";
  const std::string points = "1 2 3\n1 2 3\n1 2 3\n1 2 3\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"POINTS 2000000000\n", "bytes of points"},
      {"POINTSX 2000000000\n", "bytes of points"},
      {"# comment\nPOINTS 2000000000\n", "bytes of points"},
      {"COUNTX 100000000 1 1\nPOINTS 4\n", "bytes of points"},
      {"COUNT -100 1 1\n", "is not a count"},
      // PCL's >> reads "0-465599" as 0 and then -465599, a count of 4 G (found by the fuzzer).
      {"COUNT 0-465599 1 1\n", "is not a count"}};
  for (const auto& [line, reason] : cases) {
    SCOPED_TRACE(line);
    writeFile(path_, header + line + points);
    expectRejected(reason);
  }
}

// PCL counts a line's values at spaces, tabs and carriage returns but reads them with >>,
// which also stops at a vertical tab; the fuzzer used the difference to make PCL allocate
// 12 GB behind the size check's back. Such lines are refused.
TEST_F(InputFrame, RefusesHeaderLinesWithControlCharacters) {
  const std::string rest =
      "TYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 2\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 6\nDATA ascii\n"
      "1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n";
  for (const std::string& size_line :
       {std::string("SIZE 4 4\v4\n"), std::string("SIZE 4 4 4\x02\n"), std::string("SIZE\x01 4 4 4\n", 13)}) {
    SCOPED_TRACE(size_line);
    writeFile(path_, "VERSION 0.7\nFIELDS x y z\n" + size_line + rest);
    expectRejected("control characters");
  }
  writeFile(path_, "VERSION 0.7\nFIELDS x y z\nSIZE 4 4\n" + rest);
  expectRejected("SIZE gives 2 values for 3 fields");
}

// A binary body is read as lines until one is no keyword; a first data byte of '#' makes PCL
// take the data up to the next newline for a comment. Such a file still loads.
TEST_F(InputFrame, ReadsABinaryBodyThatStartsLikeAComment) {
  pcl::PointCloud<pcl::PointXYZ> cloud = smallGrid();
  float x = 0.0f;
  const std::uint32_t bits = 0x3F800023;  // 1.0000042f: its first byte in the file is '#'
  std::memcpy(&x, &bits, sizeof(x));
  cloud[0].x = x;
  ASSERT_EQ(pcl::io::savePCDFileBinary(path_.string(), cloud), 0);
  const auto frame = loadInputFrame(path_.string());
  EXPECT_EQ(frame.xyz[0].x, x);
  EXPECT_EQ(frame.xyz[5].z, cloud[5].z);
}

// A binary body without a newline byte in the first 64 KiB: the "line" after DATA runs past the
// part of the file read for the header check, and is still known for data by its first word.
// (All points at (1, 1, 1): 0x3F800000 has no 0x0A byte.)
TEST_F(InputFrame, ReadsABinaryBodyWithoutANewlineInItsFirst64KiB) {
  pcl::PointCloud<pcl::PointXYZ> cloud(160, 120);
  for (pcl::PointXYZ& p : cloud) p.x = p.y = p.z = 1.0f;
  ASSERT_EQ(pcl::io::savePCDFileBinary(path_.string(), cloud), 0);
  ASSERT_GT(fs::file_size(path_), 65536u);
  const auto frame = loadInputFrame(path_.string());
  ASSERT_EQ(frame.xyz.size(), cloud.size());
  EXPECT_EQ(frame.xyz[19199].z, 1.0f);
}

// ... but a header line that goes on for 64 KiB is refused.
TEST_F(InputFrame, RefusesAHeaderLineLongerThan64KiB) {
  writeHeader("ascii", 1, 1, "1 2 3\n");
  const std::string text = readFile(path_);
  writeFile(path_, "# " + std::string(70000, 'x') + "\n" + text);
  expectRejected("more than 64 KiB of header lines");
}

// A vertical tab before a POINTS line after DATA: PCL's operator>> skips it and would allocate
// what that line announces, so it is a POINTS line here too, and refused for the control
// character.
TEST_F(InputFrame, TakesALineAfterDataThatStartsWithAVerticalTabAsPclDoes) {
  writeHeader("ascii", 1, 1, "\vPOINTS 4000000000\n1 2 3\n");
  expectRejected("control characters");
}

TEST_F(InputFrame, RejectsIntegerCoordinates) {
  std::string text =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE I I I\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 2\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA ascii\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n";
  writeFile(path_, text);
  expectRejected("not a single float or double");
}

// ---- depth images ----------------------------------------------------------------------

class DepthInputFrame : public ::testing::Test {
 protected:
  void TearDown() override { fs::remove(path_); }

  // A 4 x 3 depth image with one pixel without a return.
  void writeDepth() const {
    floodplane::io::DepthImage image;
    image.width = 4;
    image.height = 3;
    image.depth = {1000, 1100, 1200, 1300, 2000, 0, 2200, 2300, 3000, 3100, 3200, 65535};
    floodplane::io::writeDepthPng(path_.string(), image);
  }

  const floodplane::io::DepthCamera camera_{500.0, 400.0, 1.5, 1.0, 1000.0};
  fs::path path_ = uniqueTempPath(".png");
};

TEST_F(DepthInputFrame, BackProjectsADepthPngOnItsGrid) {
  writeDepth();
  const auto frame = loadInputFrame(path_.string(), camera_);
  ASSERT_EQ(frame.xyz.width, 4u);
  ASSERT_EQ(frame.xyz.height, 3u);
  EXPECT_FALSE(frame.xyz.is_dense);
  EXPECT_FALSE(frame.xyzrgb.has_value());
  EXPECT_FALSE(frame.labels.has_value());
  EXPECT_TRUE(frame.xyz.sensor_origin_.isZero());
  EXPECT_FLOAT_EQ(frame.xyz.at(0, 0).z, 1.0f);
  EXPECT_FLOAT_EQ(frame.xyz.at(0, 0).x, static_cast<float>(-1.5 * 1.0 / 500.0));
  EXPECT_FLOAT_EQ(frame.xyz.at(0, 0).y, static_cast<float>(-1.0 * 1.0 / 400.0));
  EXPECT_FLOAT_EQ(frame.xyz.at(3, 2).z, 65.535f);
  EXPECT_FLOAT_EQ(frame.xyz.at(3, 2).x, static_cast<float>(1.5 * 65.535 / 500.0));
  EXPECT_FLOAT_EQ(frame.xyz.at(3, 2).y, static_cast<float>(1.0 * 65.535 / 400.0));
  EXPECT_TRUE(std::isnan(frame.xyz.at(1, 1).x) && std::isnan(frame.xyz.at(1, 1).z)) << "zero depth: no return";
}

TEST_F(DepthInputFrame, DividesTheUnitsByTheDepthScale) {
  writeDepth();
  floodplane::io::DepthCamera tum = camera_;
  tum.depth_scale = 5000.0;
  EXPECT_FLOAT_EQ(loadInputFrame(path_.string(), tum).xyz.at(2, 1).z, 2200.0f / 5000.0f);
}

TEST_F(DepthInputFrame, TellsAPngByItsExtensionInAnyCase) {
  EXPECT_TRUE(floodplane::io::isDepthImagePath("a/b/frame.png"));
  EXPECT_TRUE(floodplane::io::isDepthImagePath("FRAME.PNG"));
  EXPECT_FALSE(floodplane::io::isDepthImagePath("frame.pcd"));
  EXPECT_FALSE(floodplane::io::isDepthImagePath("png"));
  EXPECT_FALSE(floodplane::io::isDepthImagePath("frame.png.pcd"));
  fs::remove(path_);
  path_ = uniqueTempPath(".PNG");
  writeDepth();
  EXPECT_EQ(loadInputFrame(path_.string(), camera_).xyz.width, 4u);
}

TEST_F(DepthInputFrame, NeedsTheIntrinsics) {
  writeDepth();
  try {
    loadInputFrame(path_.string());
    ADD_FAILURE() << "a depth image without intrinsics was read";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("intrinsics"), std::string::npos) << error.what();
  }
}

TEST_F(DepthInputFrame, RefusesIntrinsicsItCannotUse) {
  writeDepth();
  floodplane::io::DepthCamera bad = camera_;
  bad.fy = 0.0;
  EXPECT_THROW(loadInputFrame(path_.string(), bad), std::invalid_argument);
}

TEST_F(DepthInputFrame, RefusesADepthImageOfOneRow) {
  floodplane::io::DepthImage image;
  image.width = 5;
  image.height = 1;
  image.depth.assign(5, 1000);
  floodplane::io::writeDepthPng(path_.string(), image);
  EXPECT_THROW(loadInputFrame(path_.string(), camera_), std::runtime_error);
}

TEST_F(DepthInputFrame, ReportsABrokenPngAsOneLine) {
  writeFile(path_, "\x89PNG\r\n\x1a\n but then nothing");
  try {
    loadInputFrame(path_.string(), camera_);
    ADD_FAILURE() << "a broken PNG was read";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("PNG"), std::string::npos) << error.what();
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
  }
}

// The checks only reject: on real sensor frames the reader gives what PCL's own loader gives.
TEST(InputFrameOfRealData, AgreesWithPclsLoaderOnEveryRealFrame) {
  const fs::path folder(FLOODPLANE_REAL_DATA_DIR);
  if (!fs::is_directory(folder)) GTEST_SKIP() << "no real data at " << FLOODPLANE_REAL_DATA_DIR;
  std::size_t frames = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".pcd") continue;
    SCOPED_TRACE(entry.path().string());
    ++frames;
    pcl::PointCloud<pcl::PointXYZRGBA> expected;
    ASSERT_EQ(pcl::io::loadPCDFile(entry.path().string(), expected), 0);
    const auto frame = loadInputFrame(entry.path().string());
    ASSERT_EQ(frame.xyz.width, expected.width);
    ASSERT_EQ(frame.xyz.height, expected.height);
    ASSERT_TRUE(frame.xyzrgb.has_value()) << "the real frames have colour";
    EXPECT_TRUE(frame.xyz.sensor_orientation_.isApprox(expected.sensor_orientation_));
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const auto& p = expected[i];
      if (!std::isfinite(p.z)) {
        ASSERT_FALSE(std::isfinite(frame.xyz[i].z)) << i;
        continue;
      }
      ASSERT_EQ(frame.xyz[i].x, p.x) << i;
      ASSERT_EQ(frame.xyz[i].y, p.y) << i;
      ASSERT_EQ(frame.xyz[i].z, p.z) << i;
      ASSERT_EQ((*frame.xyzrgb)[i].rgba, p.rgba) << i;
    }
  }
  EXPECT_GT(frames, 0u) << "the folder holds no .pcd file";
}

}  // namespace
}  // namespace floodplane::test
