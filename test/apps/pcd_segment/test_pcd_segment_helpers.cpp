// The rules pcd_segment applies before and after segmenting, without running it.

#include <gtest/gtest.h>

#include "output_paths.h"
#include "planes_json.h"

namespace {

TEST(OutputPaths, PutsOutputsOfADirectoryRunUnderTheInputsName) {
  const auto paths = pcd_segment::outputPaths("/data/frame.7.pcd", "out", false);
  EXPECT_EQ(paths.pcd, "out/frame.7.labels.pcd");
  EXPECT_EQ(paths.png, "out/frame.7.labels.png");
  EXPECT_EQ(paths.json, "out/frame.7.planes.json");
}

TEST(OutputPaths, PutsPngAndJsonNextToASingleOutputFileWithItsStem) {
  EXPECT_TRUE(pcd_segment::namesPcdFile("res/scene.pcd"));
  EXPECT_FALSE(pcd_segment::namesPcdFile("res/scene.pcd/"));
  const auto paths = pcd_segment::outputPaths("in.pcd", "res/scene.pcd", true);
  EXPECT_EQ(paths.pcd, "res/scene.pcd");
  EXPECT_EQ(paths.png, "res/scene.png");
  EXPECT_EQ(paths.json, "res/scene.json");
}

TEST(PixelBox, SpansTheColumnsAndRowsOfTheIndices) {
  // Width 10: index 23 is column 3 of row 2, index 47 column 7 of row 4, 50 column 0 of row 5.
  const pcd_segment::PixelBox box = pcd_segment::pixelBox({23, 47, 50}, 10);
  EXPECT_EQ(box.min_column, 0);
  EXPECT_EQ(box.max_column, 7);
  EXPECT_EQ(box.min_row, 2);
  EXPECT_EQ(box.max_row, 5);
  const pcd_segment::PixelBox empty = pcd_segment::pixelBox({}, 10);
  EXPECT_LT(empty.max_column, empty.min_column);
}

TEST(ReportJson, HoldsTheParametersAndEveryPlane) {
  pcd_segment::Report report;
  report.input = "a.pcd";
  report.width = 4;
  report.height = 3;
  report.params.seed_size = 0.125;
  report.segmentation_ms = 2.5;
  pcd_segment::PlaneRecord plane;
  plane.id = 1;
  plane.normal[2] = -1.0f;
  plane.d = 2.0f;
  plane.inliers = 7;
  plane.boundary_box = {1, 2, 0, 1};
  report.planes = {plane};
  const auto json = pcd_segment::reportJson(report);
  EXPECT_EQ(json["parameters"]["seed_size"], 0.125);
  EXPECT_EQ(json["segmentation_ms"], 2.5);
  ASSERT_EQ(json["planes"].size(), 1u);
  EXPECT_EQ(json["planes"][0]["inliers"], 7);
  EXPECT_EQ(json["planes"][0]["normal"][2], -1.0);
  EXPECT_EQ(json["planes"][0]["boundary_box"]["max_column"], 2);
}

}  // namespace
