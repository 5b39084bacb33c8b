// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_compare with labels other programs wrote (--labels NAME=DIR, --ground-truth DIR) and on
// 16-bit depth PNG images (--intrinsics): the real binaries, on scenes rendered at build time
// and a depth image written here.

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "floodplane/io/depth_camera.h"
#include "floodplane/io/depth_png.h"
#include "support/app_process.h"
#include "support/app_run.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;

const std::string kScenes = PCD_COMPARE_SCENE_DIR;
const std::vector<std::string> kStems = {"far_wall.none", "staircase.none", "tabletop.kinect"};

// A Kinect's f = 525 at 160 x 120.
const floodplane::io::DepthCamera kCamera{131.25, 131.25, 79.5, 59.5, 1000.0};
const std::string kIntrinsics = "131.25,131.25,79.5,59.5";

// A wall at 2 m (label 1) and a floor 0.5 m below the camera (label 2) in millimetres, a block
// of pixels without a return (label 0).
struct DepthScene {
  floodplane::io::DepthImage depth;
  floodplane::io::DepthImage labels;  // the ground truth, as a 16-bit label image
};

DepthScene twoPlaneDepthScene() {
  DepthScene scene;
  scene.depth.width = scene.labels.width = 160;
  scene.depth.height = scene.labels.height = 120;
  for (int v = 0; v < 120; ++v) {
    for (int u = 0; u < 160; ++u) {
      const double ry = (v - kCamera.cy) / kCamera.fy;
      const bool floor = ry > 0.0 && 0.5 / ry < 2.0;
      const bool hole = v >= 10 && v < 14 && u >= 20 && u < 24;
      scene.depth.depth.push_back(hole ? 0
                                       : static_cast<std::uint16_t>(std::lround((floor ? 0.5 / ry : 2.0) * 1000.0)));
      scene.labels.depth.push_back(hole ? 0 : floor ? 2 : 1);
    }
  }
  return scene;
}

class PcdCompareLabels : public AppTest {
 protected:
  Result compare(const std::vector<std::string>& arguments) const {
    std::vector<std::string> all = {"--quiet", "--methods", "floodplane", "--repeat", "0"};
    all.insert(all.end(), arguments.begin(), arguments.end());
    return runShell("exec " + commandLine(PCD_COMPARE_BINARY, all));
  }
  Result segment(const std::vector<std::string>& arguments) const {
    return runShell("exec " + commandLine(PCD_SEGMENT_BINARY, arguments));
  }
  std::string scene(const std::string& stem) const { return kScenes + "/" + stem + ".pcd"; }
  nlohmann::json report() const { return nlohmann::json::parse(readFile(path("report.json"))); }
};

// Labels as a 16-bit grey PNG <stem>.png, from pcd_segment's label PCD.
void writeLabelPng(const fs::path& label_pcd, const fs::path& png) {
  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(label_pcd.string(), labelled), 0);
  floodplane::io::DepthImage image;
  image.width = static_cast<int>(labelled.width);
  image.height = static_cast<int>(labelled.height);
  for (const auto& point : labelled) {
    ASSERT_LT(point.label, 65536u);
    image.depth.push_back(static_cast<std::uint16_t>(point.label));
  }
  floodplane::io::writeDepthPng(png.string(), image);
}

// The test: pcd_segment's own output, scored through --labels as a method of its own,
// gets exactly the built-in floodplane row's scores, from its label PCDs and from label PNGs.
TEST_F(PcdCompareLabels, ScoresPcdSegmentsOwnOutputAsTheBuiltInFloodplaneRow) {
  std::vector<std::string> inputs;
  for (const std::string& stem : kStems) inputs.push_back(scene(stem));
  std::vector<std::string> arguments = inputs;
  arguments.insert(arguments.end(), {"-o", path("segmented").string(), "--quiet"});
  ASSERT_EQ(segment(arguments).exit_code, 0);
  fs::create_directory(path("pngs"));
  for (const std::string& stem : kStems) {
    writeLabelPng(path("segmented") / (stem + ".labels.pcd"), path("pngs") / (stem + ".png"));
  }
  arguments = inputs;
  arguments.insert(arguments.end(), {"--labels", "mine=" + path("segmented").string(), "--labels",
                                     "mine_png=" + path("pngs").string(), "--json", path("report.json").string()});
  const Result result = compare(arguments);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json json = report();
  ASSERT_EQ(json["scenes"].size(), 3u);
  for (const auto& scene : json["scenes"]) {
    SCOPED_TRACE(scene["name"].get<std::string>());
    const auto& builtin = scene["methods"]["floodplane"];
    for (const std::string name : {"mine", "mine_png"}) {
      const auto& read = scene["methods"][name];
      ASSERT_TRUE(read.contains("mean_iou")) << name;
      EXPECT_EQ(read["mean_iou"], builtin["mean_iou"]) << name;
      EXPECT_EQ(read["weighted_iou"], builtin["weighted_iou"]) << name;
      EXPECT_EQ(read["hoover"], builtin["hoover"]) << name;
      EXPECT_EQ(read["per_plane"], builtin["per_plane"]) << name;
      EXPECT_EQ(read["planes"], builtin["planes"]) << name;
      EXPECT_TRUE(read["median_ms"].is_null()) << name << ": not run here, no time";
    }
  }
  EXPECT_EQ(json["means"]["mine"]["mean_iou"], json["means"]["floodplane"]["mean_iou"]);
  EXPECT_GT(json["means"]["mine"]["mean_iou"].get<double>(), 0.9);
  // A row of the table like a built-in method's, its time "-".
  EXPECT_TRUE(contains(result.out, "| mine | 3 | - | - | - |")) << result.out;
  EXPECT_TRUE(contains(result.out, "| mine_png | 3 | - | - | - |")) << result.out;
}

// A missing, mis-sized or unreadable label file is that input's problem: said, the method
// has no row for it, the batch goes on, and the exit code says something was missing.
TEST_F(PcdCompareLabels, ReportsABadLabelFileForItsInputAndGoesOn) {
  ASSERT_EQ(segment({scene("staircase.none"), "-o", path("labels").string(), "-q"}).exit_code, 0);
  // far_wall's labels: another scene's, of another size.
  pcl::PointCloud<pcl::PointXYZL> small(4, 3);
  ASSERT_EQ(pcl::io::savePCDFileBinary(path("labels/far_wall.none.labels.pcd").string(), small), 0);
  writeFile(path("labels/tabletop.kinect.png"), "not a png");
  const Result result = compare({scene("far_wall.none"), scene("staircase.none"), scene("tabletop.kinect"), "--labels",
                                 "mine=" + path("labels").string(), "--json", path("report.json").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_TRUE(contains(result.err, scene("far_wall.none") +
                                       ": --labels mine: " + path("labels/far_wall.none.labels.pcd").string() +
                                       ": 4x3 labels for the input's 320x240 grid"))
      << result.err;
  EXPECT_TRUE(contains(result.err, scene("tabletop.kinect") + ": --labels mine: " +
                                       path("labels/tabletop.kinect.png").string() + ": not a PNG file"))
      << result.err;
  EXPECT_TRUE(contains(result.err, "2 label files missing or unusable")) << result.err;
  const nlohmann::json json = report();
  ASSERT_EQ(json["scenes"].size(), 3u);
  EXPECT_EQ(json["means"]["mine"]["scenes"], 1);
  EXPECT_EQ(json["means"]["floodplane"]["scenes"], 3);
  EXPECT_EQ(json["label_problems"].size(), 2u);
  // No file at all for an input.
  fs::remove(path("labels/tabletop.kinect.png"));
  const Result missing = compare({scene("tabletop.kinect"), "--labels", "mine=" + path("labels").string()});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_TRUE(contains(missing.err, "--labels mine: no " + path("labels/tabletop.kinect.labels.pcd").string() + " or " +
                                        path("labels/tabletop.kinect.png").string()))
      << missing.err;
  // Both files for one input: which one is meant is not guessed.
  fs::copy_file(path("labels/staircase.none.labels.pcd"), path("labels/tabletop.kinect.labels.pcd"));
  writeFile(path("labels/tabletop.kinect.png"), "x");
  const Result both = compare({scene("tabletop.kinect"), "--labels", "mine=" + path("labels").string()});
  EXPECT_EQ(both.exit_code, 1);
  EXPECT_TRUE(contains(both.err, "keep one")) << both.err;
}

TEST_F(PcdCompareLabels, RefusesBadLabelsAndGroundTruthOptionsBeforeAnyWork) {
  fs::create_directory(path("dir"));
  const std::string dir = path("dir").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{"--labels", "mine"}, "--labels mine: give NAME=DIR"},
      {{"--labels", "=" + dir}, "the name must be one word"},
      {{"--labels", "my method=" + dir}, "the name must be one word"},
      {{"--labels", "a|b=" + dir}, "the name must be one word"},
      {{"--labels", "mine="}, "no directory after '='"},
      {{"--labels", "omps=" + dir}, "omps is already a method pcd_compare runs"},
      {{"--labels", "mine=" + dir, "--labels", "mine=" + dir}, "mine is already the name of another --labels"},
      {{"--labels", "mine=" + path("none").string()}, path("none").string() + " is not a directory"},
      {{"--ground-truth", path("none").string()}, "--ground-truth " + path("none").string() + " is not a directory"},
      {{"--png", path("pictures.png").string()}, "--png " + path("pictures.png").string() + " looks like a .png file"},
      {{"--png3d", path("pictures.png").string()}, "--png3d"},
      {{"--json", dir}, "--json " + dir + " is a directory"},
      {{"--json", path("report.txt").string()}, "--json " + path("report.txt").string() + " looks like a .txt file"},
  };
  for (const auto& [option, message] : bad) {
    std::vector<std::string> arguments = {scene("staircase.none")};
    arguments.insert(arguments.end(), option.begin(), option.end());
    SCOPED_TRACE(message);
    const Result result = compare(arguments);
    expectUsageError(result, "pcd_compare", message);
    EXPECT_TRUE(result.out.empty()) << result.out;
  }
  EXPECT_FALSE(fs::exists(path("pictures.png")));
}

// Depth images: back-projected with --intrinsics, scored against --ground-truth's label images;
// without ground truth, time and planes only.
TEST_F(PcdCompareLabels, ComparesDepthImagesAndScoresThemAgainstGroundTruthFiles) {
  const DepthScene depth = twoPlaneDepthScene();
  fs::create_directories(path("depth"));
  fs::create_directories(path("truth"));
  floodplane::io::writeDepthPng(path("depth/frame.png").string(), depth.depth);
  floodplane::io::writeDepthPng(path("truth/frame.png").string(), depth.labels);
  const Result scored = compare({path("depth").string(), "--intrinsics", kIntrinsics, "--ground-truth",
                                 path("truth").string(), "--json", path("report.json").string()});
  ASSERT_EQ(scored.exit_code, 0) << scored.err;
  nlohmann::json json = report();
  ASSERT_EQ(json["scenes"].size(), 1u);
  EXPECT_EQ(json["scenes"][0]["name"], "frame");
  EXPECT_EQ(json["scenes"][0]["width"], 160);
  EXPECT_TRUE(json["scenes"][0]["ground_truth"].get<bool>());
  const auto& floodplane = json["scenes"][0]["methods"]["floodplane"];
  EXPECT_EQ(floodplane["ground_truth_planes"], 2);
  EXPECT_EQ(floodplane["hoover"]["correct"], 2);
  EXPECT_GT(floodplane["mean_iou"].get<double>(), 0.95);
  EXPECT_TRUE(contains(scored.out, "mean IoU")) << scored.out;

  const Result unscored =
      compare({path("depth/frame.png").string(), "--intrinsics", kIntrinsics, "--json", path("report.json").string()});
  ASSERT_EQ(unscored.exit_code, 0) << unscored.err;
  json = report();
  EXPECT_FALSE(json["scenes"][0]["ground_truth"].get<bool>());
  EXPECT_EQ(json["scenes"][0]["methods"]["floodplane"]["planes"], 2);
  EXPECT_FALSE(contains(unscored.out, "mean IoU")) << unscored.out;
  EXPECT_TRUE(contains(unscored.out, "| floodplane | 1 |")) << unscored.out;

  // An input without its ground-truth file: compared without scores, and said.
  fs::remove(path("truth/frame.png"));
  const Result lacking = compare({path("depth").string(), "--intrinsics", kIntrinsics, "--ground-truth",
                                  path("truth").string(), "--json", path("report.json").string()});
  EXPECT_EQ(lacking.exit_code, 1);
  EXPECT_TRUE(contains(lacking.err, "--ground-truth: no " + path("truth/frame.labels.pcd").string())) << lacking.err;
  EXPECT_FALSE(report()["scenes"][0]["ground_truth"].get<bool>());

  // --labels pointing at the inputs' own directory: a depth image is not its own labels.
  const Result itself =
      compare({path("depth").string(), "--intrinsics", kIntrinsics, "--labels", "mine=" + path("depth").string()});
  EXPECT_EQ(itself.exit_code, 1);
  EXPECT_TRUE(contains(itself.err, "is the input itself")) << itself.err;
}

// --png's comparison images are named <scene>.png: into the depth images' own folder, or the
// ground truth's, they would overwrite the frames or their labels. Refused before any work,
// naming both files; every file stays as it was.
TEST_F(PcdCompareLabels, RefusesImagesOverTheDepthImagesOrTheGroundTruthItReads) {
  const DepthScene scene = twoPlaneDepthScene();
  fs::create_directories(path("depth"));
  fs::create_directories(path("truth"));
  floodplane::io::writeDepthPng(path("depth/frame.png").string(), scene.depth);
  floodplane::io::writeDepthPng(path("truth/frame.png").string(), scene.labels);
  const std::string depth = readFile(path("depth/frame.png"));
  const std::string truth = readFile(path("truth/frame.png"));
  const std::string frame = path("depth/frame.png").string();
  const Result over_input =
      compare({path("depth").string(), "--intrinsics", kIntrinsics, "--png", path("depth").string()});
  expectUsageError(over_input, "pcd_compare", "the output " + frame + " would overwrite the input " + frame);
  const Result over_truth = compare({path("depth").string(), "--intrinsics", kIntrinsics, "--ground-truth",
                                     path("truth").string(), "--png3d", path("truth").string()});
  expectUsageError(over_truth, "pcd_compare",
                   "the output " + path("truth/frame.png").string() + " would overwrite the input " +
                       path("truth/frame.png").string());
  const Result json_over_input =
      compare({frame, "--intrinsics", kIntrinsics, "--json", path("depth/frame.json").string()});
  EXPECT_EQ(json_over_input.exit_code, 0) << json_over_input.err;
  fs::create_symlink(frame, path("report.json"));
  expectUsageError(compare({frame, "--intrinsics", kIntrinsics, "--json", path("report.json").string()}), "pcd_compare",
                   "the output " + path("report.json").string() + " would overwrite the input " + frame);
  EXPECT_TRUE(readFile(path("depth/frame.png")) == depth) << "the depth image changed";
  EXPECT_TRUE(readFile(path("truth/frame.png")) == truth) << "the ground truth changed";
  EXPECT_EQ(std::distance(fs::directory_iterator(path("depth")), fs::directory_iterator()), 2)
      << "frame.png, frame.json";
}

// A file name that is not UTF-8: --json's report is valid JSON, each ill-formed part of the
// name written as U+FFFD (floodplane/io/json_text.h: pcd_segment's rule, and Python's "replace").
TEST_F(PcdCompareLabels, JsonOfANameThatIsNotUtf8IsValidWithTheBadBytesReplaced) {
  fs::create_directories(path("depth"));
  const std::string frame = path("depth/caf\xe9.png").string();
  floodplane::io::writeDepthPng(frame, twoPlaneDepthScene().depth);
  const Result result = compare({frame, "--intrinsics", kIntrinsics, "--json", path("report.json").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  nlohmann::json json;
  ASSERT_NO_THROW(json = report());
  EXPECT_EQ(json["scenes"][0]["file"], path("depth/caf\xef\xbf\xbd.png").string());
  EXPECT_EQ(json["scenes"][0]["name"], "caf\xef\xbf\xbd");
}

// Ctrl-C (SIGINT) or SIGTERM while the comparison images are written: no temporary left, the
// one-line message, the end by the signal (status 130 or 143), and no report.
TEST_F(PcdCompareLabels, InterruptRemovesTheTemporariesAndEndsByTheSignal) {
  fs::create_directories(path("in"));
  for (int i = 0; i < 60; ++i)
    fs::create_symlink(scene("tabletop.kinect"), path("in/f" + std::to_string(100 + i) + ".pcd"));
  for (const int signal_number : {SIGINT, SIGTERM}) {
    const std::string name = signal_number == SIGINT ? "SIGINT" : "SIGTERM";
    SCOPED_TRACE(name);
    const fs::path images = path("images_" + name);
    AppProcess app(PCD_COMPARE_BINARY,
                   {path("in").string(), "--quiet", "--methods", "floodplane,omps", "--repeat", "0", "--png",
                    images.string(), "--json", path("report.json").string()},
                   path("stdout"), path("stderr"));
    ASSERT_TRUE(app.running());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (app.running() && !fs::exists(images / "f101.png") && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    app.signal(signal_number);
    const std::optional<int> exit_code = app.waitFor(std::chrono::seconds(60));
    ASSERT_TRUE(exit_code.has_value()) << "still running 60 s after " << name;
    EXPECT_EQ(*exit_code, 128 + signal_number);
    EXPECT_TRUE(app.endedBySignal());
    EXPECT_EQ(readFile(path("stderr")), "pcd_compare: interrupted by " + name + ": unfinished outputs removed\n");
    std::size_t written = 0;
    for (const auto& entry : fs::directory_iterator(images)) {
      EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
      ++written;
    }
    EXPECT_GE(written, 2u);
    EXPECT_LT(written, 60u) << "the signal came after the run was done";
    EXPECT_FALSE(fs::exists(path("report.json")));
  }
}

TEST_F(PcdCompareLabels, DepthImagesWithoutIntrinsicsAreAUsageError) {
  fs::create_directories(path("depth"));
  floodplane::io::writeDepthPng(path("depth/frame.png").string(), twoPlaneDepthScene().depth);
  expectUsageError(compare({path("depth/frame.png").string()}), "pcd_compare", "needs --intrinsics fx,fy,cx,cy");
  expectUsageError(compare({path("depth").string()}), "pcd_compare", "--intrinsics is missing");
  expectUsageError(compare({path("depth").string(), "--intrinsics", "0,1,2,3"}), "pcd_compare",
                   "--intrinsics fx,fy,cx,cy: fx must be");
}

}  // namespace
}  // namespace floodplane::test
