// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_compare --png3d: the comparison's panels rendered in 3-D, under xvfb-run (Debian's VTK
// draws through X11 only), checked against the scene's ground truth; and its one-line error
// without a display. A machine that cannot render fails, saying why; it does not skip.

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "floodplane/io/rgb_image.h"
#include "support/app_run.h"
#include "support/png_images.h"
#include "view/plane_scene.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;

const std::string kStaircase = std::string(PCD_COMPARE_SCENE_DIR) + "/staircase.none.pcd";
constexpr std::size_t kWidth = 320;  // the test scenes' grid
constexpr std::size_t kHeight = 240;
constexpr std::size_t kPanelGap = 4;
constexpr std::size_t kTitleStrip = 7 * 2 + 2 * 4;  // the 5x7 font at scale 2 and its margins

using Rgb = std::array<std::uint8_t, 3>;

// Pixel counts by colour in panel `k` (below its title strip).
std::map<Rgb, std::size_t> panelColours(const floodplane::io::RgbImage& image, std::size_t k) {
  std::map<Rgb, std::size_t> counts;
  const std::size_t left = k * (kWidth + kPanelGap);
  for (std::size_t y = kTitleStrip; y < kTitleStrip + kHeight; ++y) {
    for (std::size_t x = left; x < left + kWidth; ++x) {
      const std::size_t i = (y * image.width + x) * 3;
      ++counts[{image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]}];
    }
  }
  return counts;
}

// The arrows' lit white (see plane_scene.h): grey enough and bright.
std::size_t arrowColoured(const std::map<Rgb, std::size_t>& colours) {
  std::size_t count = 0;
  for (const auto& [c, n] : colours) {
    const auto [low, high] = std::minmax({c[0], c[1], c[2]});
    if (low >= 140 && high - low <= 8) count += n;
  }
  return count;
}

class PcdComparePng3d : public AppTest {
 protected:
  // Runs pcd_compare with `arguments` (quoted where needed) after the shell text `prefix`.
  Result run(const std::string& arguments, const std::string& prefix = "") const {
    return runShell(prefix + quote(PCD_COMPARE_BINARY) + " " + arguments);
  }
};

TEST_F(PcdComparePng3d, RendersGroundTruthAndEachMethodInThreeDimensions) {
  ASSERT_EQ(std::system("command -v xvfb-run >/dev/null 2>&1"), 0)
      << "xvfb-run is not installed (Debian package xvfb; scripts/install_deps.sh installs it): --png3d cannot "
         "be rendered on this machine";
  const fs::path images = dir_ / "images";
  const Result outcome =
      run("--repeat 1 --quiet --methods floodplane,omps --png3d " + quote(images.string()) + " " + quote(kStaircase),
          xvfbRun());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const floodplane::io::RgbImage image = readPng(images / "staircase.none.png");
  // Ground truth, omps, floodplane: the layout of --png.
  ASSERT_EQ(image.width, 3 * kWidth + 2 * kPanelGap);
  ASSERT_EQ(image.height, kTitleStrip + kHeight);

  // Each large ground-truth plane that faces the camera shows in its colour (seen from above
  // and to the right, a plane covers another share of the picture than of the grid; one
  // seen edge-on, or from behind, may not show at all).
  pcl::PointCloud<pcl::PointXYZL> truth;
  ASSERT_EQ(pcl::io::loadPCDFile(kStaircase, truth), 0);
  auto points = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::copyPointCloud(truth, *points);
  std::vector<std::uint32_t> labels;
  for (const auto& p : truth) labels.push_back(std::isfinite(p.z) ? p.label : 0);
  floodplane::view::PlaneScene scene;
  scene.cloud = points;
  const floodplane::view::Camera camera =
      floodplane::view::sceneCamera(scene, floodplane::view::CameraView::oblique, double{kWidth} / kHeight);
  const std::map<Rgb, std::size_t> ground_truth = panelColours(image, 0);
  std::size_t facing_planes = 0;
  for (const auto& plane : floodplane::view::planeMarkersFromLabels(*points, labels, labels, truth.size() / 100)) {
    const Eigen::Vector3d to_camera = (camera.position - plane.centroid.cast<double>()).normalized();
    if (plane.normal.cast<double>().dot(to_camera) < 0.3) continue;
    ++facing_planes;
    const auto found = ground_truth.find(floodplane::view::pointColour(plane.id));
    ASSERT_NE(found, ground_truth.end()) << "ground-truth plane " << plane.id;
    EXPECT_GT(found->second, plane.inliers / 10) << "ground-truth plane " << plane.id;
  }
  EXPECT_GE(facing_planes, 4u);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::map<Rgb, std::size_t> colours = panelColours(image, k);
    EXPECT_GT(arrowColoured(colours), 50u) << "panel " << k << ": no arrows";
    EXPECT_GT(colours.size(), 5u) << "panel " << k << ": not a rendering";
  }
}

TEST_F(PcdComparePng3d, WithoutADisplaySaysSoOnOneLineBeforeAnyWork) {
  const fs::path images = dir_ / "images";
  const Result outcome = run(
      "--repeat 1 --methods floodplane --png3d " + quote(images.string()) + " " + quote(kStaircase), "env -u DISPLAY ");
  EXPECT_EQ(outcome.exit_code, 1);
  EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
  EXPECT_NE(outcome.err.find("xvfb-run"), std::string::npos) << outcome.err;
  EXPECT_TRUE(outcome.out.empty()) << outcome.out;
  EXPECT_FALSE(fs::exists(images));
}

}  // namespace
}  // namespace floodplane::test
