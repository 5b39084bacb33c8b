// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_compare end to end: the real binary on small rendered scenes, checking its exit codes,
// its Markdown means, its JSON report, its images and its error reports.

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/app_run.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;

const std::string kTabletop = std::string(PCD_COMPARE_SCENE_DIR) + "/tabletop.kinect.pcd";
const std::string kStaircase = std::string(PCD_COMPARE_SCENE_DIR) + "/staircase.none.pcd";

class PcdCompare : public AppTest {
 protected:
  // Runs pcd_compare with `arguments` (already quoted where needed).
  Result run(const std::string& arguments) const { return runShell(quote(PCD_COMPARE_BINARY) + " " + arguments); }
};

// A result's mean and weighted IoU are the plain and the size-weighted averages of the IoU of
// its kept ground-truth planes.
void expectIouAveragesOfThePlanes(const nlohmann::json& result, const std::string& what) {
  const auto& planes = result["per_plane"];
  ASSERT_FALSE(planes.empty()) << what;
  double sum = 0.0, weighted = 0.0, pixels = 0.0;
  for (const auto& plane : planes) {
    sum += plane["iou"].get<double>();
    weighted += plane["iou"].get<double>() * plane["pixels"].get<double>();
    pixels += plane["pixels"].get<double>();
  }
  EXPECT_NEAR(result["mean_iou"].get<double>(), sum / static_cast<double>(planes.size()), 1e-12) << what;
  EXPECT_NEAR(result["weighted_iou"].get<double>(), weighted / pixels, 1e-12) << what;
}

// Number of rows `| <method> | <files> |` in the Markdown table of means under `### <block>`
// ("all files (2)", "sensor model kinect (1 files)").
int meanRowCount(const std::string& markdown, const std::string& block, const std::string& method, int files) {
  const std::size_t start = markdown.find("### " + block + "\n");
  if (start == std::string::npos) return 0;
  const std::size_t end = std::min(markdown.find("\n#", start + 1), markdown.size());
  const std::string table = markdown.substr(start, end - start);
  const std::string row = "\n| " + method + " | " + std::to_string(files) + " |";
  int count = 0;
  for (std::size_t at = table.find(row); at != std::string::npos; at = table.find(row, at + 1)) ++count;
  return count;
}

// The names of the scenes of a JSON report, in report order.
std::vector<std::string> sceneNames(const nlohmann::json& report) {
  std::vector<std::string> names;
  for (const auto& scene : report["scenes"]) names.push_back(scene["name"]);
  return names;
}

TEST_F(PcdCompare, ComparesEveryMethodOnEveryScene) {
  const fs::path json_file = dir_ / "out.json";
  const Result outcome = run("--repeat 2 --methods floodplane,ransac,omps --json " + quote(json_file.string()) + " " +
                             quote(kTabletop) + " " + quote(kStaircase));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  for (const std::string method : {"floodplane", "ransac", "omps"}) {
    EXPECT_EQ(meanRowCount(outcome.out, "all files (2)", method, 2), 1) << method;
    // The configuration names every method with its parameters before the numbers.
    const std::size_t config = outcome.out.find("**method " + method + "**");
    ASSERT_NE(config, std::string::npos) << method;
    EXPECT_LT(config, outcome.out.find("## Means per method"));
  }
  EXPECT_NE(outcome.out.find("PCL"), std::string::npos);
  // Progress per file on stderr when there are several, with the time left after the first.
  EXPECT_NE(outcome.err.find("[1/2] " + kTabletop + "\n"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("[2/2] " + kStaircase + " ("), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find(" left)"), std::string::npos) << outcome.err;

  const nlohmann::json json = nlohmann::json::parse(readFile(json_file));
  ASSERT_EQ(sceneNames(json), (std::vector<std::string>{"tabletop.kinect", "staircase.none"}));
  for (const auto& scene : json["scenes"]) {
    EXPECT_TRUE(scene["ground_truth"].get<bool>());
    ASSERT_EQ(scene["methods"].size(), 3u);
    for (const auto& [method, result] : scene["methods"].items()) {
      ASSERT_TRUE(result["mean_iou"].is_number()) << method;
      expectIouAveragesOfThePlanes(result, method);
      EXPECT_GT(result["median_ms"].get<double>(), 0.0) << method;
      EXPECT_LE(result["min_ms"].get<double>(), result["median_ms"].get<double>()) << method;
      // Every kept ground-truth plane is either matched or not: the Hoover classes of the
      // planes add up to the number of planes.
      const auto& hoover = result["hoover"];
      std::size_t classified = 0;
      for (const auto& plane : result["per_plane"]) {
        classified += plane["hoover"] == "missed" ? 0 : 1;
      }
      EXPECT_EQ(classified + hoover["missed"].get<std::size_t>(), result["ground_truth_planes"].get<std::size_t>())
          << method;
    }
    EXPECT_DOUBLE_EQ(scene["methods"]["floodplane"]["ratio_to_floodplane"].get<double>(), 1.0);
  }
  // The mean rows average the scenes; the false-plane fraction only where it is defined:
  // the tabletop has a curved object (ground truth 0), the staircase has none.
  const auto& tabletop = json["scenes"][0]["name"] == "tabletop.kinect" ? json["scenes"][0] : json["scenes"][1];
  const auto& staircase = json["scenes"][0]["name"] == "tabletop.kinect" ? json["scenes"][1] : json["scenes"][0];
  ASSERT_EQ(staircase["name"], "staircase.none");
  for (const std::string method : {"floodplane", "ransac", "omps"}) {
    const auto& mean = json["means"][method];
    EXPECT_DOUBLE_EQ(mean["mean_iou"].get<double>(), (tabletop["methods"][method]["mean_iou"].get<double>() +
                                                      staircase["methods"][method]["mean_iou"].get<double>()) /
                                                         2.0)
        << method;
    ASSERT_TRUE(tabletop["methods"][method]["false_plane_fraction"].is_number()) << method;
    EXPECT_TRUE(staircase["methods"][method]["false_plane_fraction"].is_null()) << method;
    EXPECT_EQ(mean["false_plane_fraction"], tabletop["methods"][method]["false_plane_fraction"]) << method;
    EXPECT_EQ(mean["scenes_with_non_plane_ground_truth"], 1) << method;
    // One mean per sensor model named in the file names, over that model's one scene here.
    EXPECT_EQ(meanRowCount(outcome.out, "sensor model kinect (1 files)", method, 1), 1) << method;
    EXPECT_EQ(meanRowCount(outcome.out, "sensor model none (1 files)", method, 1), 1) << method;
    EXPECT_EQ(json["means_by_sensor"]["kinect"][method]["mean_iou"], tabletop["methods"][method]["mean_iou"]);
    EXPECT_EQ(json["means_by_sensor"]["none"][method]["mean_iou"], staircase["methods"][method]["mean_iou"]);
  }
  EXPECT_NE(outcome.out.find("| noise | false planes |"), std::string::npos);
  // Methods in --methods order, in the JSON as in the tables.
  std::vector<std::string> order;
  const auto in_file_order = nlohmann::ordered_json::parse(readFile(json_file))["scenes"][0]["methods"];
  for (const auto& [method, result] : in_file_order.items()) order.push_back(method);
  EXPECT_EQ(order, (std::vector<std::string>{"floodplane", "ransac", "omps"}));
  EXPECT_LT(outcome.out.find("| floodplane | 2 |"), outcome.out.find("| ransac | 2 |"));
}

// The sequential RANSACs take seconds a cloud: timed once, on the scored run, whatever
// --repeat says; the other methods --repeat times after the warm-up.
TEST_F(PcdCompare, SlowBaselinesAreTimedOnceAndTheOthersRepeatedly) {
  const fs::path json_file = dir_ / "out.json";
  const Result outcome =
      run("--repeat 5 --quiet --methods ransac,omps --json " + quote(json_file.string()) + " " + quote(kStaircase));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const nlohmann::json methods = nlohmann::json::parse(readFile(json_file))["scenes"][0]["methods"];
  EXPECT_EQ(methods["ransac"]["median_ms"], methods["ransac"]["min_ms"]);
  EXPECT_LT(methods["omps"]["min_ms"].get<double>(), methods["omps"]["median_ms"].get<double>());
}

TEST_F(PcdCompare, MethodsOptionRunsOnlyTheChosenMethods) {
  const Result outcome = run("--repeat 2 --quiet --methods omps,floodplane " + quote(kStaircase));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_EQ(meanRowCount(outcome.out, "all files (1)", "floodplane", 1), 1);
  EXPECT_EQ(meanRowCount(outcome.out, "all files (1)", "omps", 1), 1);
  EXPECT_EQ(meanRowCount(outcome.out, "all files (1)", "ransac", 1), 0);
  // --quiet: the tables but no configuration.
  EXPECT_EQ(outcome.out.find("## Configuration"), std::string::npos);
}

TEST_F(PcdCompare, MissingFileIsReportedByNameAndTheOtherFilesAreStillCompared) {
  const std::string missing = (dir_ / "no_such_scene.pcd").string();
  const Result outcome = run("--repeat 2 --methods floodplane " + quote(missing) + " " + quote(kStaircase));
  EXPECT_EQ(outcome.exit_code, 1);
  EXPECT_NE(outcome.err.find(missing + ": no such file"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("1 of 2 files failed: " + missing), std::string::npos) << outcome.err;
  EXPECT_EQ(meanRowCount(outcome.out, "all files (1)", "floodplane", 1), 1) << outcome.out;
}

TEST_F(PcdCompare, FilesThatAreNotOrganizedPointCloudsAreReportedByName) {
  const fs::path text = dir_ / "not_a_cloud.pcd";
  std::ofstream(text) << "this is not a point cloud\n";
  pcl::PointCloud<pcl::PointXYZ> unorganized;
  for (int i = 0; i < 10; ++i) {
    unorganized.push_back(pcl::PointXYZ(0.1f * static_cast<float>(i), 0.0f, 1.0f));
  }
  const fs::path flat = dir_ / "unorganized.pcd";
  pcl::io::savePCDFileBinary(flat.string(), unorganized);
  pcl::PointCloud<pcl::Label> labels_only(4, 4);
  const fs::path no_xyz = dir_ / "labels_only.pcd";
  pcl::io::savePCDFileBinary(no_xyz.string(), labels_only);

  const Result outcome = run("--repeat 2 --methods floodplane " + quote(text.string()) + " " + quote(flat.string()) +
                             " " + quote(no_xyz.string()) + " " + quote(kStaircase));
  EXPECT_EQ(outcome.exit_code, 1);
  EXPECT_NE(outcome.err.find(text.string() + ": not a PCD file"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find(flat.string() + ": unorganized cloud"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find(no_xyz.string() + ": the cloud has no x y z fields"), std::string::npos) << outcome.err;
  EXPECT_EQ(meanRowCount(outcome.out, "all files (1)", "floodplane", 1), 1);
}

// The rule of every interface: a frame with no finite point, or one too small to hold much (a
// 2 x 2 grid, a single column), is a valid frame that every method finds its planes in, or
// none; not a failed file. OMPS's normal estimation would write past a grid smaller than its
// window (PCL 1.13): it finds no plane there, unrun.
TEST_F(PcdCompare, EmptyAndTinyFramesAreComparedLikeAnyOther) {
  pcl::PointCloud<pcl::PointXYZ> staircase;
  ASSERT_EQ(pcl::io::loadPCDFile(kStaircase, staircase), 0);
  const auto frame = [&](const std::string& name, std::uint32_t width, std::uint32_t height, bool finite) {
    pcl::PointCloud<pcl::PointXYZ> cloud(width, height);
    for (std::uint32_t i = 0; i < cloud.size(); ++i) {
      cloud[i] = staircase.at(static_cast<int>(160 + i % width), static_cast<int>(200 + i / width));
      if (!finite) cloud[i].x = cloud[i].y = cloud[i].z = std::numeric_limits<float>::quiet_NaN();
    }
    cloud.is_dense = finite;
    const std::string file = (dir_ / name).string();
    pcl::io::savePCDFileBinary(file, cloud);
    return file;
  };
  const std::string nan = frame("nan.pcd", 40, 30, false);
  const fs::path json_file = dir_ / "out.json";
  const Result outcome = run("--repeat 1 --methods floodplane,floodplane/8,ransac,open3d_ransac,omps --json " +
                             quote(json_file.string()) + " --png " + quote((dir_ / "pictures").string()) + " " +
                             quote(nan) + " " + quote(frame("square.pcd", 2, 2, true)) + " " +
                             quote(frame("column.pcd", 1, 6, true)) + " " + quote(frame("edge.pcd", 12, 12, true)));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_TRUE(contains(
      outcome.err,
      "pcd_compare: note: " + nan + ": no point has a finite x y z (all NaN, or no depth): a frame with no planes\n"))
      << outcome.err;
  EXPECT_FALSE(contains(outcome.err, "error")) << outcome.err;
  const nlohmann::json report = nlohmann::json::parse(readFile(json_file));
  EXPECT_TRUE(report["failed"].empty()) << report["failed"];
  EXPECT_EQ(sceneNames(report), (std::vector<std::string>{"nan", "square", "column", "edge"}));
  for (const auto& scene : report["scenes"]) {
    for (const std::string method : {"floodplane", "floodplane/8", "ransac", "open3d_ransac", "omps"}) {
      ASSERT_TRUE(scene["methods"].contains(method)) << scene["name"] << " " << method;
      if (scene["name"] == "nan" || method == "omps") {
        EXPECT_EQ(scene["methods"][method]["planes"], 0) << method;
      }
    }
    EXPECT_TRUE(fs::exists(dir_ / "pictures" / (scene["name"].get<std::string>() + ".png"))) << scene["name"];
  }
  // Quiet: the means and errors only.
  EXPECT_TRUE(run("--quiet --repeat 1 --methods floodplane " + quote(nan)).err.empty());
}

TEST_F(PcdCompare, BadOptionsAreOneLineNamingTheFlagWithExitCodeTwo) {
  expectUsageError(run("--no-such-option " + quote(kStaircase)), "pcd_compare", "--no-such-option");
  expectUsageError(run("--methods floodplane,watershed " + quote(kStaircase)), "pcd_compare", "--methods");
  expectUsageError(run("--repeat -1 " + quote(kStaircase)), "pcd_compare", "--repeat");
  expectUsageError(run("--sensor phone " + quote(kStaircase)), "pcd_compare", "--sensor");
  expectUsageError(run("--methods floodplane/3 " + quote(kStaircase)), "pcd_compare", "--methods");
  expectUsageError(run("--repeat 2"), "pcd_compare", "INPUT is required");
}

TEST_F(PcdCompare, HelpAndVersionExitWithCodeZero) {
  const Result help = run("--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const std::string option : {"--resolutions", "--sensor", "--tuned-file", "--png3d"}) {
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
  }
  // --png's pictures as every app's label images (cli/cli.h).
  EXPECT_NE(help.out.find("near-black where a point is on no plane, white where there is no point (no depth)"),
            std::string::npos);
  const Result version = run("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_FALSE(version.out.empty());
}

// Regression: PCL's OMPS appends to the coefficient and inlier vectors it is given, and the
// app reused them across runs and files; several files into a batch PCL's refine() indexed
// its per-label tables with stale labels and corrupted the heap ("double free or corruption"
// on the rendered scene set). A batch must finish, and a scene's result must not depend on
// the scenes before it.
TEST_F(PcdCompare, OmpsOverAWholeSceneBatchFinishesAndEachSceneIsIndependent) {
  const fs::path alone_json = dir_ / "alone.json";
  const fs::path batch_json = dir_ / "batch.json";
  const Result batch = run("--quiet --repeat 3 --methods omps --json " + quote(batch_json.string()) + " " +
                           quote(FLOODPLANE_RENDERED_DIR));
  ASSERT_EQ(batch.exit_code, 0) << batch.err;
  const nlohmann::json scenes = nlohmann::json::parse(readFile(batch_json))["scenes"];
  ASSERT_GE(scenes.size(), 10u);
  const std::string last_scene = std::string(FLOODPLANE_RENDERED_DIR) + "/tabletop.none.pcd";
  ASSERT_EQ(
      run("--quiet --repeat 3 --methods omps --json " + quote(alone_json.string()) + " " + quote(last_scene)).exit_code,
      0);
  const nlohmann::json alone = nlohmann::json::parse(readFile(alone_json))["scenes"][0];
  bool found = false;
  for (const auto& scene : scenes) {
    if (scene["name"] != alone["name"]) continue;
    found = true;
    const auto& a = alone["methods"]["omps"];
    const auto& b = scene["methods"]["omps"];
    EXPECT_EQ(b["planes"], a["planes"]);
    EXPECT_EQ(b["mean_iou"], a["mean_iou"]);
    EXPECT_EQ(b["per_plane"], a["per_plane"]);
  }
  EXPECT_TRUE(found) << alone["name"];
}

TEST_F(PcdCompare, CloudWithoutLabelsGivesRuntimeOnly) {
  pcl::PointCloud<pcl::PointXYZ> xyz;
  ASSERT_EQ(pcl::io::loadPCDFile(kStaircase, xyz), 0);
  const fs::path file = dir_ / "unlabelled.pcd";
  pcl::io::savePCDFileBinary(file.string(), xyz);
  const fs::path json_file = dir_ / "out.json";
  const Result outcome =
      run("--repeat 2 --methods floodplane,omps --json " + quote(json_file.string()) + " " + quote(file.string()));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_EQ(meanRowCount(outcome.out, "all files (1)", "floodplane", 1), 1);
  EXPECT_EQ(outcome.out.find("mean IoU"), std::string::npos);
  const nlohmann::json json = nlohmann::json::parse(readFile(json_file));
  const auto& scene = json["scenes"][0];
  EXPECT_FALSE(scene["ground_truth"].get<bool>());
  EXPECT_FALSE(scene["methods"]["floodplane"].contains("mean_iou"));
  EXPECT_GT(scene["methods"]["omps"]["parts_median_ms"]["normals"].get<double>(), 0.0);
}

TEST_F(PcdCompare, DirectoryInputComparesItsPcdFilesInSortedOrder) {
  fs::copy_file(kTabletop, dir_ / "b_tabletop.pcd");
  fs::copy_file(kStaircase, dir_ / "a_staircase.pcd");
  std::ofstream(dir_ / "notes.txt") << "not a cloud, and not named .pcd\n";
  const fs::path json_file = dir_ / "out" / "report.json";
  fs::create_directories(json_file.parent_path());
  const Result outcome =
      run("--repeat 2 --methods floodplane --json " + quote(json_file.string()) + " " + quote(dir_.string()));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_EQ(sceneNames(nlohmann::json::parse(readFile(json_file))),
            (std::vector<std::string>{"a_staircase", "b_tabletop"}));
}

TEST_F(PcdCompare, AveragesPerSensorModelNamedInTheFileName) {
  fs::copy_file(kStaircase, dir_ / "wall.scanner.pcd");
  fs::copy_file(kStaircase, dir_ / "frame_1.250.pcd");  // a time stamp, not a sensor model
  fs::copy_file(kStaircase, dir_ / "plain.pcd");
  const fs::path json_file = dir_ / "out.json";
  const Result outcome =
      run("--repeat 2 --quiet --methods floodplane --json " + quote(json_file.string()) + " " + quote(dir_.string()));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_EQ(meanRowCount(outcome.out, "all files (3)", "floodplane", 3), 1) << outcome.out;
  EXPECT_EQ(meanRowCount(outcome.out, "sensor model scanner (1 files)", "floodplane", 1), 1) << outcome.out;
  const nlohmann::json json = nlohmann::json::parse(readFile(json_file));
  ASSERT_EQ(json["means_by_sensor"].size(), 1u) << json["means_by_sensor"].dump();
  EXPECT_EQ(json["means_by_sensor"]["scanner"]["floodplane"]["scenes"], 1);
}

TEST_F(PcdCompare, PngShowsGroundTruthAndEachMethodSideBySide) {
  const fs::path png_dir = dir_ / "images";
  const Result outcome =
      run("--repeat 2 --quiet --methods floodplane,omps --png " + quote(png_dir.string()) + " " + quote(kStaircase));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const std::string png = readFile(png_dir / "staircase.none.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  // IHDR width, big-endian at byte 16: three 320-pixel panels (ground truth, omps,
  // floodplane) and two 4-pixel gaps.
  const auto byte = [&png](std::size_t i) { return static_cast<unsigned char>(png[i]); };
  const unsigned width = (byte(16) << 24) | (byte(17) << 16) | (byte(18) << 8) | byte(19);
  EXPECT_EQ(width, 3u * 320u + 2u * 4u);
}

TEST_F(PcdCompare, ResolutionsAddFloodplaneAtEachSubsampling) {
  const fs::path json_file = dir_ / "out.json";
  const Result outcome = run("--repeat 2 --quiet --methods ransac,floodplane/2 --resolutions --json " +
                             quote(json_file.string()) + " " + quote(kStaircase));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const nlohmann::json json = nlohmann::json::parse(readFile(json_file));
  const auto& scene = json["scenes"][0];
  // floodplane/2 once, although both --methods and --resolutions name it; in run order.
  std::vector<std::string> order;
  const auto in_file_order = nlohmann::ordered_json::parse(readFile(json_file))["scenes"][0]["methods"];
  for (const auto& [method, result] : in_file_order.items()) order.push_back(method);
  EXPECT_EQ(order,
            (std::vector<std::string>{"ransac", "floodplane/2", "floodplane/1", "floodplane/4", "floodplane/8"}));
  for (const std::string method : {"floodplane/1", "floodplane/2", "floodplane/4", "floodplane/8"}) {
    expectIouAveragesOfThePlanes(scene["methods"][method], method);
  }
}

TEST_F(PcdCompare, MinGtPointsSetsTheSizeOfTheRegionsThatCount) {
  // The scene's planes, counted with a minimum of n pixels; every kept plane has n or more.
  const auto planesOfAtLeast = [this](const std::string& option, std::uint32_t n) {
    const fs::path json_file = dir_ / "out.json";
    const Result outcome = run("--repeat 0 --methods floodplane " + option + " --json " + quote(json_file.string()) +
                               " " + quote(kStaircase));
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    const nlohmann::json json = nlohmann::json::parse(readFile(json_file));
    const auto& scene = json["scenes"][0];
    EXPECT_EQ(scene["min_points"].get<std::uint32_t>(), n) << option;
    const auto& floodplane = scene["methods"]["floodplane"];
    for (const auto& plane : floodplane["per_plane"]) {
      EXPECT_GE(plane["pixels"].get<std::uint32_t>(), n) << option;
    }
    if (!option.empty()) {
      EXPECT_NE(outcome.out.find("pixels (--min-gt-points)"), std::string::npos) << outcome.out;
    }
    return floodplane["ground_truth_planes"].get<std::size_t>();
  };
  const std::size_t by_default = planesOfAtLeast("", 125);  // round(500 * 320 * 240 / (640 * 480))
  EXPECT_GE(planesOfAtLeast("--min-gt-points 100", 100), by_default);
  EXPECT_LT(planesOfAtLeast("--min-gt-points 5000", 5000), by_default);
}

TEST_F(PcdCompare, MinGtPointsMustBeAWholeNumberOfPixelsAboveZero) {
  for (const std::string value : {"0", "-3", "many", "1.5", "5000000000"}) {
    expectUsageError(run("--min-gt-points " + value + " " + quote(kStaircase)), "pcd_compare", "--min-gt-points");
  }
  EXPECT_NE(run("--help").out.find("--min-gt-points"), std::string::npos);
}

TEST_F(PcdCompare, MissesListEveryPlaneNotFoundCorrectlyWithItsReason) {
  const fs::path json_file = dir_ / "out.json";
  const Result outcome = run("--repeat 0 --quiet --misses --methods floodplane,omps --json " +
                             quote(json_file.string()) + " " + quote(kTabletop) + " " + quote(kStaircase));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const std::size_t misses = outcome.out.find("## Misses per method");
  ASSERT_NE(misses, std::string::npos) << outcome.out;
  EXPECT_GT(misses, outcome.out.find("## Means per method"));
  const std::string table = outcome.out.substr(misses);
  const nlohmann::json json = nlohmann::json::parse(readFile(json_file));
  std::size_t rows = 0;
  for (const std::string method : {"floodplane", "omps"}) {
    std::size_t planes = 0, missed = 0, noise = 0;
    for (const auto& scene : json["scenes"]) {
      const auto& result = scene["methods"][method];
      const std::string file = scene["name"];
      for (const auto& plane : result["per_plane"]) {
        ++planes;
        // A reason exactly for the planes that are not correct detections.
        EXPECT_EQ(plane["miss"].is_null(), plane["hoover"] == "correct") << plane.dump();
        EXPECT_GE(plane["unlabelled_share"].get<double>(), 0.0);
        EXPECT_LE(plane["unlabelled_share"].get<double>(), 1.0);
        if (plane["miss"].is_null()) continue;
        ++missed;
        const std::string reason = plane["miss"];
        EXPECT_TRUE(reason == "no_segment" || reason == "under_segmented" || reason == "over_segmented" ||
                    reason == "iou_below_t")
            << reason;
        // Hoover's own classes keep their names.
        if (plane["hoover"] == "over" || plane["hoover"] == "under") {
          EXPECT_EQ(reason, plane["hoover"].get<std::string>() + "_segmented");
        }
        const std::string row = "| " + file + " | " + std::to_string(plane["label"].get<int>()) + " | " + reason +
                                " | " + std::to_string(plane["pixels"].get<int>()) + " | ";
        EXPECT_NE(table.find(row), std::string::npos) << row << "\n" << table;
        ++rows;
      }
      EXPECT_EQ(result["noise_segments"].size(), result["hoover"]["noise"].get<std::size_t>());
      noise += result["noise_segments"].size();
    }
    EXPECT_NE(table.find("### " + method + ": " + std::to_string(missed) + " of " + std::to_string(planes) +
                         " ground-truth planes not correct, " + std::to_string(noise) + " noise segments"),
              std::string::npos)
        << table;
  }
  EXPECT_GT(rows, 0u) << "OMPS at its defaults misses planes of these scenes";
  // Without --misses, no such table.
  EXPECT_EQ(run("--repeat 0 --quiet --methods floodplane " + quote(kStaircase)).out.find("## Misses"),
            std::string::npos);
}

}  // namespace

namespace {

// A tuning file as bench/tune_baselines.py writes it, with one OMPS value for the sensor model
// "none".
void writeTunedFile(const fs::path& file, double maximum_curvature) {
  nlohmann::json json;
  json["methods"]["omps"]["by_sensor"]["none"]["parameters"]["maximum_curvature"] = maximum_curvature;
  std::ofstream(file) << json.dump();
}

using PcdCompareTuned = PcdCompare;

TEST_F(PcdCompareTuned, TunedRowsFollowTheSensorModelOfEachFileAndSayWhyOneIsMissing) {
  const fs::path tuned = dir_ / "tuned.json";
  writeTunedFile(tuned, 0.1);
  const fs::path json_file = dir_ / "out.json";
  const Result outcome = run("--repeat 0 --methods floodplane,omps --tuned --tuned-file " + quote(tuned.string()) +
                             " --json " + quote(json_file.string()) + " " + quote(kStaircase) + " " + quote(kTabletop));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const nlohmann::json json = nlohmann::json::parse(readFile(json_file));
  ASSERT_EQ(sceneNames(json), (std::vector<std::string>{"staircase.none", "tabletop.kinect"}));
  EXPECT_TRUE(json["scenes"][0]["methods"].contains("omps (tuned)"));
  // No tuned values for the Kinect model in the file: no tuned row, and a note why.
  EXPECT_FALSE(json["scenes"][1]["methods"].contains("omps (tuned)"));
  EXPECT_NE(outcome.err.find("--tuned: no tuned rows for 1 file(s), no values of omps (tuned) for sensor model "
                             "'kinect' in " +
                             tuned.string() + ": tabletop.kinect"),
            std::string::npos)
      << outcome.err;
  // The configuration gives every value, defaults filled in, then the method's own description.
  EXPECT_NE(outcome.out.find("**method omps (tuned) [none]**: angular_threshold="), std::string::npos);
  EXPECT_NE(outcome.out.find("maximum curvature 0.1;"), std::string::npos);
  EXPECT_EQ(meanRowCount(outcome.out, "sensor model none (1 files)", "omps (tuned)", 1), 1) << outcome.out;
}

// A user's own file has no sensor model in its name: --tuned says so, even with --quiet, and
// --sensor picks the model.
TEST_F(PcdCompareTuned, SensorOptionPicksTheTunedValuesOfFilesWithoutAModelInTheirName) {
  const fs::path tuned = dir_ / "tuned.json";
  writeTunedFile(tuned, 0.1);
  fs::copy_file(kStaircase, dir_ / "myscan.pcd");
  const std::string common = "--repeat 0 --quiet --methods omps --tuned --tuned-file " + quote(tuned.string());
  const Result unnamed = run(common + " " + quote((dir_ / "myscan.pcd").string()));
  ASSERT_EQ(unnamed.exit_code, 0) << unnamed.err;
  EXPECT_NE(unnamed.err.find("no tuned rows for 1 file(s), no sensor model (name the file <scene>.<sensor>.pcd, or "
                             "pass --sensor kinect|scanner|none): myscan"),
            std::string::npos)
      << unnamed.err;
  EXPECT_EQ(meanRowCount(unnamed.out, "all files (1)", "omps (tuned)", 1), 0);

  const Result chosen = run(common + " --sensor none " + quote((dir_ / "myscan.pcd").string()));
  ASSERT_EQ(chosen.exit_code, 0) << chosen.err;
  EXPECT_EQ(chosen.err.find("no tuned rows"), std::string::npos) << chosen.err;
  EXPECT_EQ(meanRowCount(chosen.out, "all files (1)", "omps (tuned)", 1), 1) << chosen.out;
  EXPECT_EQ(meanRowCount(chosen.out, "sensor model none (1 files)", "omps", 1), 1) << chosen.out;
}

// No source-tree path in the binary: the tuned values come from --tuned-file, else
// $FLOODPLANE_TUNED_FILE, else the copy beside the binary (build tree) or in share/floodplane.
TEST_F(PcdCompareTuned, DefaultTunedFileIsTheEnvironmentsOrTheOneBesideTheBinary) {
  const Result beside = run("--repeat 0 --quiet --methods omps --tuned " + quote(kStaircase));
  ASSERT_EQ(beside.exit_code, 0) << beside.err;
  EXPECT_EQ(meanRowCount(beside.out, "all files (1)", "omps (tuned)", 1), 1) << beside.out;

  const fs::path missing = dir_ / "missing.json";
  const Result from_environment = runShell("FLOODPLANE_TUNED_FILE=" + quote(missing.string()) + " " +
                                           quote(PCD_COMPARE_BINARY) + " --tuned " + quote(kStaircase));
  EXPECT_EQ(from_environment.exit_code, 1);
  EXPECT_NE(from_environment.err.find(missing.string() + ": cannot read the tuned parameters"), std::string::npos)
      << from_environment.err;
}

TEST_F(PcdCompareTuned, BadTunedFilesAreReportedByName) {
  const fs::path missing = dir_ / "missing.json";
  const Result no_file = run("--tuned --tuned-file " + quote(missing.string()) + " " + quote(kStaircase));
  EXPECT_EQ(no_file.exit_code, 1);
  EXPECT_NE(no_file.err.find(missing.string() + ": cannot read the tuned parameters"), std::string::npos)
      << no_file.err;
  const fs::path bad = dir_ / "bad.json";
  std::ofstream(bad) << R"({"methods": {"omps": {"by_sensor": {"none": {"parameters": {"bogus": 1.0}}}}}})";
  const Result bad_value = run("--tuned --tuned-file " + quote(bad.string()) + " " + quote(kStaircase));
  EXPECT_EQ(bad_value.exit_code, 1);
  EXPECT_NE(bad_value.err.find(bad.string() + ": omps has no parameter 'bogus'"), std::string::npos) << bad_value.err;
}

// --objects on the tabletop: each object method's objects written and scored. Scored against its
// own objects as ground truth (object k as mOSD's label 10 (k + 1): 20, 30, ...), a method is
// perfect: what was written is what was scored, by the osd_scores.py rules.
TEST_F(PcdCompare, ObjectMethodsWriteTheirObjectsAndScoreThem) {
  const fs::path objects_dir = dir_ / "objects";
  const fs::path json_file = dir_ / "objects.json";
  const Result first = run("--objects --repeat 0 --write-objects " + quote(objects_dir.string()) + " --json " +
                           quote(json_file.string()) + " " + quote(kTabletop));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.out.find("**object method pcl_organized**"), std::string::npos) << first.out;
  const nlohmann::json report = nlohmann::json::parse(readFile(json_file));
  ASSERT_EQ(report["scenes"].size(), 1u);
  for (const std::string method : {"floodplane", "pcl_organized", "lccp", "lccp_ec_sc"}) {
    EXPECT_EQ(meanRowCount(first.out, "all files (1)", method, 1), 1) << method << first.out;
    const auto& entry = report["scenes"][0]["methods"][method];
    pcl::PointCloud<pcl::PointXYZL> objects;
    const fs::path file = objects_dir / method / "tabletop.kinect.objects.pcd";
    ASSERT_EQ(pcl::io::loadPCDFile(file.string(), objects), 0) << file;
    ASSERT_EQ(objects.width, 320u);
    ASSERT_EQ(objects.height, 240u);
    std::set<std::uint32_t> ids;
    for (const auto& point : objects) {
      if (point.label != 0) ids.insert(point.label);
    }
    // The tabletop's boxes, ball and jar: some objects, numbered 1..K.
    ASSERT_FALSE(ids.empty()) << method;
    EXPECT_EQ(*ids.rbegin(), ids.size()) << method;
    EXPECT_EQ(entry["objects"].get<std::size_t>(), ids.size()) << method;

    const fs::path truth_dir = dir_ / ("truth_" + method);
    fs::create_directories(truth_dir);
    for (auto& point : objects) point.label = point.label == 0 ? 0 : 10 * (point.label + 1);
    pcl::io::savePCDFileBinary((truth_dir / "tabletop.kinect.labels.pcd").string(), objects);
    const fs::path scored_file = dir_ / ("scored_" + method + ".json");
    const Result scored =
        run("--objects --repeat 0 --quiet --object-methods " + method + " --ground-truth " + quote(truth_dir.string()) +
            " --json " + quote(scored_file.string()) + " " + quote(kTabletop));
    ASSERT_EQ(scored.exit_code, 0) << scored.err;
    const nlohmann::json self = nlohmann::json::parse(readFile(scored_file))["scenes"][0]["methods"][method];
    EXPECT_EQ(self["ground_truth_objects"].get<std::size_t>(), ids.size()) << method;
    EXPECT_DOUBLE_EQ(self["object_iou"].get<double>(), 1.0) << method;
    EXPECT_DOUBLE_EQ(self["objects_found"].get<double>(), 1.0) << method;
    EXPECT_DOUBLE_EQ(self["under"].get<double>(), 0.0) << method;
    EXPECT_DOUBLE_EQ(self["over"].get<double>(), 0.0) << method;
    EXPECT_DOUBLE_EQ(self["support_in_objects"].get<double>(), 0.0) << method;
  }
  // Another program's objects (--labels, <stem>.objects.pcd): the written objects scored again
  // give the method's scores, without a time.
  const Result labelled = run("--objects --repeat 0 --quiet --object-methods pcl_organized --labels mine=" +
                              quote((objects_dir / "pcl_organized").string()) + " --json " + quote(json_file.string()) +
                              " " + quote(kTabletop));
  ASSERT_EQ(labelled.exit_code, 0) << labelled.err;
  EXPECT_NE(labelled.out.find("\n| mine | 1 | - | - |"), std::string::npos) << labelled.out;
  const nlohmann::json both = nlohmann::json::parse(readFile(json_file))["scenes"][0]["methods"];
  for (const std::string score : {"objects", "object_iou", "objects_found", "under", "over", "support_in_objects"}) {
    EXPECT_EQ(both["mine"][score], both["pcl_organized"][score]) << score;
  }
  const Result missing =
      run("--objects --repeat 0 --quiet --object-methods pcl_organized --labels mine=" + quote(dir_.string()) + " " +
          quote(kTabletop));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("tabletop.kinect.objects.pcd"), std::string::npos) << missing.err;
}

TEST_F(PcdCompare, ObjectOptionsAreRefusedWithThePlaneComparison) {
  expectUsageError(run("--objects --methods omps " + quote(kStaircase)), "pcd_compare", "--methods");
  expectUsageError(run("--objects --png " + quote((dir_ / "png").string()) + " " + quote(kStaircase)), "pcd_compare",
                   "--png");
  expectUsageError(run("--write-objects " + quote((dir_ / "o").string()) + " " + quote(kStaircase)), "pcd_compare",
                   "--objects");
  expectUsageError(run("--objects --object-methods cpc " + quote(kStaircase)), "pcd_compare", "--object-methods");
  expectUsageError(run("--objects --labels lccp=" + quote(dir_.string()) + " " + quote(kStaircase)), "pcd_compare",
                   "lccp is already a method");
  EXPECT_FALSE(fs::exists(dir_ / "o"));
  std::ofstream(dir_ / "file") << "not a directory";
  expectUsageError(run("--objects --write-objects " + quote((dir_ / "file").string()) + " " + quote(kStaircase)),
                   "pcd_compare", "is a file");
}

// A directory under an objects file's name is named as a directory, not reported missing; the
// configuration names the label files without a doubled '/'; a --write-objects file over a
// label file it reads is refused naming the flags of an --objects run.
TEST_F(PcdCompare, ObjectLabelsInADirectoryAreNamedAsSuch) {
  const fs::path lab = dir_ / "lab";
  fs::create_directories(lab / "tabletop.kinect.objects.pcd");
  const fs::path json_file = dir_ / "report.json";
  const Result result =
      run("--objects --repeat 0 --object-methods floodplane --labels mine=" + quote(lab.string() + "/") + " --json " +
          quote(json_file.string()) + " " + quote(kTabletop));
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.err.find((lab / "tabletop.kinect.objects.pcd").string() + " is a directory, not a label file"),
            std::string::npos)
      << result.err;
  const nlohmann::json report = nlohmann::json::parse(readFile(json_file));
  const std::string line = report["configuration"]["object method mine"].get<std::string>();
  EXPECT_NE(line.find((lab / "<stem>.objects.pcd").string()), std::string::npos) << line;
  EXPECT_EQ(line.find("//"), std::string::npos) << line;

  const fs::path written = dir_ / "written";
  fs::create_directories(written / "floodplane");
  std::ofstream(written / "floodplane" / "tabletop.kinect.objects.pcd") << "labels another run wrote";
  const Result over =
      run("--objects --repeat 0 --object-methods floodplane --labels mine=" + quote((written / "floodplane").string()) +
          " --write-objects " + quote(written.string()) + " " + quote(kTabletop));
  expectUsageError(over, "pcd_compare", "give --json or --write-objects another place");
  EXPECT_EQ(readFile(written / "floodplane" / "tabletop.kinect.objects.pcd"), "labels another run wrote");
}

}  // namespace
}  // namespace floodplane::test
