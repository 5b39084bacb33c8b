// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_segment's 3-D outputs. The snapshots are rendered for real, under xvfb-run (Debian's
// xvfb: Debian's VTK draws through X11 only, off screen too), from a bundled scene, and the
// images are checked against what the segmentation says: every plane in its palette colour,
// in the share of the picture it has in the label image, a white arrow along each plane's
// normal where the camera sees its centroid, and white nowhere else but the arrows' text.
// A machine that cannot render fails these tests, saying why; it does not skip them.
// The options' errors, and the one-line error without a display, need no rendering.

#include <gtest/gtest.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "floodplane/io/rgb_image.h"
#include "support/app_run.h"
#include "support/png_images.h"
#include "view/plane_scene.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;
using floodplane::view::CameraView;

const std::string kScene = std::string(FLOODPLANE_RENDERED_DIR) + "/boxes_on_floor.none.pcd";

std::vector<fs::path> filesIn(const fs::path& directory) {
  std::vector<fs::path> files;
  if (!fs::exists(directory)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(directory)) {
    if (entry.is_regular_file() && entry.path().filename().string()[0] != '.') files.push_back(entry.path());
  }
  return files;
}

using Rgb = std::array<std::uint8_t, 3>;

Rgb pixelAt(const floodplane::io::RgbImage& image, std::size_t column, std::size_t row) {
  const std::size_t i = (row * image.width + column) * 3;
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

// The lit white of the arrows (kArrowColour at 60-100 %): grey enough and bright. No plane's
// colour is (the palette's saturation is 0.6 or more), nor the unlabelled points' grey.
bool isArrowColour(const Rgb& c) {
  const auto [low, high] = std::minmax({c[0], c[1], c[2]});
  return low >= 140 && high - low <= 8;
}

// What the segmentation says about a plane, and where its arrow ends.
struct Plane {
  std::uint32_t id = 0;
  std::size_t inliers = 0;
  Eigen::Vector3d centroid;
  Eigen::Vector3d tip;
};

// The segmentation pcd_segment wrote into `out` for the input `name`: its labels, its planes
// (from the JSON report, sizes from the labelled points) and the cloud, for the cameras.
struct Written {
  pcl::PointCloud<pcl::PointXYZL> labelled;
  std::vector<Plane> planes;
  floodplane::view::PlaneScene scene;
};

Written readWritten(const fs::path& out, const std::string& name) {
  Written written;
  if (pcl::io::loadPCDFile((out / (name + ".labels.pcd")).string(), written.labelled) != 0) {
    throw std::runtime_error("no label cloud for " + name);
  }
  auto points = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::copyPointCloud(written.labelled, *points);
  written.scene.cloud = points;
  const float longest_arrow = floodplane::view::longestArrow(*points);
  const nlohmann::json report = nlohmann::json::parse(readFile(out / (name + ".planes.json")));
  for (const auto& record : report["planes"]) {
    floodplane::view::PlaneMarker marker;
    marker.id = record["id"];
    marker.inliers = record["inliers"];
    marker.centroid = Eigen::Vector3f(record["centroid"][0], record["centroid"][1], record["centroid"][2]);
    marker.normal = Eigen::Vector3f(record["normal"][0], record["normal"][1], record["normal"][2]);
    double squares = 0.0;
    for (const auto& p : written.labelled) {
      if (p.label == marker.id) squares += (p.getVector3fMap() - marker.centroid).cast<double>().squaredNorm();
    }
    marker.size = static_cast<float>(std::sqrt(squares / static_cast<double>(marker.inliers)));
    written.planes.push_back({marker.id, marker.inliers, marker.centroid.cast<double>(),
                              floodplane::view::arrowTip(marker, longest_arrow).cast<double>()});
  }
  return written;
}

// The pixels the arrow of `plane` covers on screen: its projected axis, thickened by `margin`.
std::vector<std::pair<int, int>> arrowPixels(const Plane& plane, const floodplane::view::Camera& camera,
                                             const floodplane::io::RgbImage& image, int margin) {
  std::vector<std::pair<int, int>> pixels;
  const int width = static_cast<int>(image.width), height = static_cast<int>(image.height);
  for (int step = 0; step <= 20; ++step) {
    const Eigen::Vector3d point = plane.centroid + (plane.tip - plane.centroid) * (step / 20.0);
    const auto pixel = floodplane::view::projectToPixel(camera, point, width, height);
    if (!pixel) continue;
    const int u = static_cast<int>(std::lround(pixel->x())), v = static_cast<int>(std::lround(pixel->y()));
    for (int dv = -margin; dv <= margin; ++dv)
      for (int du = -margin; du <= margin; ++du)
        if (u + du >= 0 && u + du < width && v + dv >= 0 && v + dv < height) pixels.emplace_back(u + du, v + dv);
  }
  std::sort(pixels.begin(), pixels.end());
  pixels.erase(std::unique(pixels.begin(), pixels.end()), pixels.end());
  return pixels;
}

std::size_t arrowColouredAmong(const floodplane::io::RgbImage& image, const std::vector<std::pair<int, int>>& pixels) {
  std::size_t count = 0;
  for (const auto& [u, v] : pixels) count += isArrowColour(pixelAt(image, u, v)) ? 1 : 0;
  return count;
}

// Arrow-coloured pixels neither on an arrow (within `margin`) nor where its text may be (the
// text goes beyond the tip, to any side: a box 130 pixels either side of the tip and 30 above
// and below holds it): they would be white drawn where nothing white is.
std::size_t strayArrowColoured(const floodplane::io::RgbImage& image, const std::vector<Plane>& planes,
                               const floodplane::view::Camera& camera, int margin) {
  std::vector<std::uint8_t> allowed(image.width * image.height, 0);
  const int width = static_cast<int>(image.width), height = static_cast<int>(image.height);
  for (const Plane& plane : planes) {
    for (const auto& [u, v] : arrowPixels(plane, camera, image, margin)) allowed[v * image.width + u] = 1;
    const auto tip = floodplane::view::projectToPixel(camera, plane.tip, width, height);
    if (!tip) continue;
    for (int v = static_cast<int>(tip->y()) - 30; v <= static_cast<int>(tip->y()) + 30; ++v)
      for (int u = static_cast<int>(tip->x()) - 130; u <= static_cast<int>(tip->x()) + 130; ++u)
        if (u >= 0 && u < width && v >= 0 && v < height) allowed[v * image.width + u] = 1;
  }
  std::size_t stray = 0;
  for (std::size_t v = 0; v < image.height; ++v)
    for (std::size_t u = 0; u < image.width; ++u)
      if (!allowed[v * image.width + u] && isArrowColour(pixelAt(image, u, v))) ++stray;
  return stray;
}

std::map<Rgb, std::size_t> colourCounts(const floodplane::io::RgbImage& image) {
  std::map<Rgb, std::size_t> counts;
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) {
    ++counts[{image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]}];
  }
  return counts;
}

// Finite points per label.
std::map<std::uint32_t, std::size_t> labelCounts(const pcl::PointCloud<pcl::PointXYZL>& labelled) {
  std::map<std::uint32_t, std::size_t> counts;
  for (const auto& p : labelled) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) ++counts[p.label];
  }
  return counts;
}

class PcdSegmentView : public AppTest {
 protected:
  void SetUp() override {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    AppTest::SetUp();
  }

  // Runs pcd_segment with `arguments`, after the shell text `prefix` (env, xvfb-run).
  Result run(const std::vector<std::string>& arguments, const std::string& prefix = "") const {
    return runShell(prefix + commandLine(PCD_SEGMENT_BINARY, arguments));
  }

  // Runs pcd_segment on a virtual X display of its own. Fails the test (does not skip it)
  // where xvfb-run is missing: rendering is what these tests are for.
  Result runWithDisplay(const std::vector<std::string>& arguments) const {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) {
      ADD_FAILURE() << "xvfb-run is not installed (Debian package xvfb; scripts/install_deps.sh installs it): "
                       "the snapshots cannot be rendered on this machine";
      return {};
    }
    return run(arguments, xvfbRun());
  }
};

// From the sensor's own viewpoint, as large as the grid, the snapshot is the label image in
// 3-D: each plane's colour covers the share of the picture its label has there (less what
// arrows and text cover), and each arrow is drawn where the plane's centroid is.
TEST_F(PcdSegmentView, SensorSnapshotShowsEachPlaneInItsColourShareAndItsArrow) {
  const fs::path snapshot = path("sensor.png");
  const Result result = runWithDisplay({kScene, "-o", path("out").string(), "--json", "--snapshot", snapshot.string(),
                                        "--snapshot-size", "640x480", "--snapshot-camera", "sensor"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const floodplane::io::RgbImage image = readPng(snapshot);
  ASSERT_EQ(image.width, 640u);
  ASSERT_EQ(image.height, 480u);
  const Written written = readWritten(path("out"), "boxes_on_floor.none");
  ASSERT_EQ(written.labelled.size(), image.width * image.height);

  const std::map<Rgb, std::size_t> colours = colourCounts(image);
  const double pixels = static_cast<double>(image.width * image.height);
  std::size_t planes_checked = 0;
  for (const auto& [label, count] : labelCounts(written.labelled)) {
    const double share = static_cast<double>(count) / pixels;
    if (share < 0.005) continue;  // small planes are mostly hidden by their arrows and text
    const auto found = colours.find(floodplane::view::pointColour(label));
    const double shown = found == colours.end() ? 0.0 : static_cast<double>(found->second) / pixels;
    EXPECT_NEAR(shown, share, 0.15 * share + 0.003) << "label " << label;
    planes_checked += label != 0 ? 1 : 0;
  }
  EXPECT_GE(planes_checked, 8u);

  const floodplane::view::Camera camera = floodplane::view::sceneCamera(written.scene, CameraView::sensor, 4.0 / 3.0);
  for (const Plane& plane : written.planes) {
    EXPECT_GE(arrowColouredAmong(image, arrowPixels(plane, camera, image, 2)), 4u) << "plane " << plane.id;
  }
  EXPECT_LT(strayArrowColoured(image, written.planes, camera, 6), image.width * image.height / 1000);
}

// The default snapshot, from above and to the right: every large plane shows in its colour
// and with its arrow where the camera projects it, and the same input gives the same bytes.
TEST_F(PcdSegmentView, ObliqueSnapshotShowsThePlanesWithTheirArrowsTheSameEveryTime) {
  const Result result =
      runWithDisplay({kScene, "-o", path("out").string(), "--json", "--snapshot", path("first.png").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const floodplane::io::RgbImage image = readPng(path("first.png"));
  ASSERT_EQ(image.width, 800u);  // the default size
  ASSERT_EQ(image.height, 600u);
  const Written written = readWritten(path("out"), "boxes_on_floor.none");

  const std::map<Rgb, std::size_t> colours = colourCounts(image);
  const double pixels = static_cast<double>(image.width * image.height);
  const double grid = static_cast<double>(written.labelled.size());
  for (const auto& [label, count] : labelCounts(written.labelled)) {
    if (static_cast<double>(count) < 0.01 * grid) continue;
    const auto found = colours.find(floodplane::view::pointColour(label));
    ASSERT_NE(found, colours.end()) << "label " << label;
    EXPECT_GT(static_cast<double>(found->second) / pixels, 0.2 * static_cast<double>(count) / grid)
        << "label " << label;
  }
  const floodplane::view::Camera camera = floodplane::view::sceneCamera(
      written.scene, CameraView::oblique, static_cast<double>(image.width) / static_cast<double>(image.height));
  for (const Plane& plane : written.planes) {
    EXPECT_GE(arrowColouredAmong(image, arrowPixels(plane, camera, image, 2)), 4u) << "plane " << plane.id;
  }
  EXPECT_LT(strayArrowColoured(image, written.planes, camera, 6), image.width * image.height / 1000);

  ASSERT_EQ(runWithDisplay({kScene, "-o", path("out").string(), "--snapshot", path("second.png").string()}).exit_code,
            0);
  EXPECT_TRUE(readFile(path("first.png")) == readFile(path("second.png")));
}

// A batch writes <name>.snapshot.png for each input beside its other outputs, the same drawn
// one input at a time as several at once (on whichever thread reports an input).
TEST_F(PcdSegmentView, BatchWritesASnapshotPerInputInTheOutputDirectory) {
  fs::create_directories(path("in"));
  fs::copy_file(kScene, path("in/a.pcd"));
  fs::copy_file(std::string(FLOODPLANE_RENDERED_DIR) + "/staircase.kinect.pcd", path("in/b.pcd"));
  fs::copy_file(kScene, path("in/c.pcd"));
  const Result result = runWithDisplay({path("in").string(), "-o", path("out").string(), "--quiet", "--snapshot",
                                        "--snapshot-size", "160x120", "-j", "3"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const Result serial = runWithDisplay({path("in").string(), "-o", path("serial").string(), "--quiet", "--snapshot",
                                        "--snapshot-size", "160x120", "-j", "1"});
  ASSERT_EQ(serial.exit_code, 0) << serial.err;
  for (const std::string name : {"a", "b", "c"}) {
    const floodplane::io::RgbImage image = readPng(path("out/" + name + ".snapshot.png"));
    EXPECT_EQ(image.width, 160u);
    EXPECT_EQ(image.height, 120u);
    EXPECT_GT(colourCounts(image).size(), 3u) << name << ": not a blank image";
    EXPECT_TRUE(readFile(path("out/" + name + ".snapshot.png")) == readFile(path("serial/" + name + ".snapshot.png")))
        << name;
  }
  // A single output file: the snapshot takes its stem.
  ASSERT_EQ(runWithDisplay({kScene, "-o", path("one/scene.pcd").string(), "--snapshot", "--snapshot-size", "64x48"})
                .exit_code,
            0);
  EXPECT_TRUE(fs::exists(path("one/scene.snapshot.png")));
}

TEST_F(PcdSegmentView, SnapshotThatCannotBeWrittenIsAnErrorNamingTheFileAndLeavesNothing) {
  const Result result =
      runWithDisplay({kScene, "-o", path("out").string(), "--snapshot", path("missing/dir/s.png").string()});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_TRUE(contains(result.err, "missing/dir/s.png")) << result.err;
  EXPECT_FALSE(fs::exists(path("missing")));
}

// Without a display nothing can be drawn: one line that says why and what to do, exit 1,
// before any work (no outputs).
TEST_F(PcdSegmentView, WithoutADisplaySaysSoOnOneLineAndWritesNothing) {
  for (const std::string option : {"--snapshot", "--view"}) {
    const Result result = run({kScene, "-o", path("out").string(), option}, "env -u DISPLAY ");
    EXPECT_EQ(result.exit_code, 1) << option;
    EXPECT_EQ(lineCount(result.err), 1u) << option << ": " << result.err;
    EXPECT_TRUE(contains(result.err, "DISPLAY is not set")) << result.err;
    EXPECT_TRUE(contains(result.err, "xvfb-run")) << result.err;
    EXPECT_TRUE(filesIn(path("out")).empty()) << option;
  }
  const Result unreachable = run({kScene, "-o", path("out").string(), "--snapshot"}, "DISPLAY=:4321 ");
  EXPECT_EQ(unreachable.exit_code, 1);
  EXPECT_EQ(lineCount(unreachable.err), 1u) << unreachable.err;
  EXPECT_TRUE(contains(unreachable.err, "cannot open the X display ':4321'")) << unreachable.err;
  EXPECT_TRUE(filesIn(path("out")).empty());
}

// Options that contradict each other or carry bad values are usage errors (exit 2), found
// before anything is read, drawn or written.
TEST_F(PcdSegmentView, RefusesViewOptionsThatCannotWork) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{kScene, kScene, "-o", path("out").string(), "--view"}, "--view"},
      {{kScene, kScene, "-o", path("out").string(), "--snapshot", path("s.png").string()}, "--snapshot"},
      {{kScene, "-o", path("out").string(), "--snapshot", path("s.jpg").string()}, "--snapshot"},
      {{kScene, "-o", path("out").string(), "--snapshot", "--snapshot-size", "8x8"}, "--snapshot-size"},
      {{kScene, "-o", path("out").string(), "--snapshot", "--snapshot-size", "640"}, "--snapshot-size"},
      {{kScene, "-o", path("out").string(), "--snapshot", "--snapshot-camera", "top"}, "--snapshot-camera"},
      {{kScene, "-o", path("out").string(), "--snapshot-size", "640x480"}, "--snapshot-size"},
  };
  for (const auto& [arguments, flag] : bad) {
    const Result result = run(arguments, "env -u DISPLAY ");
    std::string shown;
    for (const auto& argument : arguments) shown += " " + argument;
    SCOPED_TRACE(shown);
    expectUsageError(result, "pcd_segment", flag);
    EXPECT_TRUE(filesIn(path("out")).empty()) << shown;
  }
}

}  // namespace
}  // namespace floodplane::test
