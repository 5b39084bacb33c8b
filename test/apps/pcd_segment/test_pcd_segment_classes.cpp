// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_segment --up and --gravity: each plane's class and height above the floor in the JSON
// report, the library's own (floodplane::describePlanes) for the same cloud, on a bundled scene
// with the up direction from its camera pose; and the errors of bad vectors.

#include <gtest/gtest.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "floodplane/flood_fill_plane_segmentation.h"
#include "floodplane/plane_classes.h"
#include "pcd_segment_test.h"
#include "support/app_run.h"
#include "synth/scene_file.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const std::string kScene = "tabletop";
const std::string kCloud = std::string(FLOODPLANE_RENDERED_DIR) + "/" + kScene + ".kinect.pcd";

// The scene's up (its world's z) in the camera's frame, from the scene file's camera pose.
Eigen::Vector3d sceneUp() {
  const synth::Scene scene = synth::loadScene(std::string(FLOODPLANE_SOURCE_DIR) + "/data/scenes/" + kScene + ".json");
  return scene.world_from_camera.linear().transpose() * Eigen::Vector3d::UnitZ();
}

std::string vectorText(const Eigen::Vector3d& v) {
  char text[128];
  std::snprintf(text, sizeof text, "%.17g,%.17g,%.17g", v.x(), v.y(), v.z());
  return text;
}

// The library's descriptions of the cloud's planes, segmented as pcd_segment does.
std::vector<PlaneDescription> libraryDescriptions(const Eigen::Vector3d& up) {
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  EXPECT_EQ(pcl::io::loadPCDFile(kCloud, *cloud), 0) << kCloud;
  FloodFillPlaneSegmentation<pcl::PointXYZ> segmentation;
  segmentation.setInputCloud(cloud);
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions;
  segmentation.segmentAndRefine(regions);
  return describePlanes(segmentation.getLastSegmentation().planes, up);
}

class PcdSegmentClasses : public PcdSegmentTest {
 protected:
  Json report(const std::string& folder) const {
    return Json::parse(readFile(path(folder) / (kScene + ".kinect.planes.json")));
  }
};

TEST_F(PcdSegmentClasses, UpGivesEachPlaneTheLibrarysClassAndHeight) {
  const Eigen::Vector3d up = sceneUp();
  const Result result = run({kCloud, "-o", path("out").string(), "--json", "--up", vectorText(2.5 * up)});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const Json json = report("out");
  const std::vector<PlaneDescription> expected = libraryDescriptions(up);
  ASSERT_EQ(json.at("planes").size(), expected.size());
  ASSERT_GT(expected.size(), 5u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(json.at("up")[i].get<double>(), up[i], 1e-9) << "unit, as given";
  std::set<std::string> classes;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const Json& plane = json["planes"][k];
    EXPECT_EQ(plane.at("class"), planeClassName(expected[k].plane_class)) << "plane " << k + 1;
    EXPECT_NEAR(plane.at("height_above_floor").get<double>(), expected[k].height_above_floor, 1e-9);
    classes.insert(plane.at("class").get<std::string>());
  }
  // The scene's floor, walls and table (its top 0.75 m high) are there.
  EXPECT_EQ(classes, (std::set<std::string>{"floor", "wall", "horizontal_surface"}));
  bool table = false;
  for (const Json& plane : json["planes"])
    table = table ||
            (plane["class"] == "horizontal_surface" &&
             std::abs(plane["height_above_floor"].get<double>() - 0.75) < 0.01 && plane["inliers"].get<int>() > 10000);
  EXPECT_TRUE(table) << json["planes"].dump();
}

TEST_F(PcdSegmentClasses, GravityIsUpTheOtherWayRound) {
  const Eigen::Vector3d up = sceneUp();
  ASSERT_EQ(run({kCloud, "-o", path("up").string(), "--json", "--up", vectorText(up)}).exit_code, 0);
  ASSERT_EQ(run({kCloud, "-o", path("down").string(), "--json", "--gravity", vectorText(-9.81 * up)}).exit_code, 0);
  Json a = report("up"), b = report("down");
  ASSERT_EQ(a["planes"].size(), b["planes"].size());
  for (std::size_t k = 0; k < a["planes"].size(); ++k) {
    EXPECT_EQ(a["planes"][k]["class"], b["planes"][k]["class"]);
    EXPECT_NEAR(a["planes"][k]["height_above_floor"].get<double>(), b["planes"][k]["height_above_floor"].get<double>(),
                1e-9);
  }
}

// Seen upside down (up given as down), the floor faces down: no floor, every height null.
TEST_F(PcdSegmentClasses, NoFloorGivesNullHeights) {
  const Result result = run({kCloud, "-o", path("out").string(), "--json", "--up", vectorText(-sceneUp())});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const Json json = report("out");
  ASSERT_FALSE(json.at("planes").empty());
  for (const Json& plane : json["planes"]) {
    EXPECT_TRUE(plane.at("height_above_floor").is_null()) << plane.dump();
    EXPECT_NE(plane.at("class"), "floor");
  }
}

TEST_F(PcdSegmentClasses, WithoutUpTheReportHasNoClasses) {
  ASSERT_EQ(run({kCloud, "-o", path("out").string(), "--json"}).exit_code, 0);
  const Json json = report("out");
  EXPECT_FALSE(json.contains("up"));
  for (const Json& plane : json.at("planes")) {
    EXPECT_FALSE(plane.contains("class"));
    EXPECT_FALSE(plane.contains("height_above_floor"));
  }
}

// pcd_synth writes the camera's orientation into the PCD's VIEWPOINT: --up viewpoint takes the
// scene's up from there, and gives the classes and heights of --up with the scene's own up.
TEST_F(PcdSegmentClasses, UpViewpointTakesTheUpOfTheRenderedCamera) {
  const Result result = run({kCloud, "-o", path("viewpoint").string(), "--json", "--up", "viewpoint"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  ASSERT_EQ(run({kCloud, "-o", path("given").string(), "--json", "--up", vectorText(sceneUp())}).exit_code, 0);
  const Json a = report("viewpoint"), b = report("given");
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a.at("up")[i].get<double>(), sceneUp()[i], 1e-6);
  ASSERT_EQ(a["planes"].size(), b["planes"].size());
  ASSERT_GT(a["planes"].size(), 5u);
  for (std::size_t k = 0; k < a["planes"].size(); ++k) {
    EXPECT_EQ(a["planes"][k]["class"], b["planes"][k]["class"]) << "plane " << k + 1;
    EXPECT_NEAR(a["planes"][k]["height_above_floor"].get<double>(), b["planes"][k]["height_above_floor"].get<double>(),
                1e-4);
  }
}

// A cloud whose VIEWPOINT has no rotation says nothing of up: that input fails with the reason,
// and writes nothing.
TEST_F(PcdSegmentClasses, UpViewpointOfACloudWithoutRotationIsAnError) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  ASSERT_EQ(pcl::io::loadPCDFile(kCloud, cloud), 0);
  cloud.sensor_orientation_ = Eigen::Quaternionf::Identity();
  const std::string input = path("level.pcd").string();
  ASSERT_EQ(pcl::io::savePCDFileBinary(input, cloud), 0);
  const Result result = run({input, "-o", path("out").string(), "--json", "--up", "viewpoint"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err, "pcd_segment: error: " + input +
                            ": --up viewpoint: the input has no VIEWPOINT rotation (the identity) to take the up "
                            "direction from; give --up X,Y,Z\n");
  EXPECT_TRUE(fs::is_empty(path("out")));
}

TEST_F(PcdSegmentClasses, RefusesVectorsThatAreNoDirection) {
  const std::string out = path("out").string();
  expectUsageError(run({kCloud, "-o", out, "--json", "--up", "0,0,0"}), "pcd_segment",
                   "--up X,Y,Z must be a direction");
  expectUsageError(run({kCloud, "-o", out, "--json", "--gravity", "0,0,0"}), "pcd_segment",
                   "--gravity X,Y,Z must be a direction");
  expectUsageError(run({kCloud, "-o", out, "--json", "--up", "nan,1,0"}), "pcd_segment", "--up");
  expectUsageError(run({kCloud, "-o", out, "--json", "--up", "inf,1,0"}), "pcd_segment", "--up");
  expectUsageError(run({kCloud, "-o", out, "--json", "--up", "0,1"}), "pcd_segment", "--up");
  expectUsageError(run({kCloud, "-o", out, "--json", "--up", "0,1,0,0"}), "pcd_segment", "--up");
  expectUsageError(run({kCloud, "-o", out, "--json", "--up", "up"}), "pcd_segment",
                   "--up takes X,Y,Z (three numbers) or viewpoint, not 'up'");
  expectUsageError(run({kCloud, "-o", out, "--json", "--up", "0,1,x"}), "pcd_segment", "--up");
  expectUsageError(run({kCloud, "-o", out, "--json", "--up", "0,-1,0", "--gravity", "0,1,0"}), "pcd_segment",
                   "--gravity");
  expectUsageError(run({kCloud, "-o", out, "--up", "0,-1,0"}), "pcd_segment", "--json");
  EXPECT_FALSE(fs::exists(out)) << "nothing written";
}

}  // namespace
}  // namespace floodplane::test
