// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Reading label files other programs wrote: grey PNGs of 8 or 16 bits, label by label
// exactly, and label PCDs as pcd_segment writes them; one clear line for everything else.

#include "floodplane/io/label_file.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <png.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "floodplane/io/depth_png.h"
#include "support/files.h"
#include "support/one_line_error.h"
#include "support/png_images.h"
#include "temp_path.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;
using floodplane::io::readLabelFile;

class LabelFile : public ::testing::Test {
 protected:
  void TearDown() override { fs::remove(path_); }
  void use(const std::string& extension) { path_ = uniqueTempPath(extension); }
  void expectRejected(const std::string& reason) const {
    expectOneLineError([&] { readLabelFile(path_.string()); }, reason);
  }
  fs::path path_ = uniqueTempPath(".png");
};

TEST_F(LabelFile, ReadsEveryLabelOfA16BitGreyPngExactly) {
  io::DepthImage image;
  image.width = 4;
  image.height = 2;
  image.depth = {0, 1, 2, 300, 65535, 7, 0, 4660};
  io::writeDepthPng(path_.string(), image);
  const io::LabelGrid grid = readLabelFile(path_.string());
  EXPECT_EQ(grid.width, 4u);
  EXPECT_EQ(grid.height, 2u);
  EXPECT_EQ(grid.labels, (std::vector<std::uint32_t>{0, 1, 2, 300, 65535, 7, 0, 4660}));
}

TEST_F(LabelFile, ReadsEveryLabelOfAnEightBitGreyPngExactly) {
  use(".PNG");
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = 3;
  png.height = 2;
  png.format = PNG_FORMAT_GRAY;
  const std::vector<std::uint8_t> pixels{0, 1, 2, 255, 17, 0};
  ASSERT_NE(png_image_write_to_file(&png, path_.c_str(), 0, pixels.data(), 0, nullptr), 0) << png.message;
  const io::LabelGrid grid = readLabelFile(path_.string());
  EXPECT_EQ(grid.width, 3u);
  EXPECT_EQ(grid.height, 2u);
  EXPECT_EQ(grid.labels, (std::vector<std::uint32_t>{0, 1, 2, 255, 17, 0}));
}

TEST_F(LabelFile, ReadsTheLabelFieldOfALabelPcd) {
  use(".labels.pcd");
  pcl::PointCloud<pcl::PointXYZL> cloud(3, 2);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    cloud[i].x = static_cast<float>(i);
    cloud[i].z = 1.0f;
    cloud[i].label = static_cast<std::uint32_t>(i * 1000);
  }
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(path_.string(), cloud), 0);
  const io::LabelGrid grid = readLabelFile(path_.string());
  EXPECT_EQ(grid.width, 3u);
  EXPECT_EQ(grid.height, 2u);
  EXPECT_EQ(grid.labels, (std::vector<std::uint32_t>{0, 1000, 2000, 3000, 4000, 5000}));
}

TEST_F(LabelFile, RejectsAPcdWithoutALabelField) {
  use(".pcd");
  pcl::PointCloud<pcl::PointXYZ> cloud(3, 2);
  ASSERT_EQ(pcl::io::savePCDFileBinary(path_.string(), cloud), 0);
  expectRejected("the cloud has no label field");
}

TEST_F(LabelFile, RejectsAColourOrAlphaOrBrokenPngAndAMissingFile) {
  writeOtherPng(path_, PNG_FORMAT_RGB);
  expectRejected("not a label image: a colour PNG");
  writeOtherPng(path_, PNG_FORMAT_GA);
  expectRejected("not a label image: a PNG with an alpha channel");
  writeOtherPng(path_, PNG_FORMAT_RGB_COLORMAP);
  expectRejected("not a label image: a palette (colour) PNG");
  writeFile(path_, "not a png");
  expectRejected("not a PNG file");
  fs::remove(path_);
  expectRejected("cannot read file");
}

}  // namespace
}  // namespace floodplane::test
