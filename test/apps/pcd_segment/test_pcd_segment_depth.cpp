// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_segment on 16-bit depth PNG images: the back-projected points and the library's labels
// in the output, --intrinsics and --depth-scale, directories of depth images, and one clear
// error for an 8-bit or colour PNG, a broken file and missing or bad intrinsics.

#include <gtest/gtest.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "floodplane/io/depth_camera.h"
#include "floodplane/io/depth_png.h"
#include "pcd_segment_test.h"
#include "support/app_run.h"
#include "support/library_labels.h"
#include "support/png_images.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;

// The camera of the scene: a Kinect's f = 525 at 160 x 120.
const floodplane::io::DepthCamera kCamera{131.25, 131.25, 79.5, 59.5, 5000.0};
const std::string kIntrinsics = "131.25,131.25,79.5,59.5";

// A wall at 2 m and a floor 0.5 m below the camera, seen as a TUM-style depth image (units of
// 0.2 mm), with a block of pixels without a return.
floodplane::io::DepthImage twoPlaneDepth() {
  floodplane::io::DepthImage image;
  image.width = 160;
  image.height = 120;
  for (int v = 0; v < image.height; ++v) {
    for (int u = 0; u < image.width; ++u) {
      const double ry = (v - kCamera.cy) / kCamera.fy;
      const double z = ry > 0.0 ? std::min(2.0, 0.5 / ry) : 2.0;
      const bool hole = v >= 10 && v < 14 && u >= 20 && u < 24;
      image.depth.push_back(hole ? 0 : static_cast<std::uint16_t>(std::lround(z * kCamera.depth_scale)));
    }
  }
  return image;
}

// The points pcd_segment should segment: the same back-projection.
pcl::PointCloud<pcl::PointXYZ> backProjected(const floodplane::io::DepthImage& image) {
  pcl::PointCloud<pcl::PointXYZ> cloud(static_cast<std::uint32_t>(image.width),
                                       static_cast<std::uint32_t>(image.height));
  for (int v = 0; v < image.height; ++v) {
    for (int u = 0; u < image.width; ++u) {
      const std::size_t i = static_cast<std::size_t>(v * image.width + u);
      floodplane::io::backProjectPixel(u, v, image.depth[i], kCamera, cloud[i].data);
    }
  }
  cloud.is_dense = false;
  return cloud;
}

class PcdSegmentDepth : public PcdSegmentTest {
 protected:
  std::string writeDepth(const std::string& name) const {
    floodplane::io::writeDepthPng(path(name).string(), twoPlaneDepth());
    return path(name).string();
  }

  // One error line naming the input, exit code 1, nothing written.
  void expectRejected(const std::string& input, const std::string& reason) const {
    const Result result = run({input, "-o", path("out").string(), "--intrinsics", kIntrinsics});
    EXPECT_EQ(result.exit_code, 1) << result.err;
    EXPECT_EQ(lineCount(result.err), 1u) << result.err;
    EXPECT_TRUE(contains(result.err, input)) << result.err;
    EXPECT_TRUE(contains(result.err, reason)) << "expected '" << reason << "' in: " << result.err;
    EXPECT_TRUE(fs::is_empty(path("out")));
  }
};

TEST_F(PcdSegmentDepth, WritesTheBackProjectedPointsAndTheLibrarysLabels) {
  const std::string input = writeDepth("frame.png");
  const Result result = run({input, "-o", path("out").string(), "--intrinsics", kIntrinsics, "--depth-scale", "5000"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "frame.png: 160x120, 2 planes, ")) << result.out;

  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/frame.labels.pcd").string(), labelled), 0);
  const pcl::PointCloud<pcl::PointXYZ> expected = backProjected(twoPlaneDepth());
  ASSERT_EQ(labelled.width, 160u);
  ASSERT_EQ(labelled.height, 120u);
  std::vector<std::uint32_t> labels;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (!std::isfinite(expected[i].z)) {
      ASSERT_FALSE(std::isfinite(labelled[i].z)) << i;
    } else {
      ASSERT_EQ(labelled[i].x, expected[i].x) << i;
      ASSERT_EQ(labelled[i].y, expected[i].y) << i;
      ASSERT_EQ(labelled[i].z, expected[i].z) << i;
    }
    labels.push_back(labelled[i].label);
  }
  EXPECT_EQ(labels, libraryLabels(expected));
  EXPECT_EQ(*std::max_element(labels.begin(), labels.end()), 2u);
}

// 0 is "no return": a depth image of zeros is a frame without a finite point, valid and empty.
TEST_F(PcdSegmentDepth, ADepthImageOfZerosIsAFrameWithNoPlanes) {
  floodplane::io::DepthImage zeros = twoPlaneDepth();
  std::fill(zeros.depth.begin(), zeros.depth.end(), std::uint16_t{0});
  floodplane::io::writeDepthPng(path("zeros.png").string(), zeros);
  const Result result =
      run({path("zeros.png").string(), "-o", path("out").string(), "--intrinsics", kIntrinsics, "--png", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "zeros.png: 160x120, 0 planes, ")) << result.out;
  EXPECT_EQ(lineCount(result.err), 1u) << result.err;
  EXPECT_TRUE(contains(result.err, "pcd_segment: note: " + path("zeros.png").string() + ": no point has a finite"))
      << result.err;
  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/zeros.labels.pcd").string(), labelled), 0);
  EXPECT_EQ(labelled.size(), 160u * 120u);
  EXPECT_TRUE(std::all_of(labelled.begin(), labelled.end(), [](const pcl::PointXYZL& p) { return p.label == 0; }));
  EXPECT_TRUE(fs::exists(path("out/zeros.labels.png")));
  EXPECT_TRUE(fs::exists(path("out/zeros.planes.json")));
}

// -o NAME.png of a depth image: its label image; never the depth image itself.
TEST_F(PcdSegmentDepth, OutputPngIsTheLabelImageAndNeverTheInput) {
  const std::string input = writeDepth("frame.png");
  const Result result = run({input, "-o", path("labels.png").string(), "--intrinsics", kIntrinsics});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const floodplane::io::RgbImage image = readPng(path("labels.png"));
  EXPECT_EQ(image.width, 160);
  EXPECT_EQ(image.height, 120);
  EXPECT_FALSE(fs::exists(path("labels.pcd")));
  const std::string before = readFile(path("frame.png"));
  expectUsageError(run({input, "-o", input, "--intrinsics", kIntrinsics}), "pcd_segment",
                   "-o " + input + " is the input itself; give the .png file another name");
  EXPECT_EQ(readFile(path("frame.png")), before);
}

// -o NAME.pcd with --png writes NAME.png beside it: refused when that is the depth image read,
// before any write, naming both files; the image stays as it was.
TEST_F(PcdSegmentDepth, RefusesALabelImageOverTheDepthImageItReads) {
  const std::string input = writeDepth("depth.png");
  const std::string before = readFile(input);
  const Result result = run({input, "--intrinsics", kIntrinsics, "-o", path("depth.pcd").string(), "--png", "--json"});
  expectUsageError(result, "pcd_segment", "the output " + input + " would overwrite the input " + input);
  EXPECT_TRUE(readFile(input) == before) << "the depth image changed";
  EXPECT_FALSE(fs::exists(path("depth.pcd")));
  EXPECT_FALSE(fs::exists(path("depth.json")));
  // The same image in a folder with -o that folder: its outputs are named apart, and written.
  fs::create_directory(path("in"));
  const std::string inside = writeDepth("in/depth.png");
  const Result beside = run({path("in").string(), "--intrinsics", kIntrinsics, "-o", path("in").string(), "--png"});
  EXPECT_EQ(beside.exit_code, 0) << beside.err;
  EXPECT_TRUE(readFile(inside) == before) << "the depth image changed";
  EXPECT_TRUE(fs::exists(path("in/depth.labels.png")));
}

TEST_F(PcdSegmentDepth, TheDepthScaleIsUnitsPerMetreAndDefaultsToMillimetres) {
  const std::string input = writeDepth("frame.png");
  ASSERT_EQ(run({input, "-o", path("mm.pcd").string(), "--intrinsics", kIntrinsics}).exit_code, 0);
  pcl::PointCloud<pcl::PointXYZL> millimetres;
  ASSERT_EQ(pcl::io::loadPCDFile(path("mm.pcd").string(), millimetres), 0);
  EXPECT_FLOAT_EQ(millimetres.at(0, 0).z, 10.0f);  // 10000 units of 0.2 mm read as millimetres
}

TEST_F(PcdSegmentDepth, ReadsADirectorysDepthImagesOnlyWithIntrinsics) {
  writeDepth("b.png");
  writeDepth("a.png");
  ASSERT_EQ(pcl::io::savePCDFileBinary(path("c.pcd").string(), backProjected(twoPlaneDepth())), 0);
  const Result with = run({dir_.string(), "-o", path("out").string(), "--intrinsics", kIntrinsics, "-q"});
  ASSERT_EQ(with.exit_code, 0) << with.err;
  EXPECT_TRUE(fs::exists(path("out/a.labels.pcd")));
  EXPECT_TRUE(fs::exists(path("out/b.labels.pcd")));
  EXPECT_TRUE(fs::exists(path("out/c.labels.pcd")));
  // Without intrinsics a directory's PNG files are not inputs (they may be colour images).
  const Result without = run({dir_.string(), "-o", path("out2").string(), "-q"});
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_EQ(std::distance(fs::directory_iterator(path("out2")), fs::directory_iterator()), 1);
}

TEST_F(PcdSegmentDepth, APngWithoutIntrinsicsIsAUsageError) {
  const std::string input = writeDepth("frame.png");
  const Result result = run({input, "-o", path("out").string()});
  expectUsageError(result, "pcd_segment", "needs --intrinsics fx,fy,cx,cy");
  EXPECT_FALSE(fs::exists(path("out")));
}

// A folder of depth images and no PCD files: what is missing is --intrinsics, not PCD files.
TEST_F(PcdSegmentDepth, AFolderOfPngsWithoutIntrinsicsSaysThatIntrinsicsIsMissing) {
  fs::create_directory(path("depth"));
  writeDepth("depth/a.png");
  writeDepth("depth/b.png");
  const Result result = run({path("depth").string(), "-o", path("out").string()});
  expectUsageError(result, "pcd_segment",
                   path("depth").string() + ": directory contains no .pcd files; its 2 .png files");
  EXPECT_TRUE(contains(result.err, "--intrinsics is missing")) << result.err;
  EXPECT_FALSE(fs::exists(path("out")));
}

TEST_F(PcdSegmentDepth, OverlayOfDepthImagesAloneIsAUsageError) {
  const std::string input = writeDepth("frame.png");
  expectUsageError(run({input, "-o", path("out").string(), "--intrinsics", kIntrinsics, "--overlay"}), "pcd_segment",
                   "--overlay lays the labels over the input's colours, and depth images have none");
  EXPECT_FALSE(fs::exists(path("out")));
}

TEST_F(PcdSegmentDepth, RefusesBadIntrinsicsWithUsageAndExitCodeTwo) {
  const std::string input = writeDepth("frame.png");
  const std::vector<std::vector<std::string>> bad = {{"--intrinsics", "525,525,319.5"},
                                                     {"--intrinsics", "525,525,319.5,239.5,1"},
                                                     {"--intrinsics", "0,525,319.5,239.5"},
                                                     {"--intrinsics", "525,abc,319.5,239.5"},
                                                     {"--intrinsics", "525,525,nan,239.5"},
                                                     {"--intrinsics", kIntrinsics, "--depth-scale", "0"},
                                                     {"--intrinsics", kIntrinsics, "--depth-scale", "-5"}};
  for (const auto& option : bad) {
    std::vector<std::string> arguments = {input, "-o", path("out").string()};
    arguments.insert(arguments.end(), option.begin(), option.end());
    SCOPED_TRACE(option[1] + (option.size() > 2 ? " " + option[3] : ""));
    const Result result = run(arguments);
    expectUsageError(result, "pcd_segment", option[option.size() - 2]);
    EXPECT_FALSE(fs::exists(path("out")));
  }
  const Result named = run({input, "-o", path("out").string(), "--intrinsics", "0,525,319.5,239.5"});
  EXPECT_TRUE(contains(named.err, "--intrinsics fx,fy,cx,cy: fx must be")) << named.err;
  const Result scale = run({input, "-o", path("out").string(), "--intrinsics", kIntrinsics, "--depth-scale", "0"});
  EXPECT_TRUE(contains(scale.err, "--depth-scale must be")) << scale.err;
  expectUsageError(run({input, "-o", path("out").string(), "--depth-scale", "5000"}), "pcd_segment",
                   "--depth-scale requires --intrinsics");
}

TEST_F(PcdSegmentDepth, RejectsAnEightBitPng) {
  writeOtherPng(path("grey.png"), PNG_FORMAT_GRAY);
  expectRejected(path("grey.png").string(), "not a depth image: 8 bits per pixel");
}

TEST_F(PcdSegmentDepth, RejectsAColourPng) {
  writeOtherPng(path("colour.png"), PNG_FORMAT_RGB);
  expectRejected(path("colour.png").string(), "not a depth image: a colour PNG");
}

TEST_F(PcdSegmentDepth, RejectsABrokenPng) {
  const std::string input = writeDepth("frame.png");
  const std::string bytes = readFile(input);
  std::ofstream(input, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 2);
  expectRejected(input, "corrupt or truncated PNG file");
}

TEST_F(PcdSegmentDepth, BatchGoesOnPastABadDepthImage) {
  const std::string good = writeDepth("good.png");
  std::ofstream(path("bad.png")) << "not a png";
  const Result result = run({path("bad.png").string(), good, "-o", path("out").string(), "--intrinsics", kIntrinsics});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_TRUE(contains(result.err, "bad.png: not a PNG file")) << result.err;
  EXPECT_TRUE(fs::exists(path("out/good.labels.pcd")));
}

}  // namespace
}  // namespace floodplane::test
