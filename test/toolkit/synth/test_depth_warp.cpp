// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The calibration warp (depth_warp.h): its peak and mean over the image, its dependence on the
// seed alone, the same warp at another resolution, bad amplitudes; then rendered frames: the
// points moved along their rays by exactly the warp, and a flat wall that with the warp
// deviates from its best-fit plane by about the amplitude and without it only by the noise.

#include "synth/depth_warp.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "synth/renderer.h"

namespace {

using namespace floodplane::synth;

// The peak of |w| and its mean over every pixel of `camera`.
struct Extent {
  double peak = 0.0;
  double mean = 0.0;
};

Extent extentOver(const DepthWarp& warp, const CameraIntrinsics& camera) {
  Extent extent;
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      extent.peak = std::max(extent.peak, std::abs(warp.at(u, v)));
      extent.mean += warp.at(u, v);
    }
  }
  extent.mean /= static_cast<double>(camera.width) * static_cast<double>(camera.height);
  return extent;
}

TEST(DepthWarp, PeaksAtTheAmplitudeWithMeanZeroOverTheImage) {
  for (const CameraIntrinsics& camera : {CameraIntrinsics{}, scannerIntrinsics()}) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const DepthWarp warp({0.003, seed}, camera);
      const Extent extent = extentOver(warp, camera);
      EXPECT_NEAR(extent.peak, 0.003, 1e-15) << "seed " << seed;
      EXPECT_NEAR(extent.mean, 0.0, 1e-15) << "seed " << seed;
    }
  }
}

TEST(DepthWarp, TheSeedAloneFixesTheShape) {
  const CameraIntrinsics camera;
  const DepthWarp first({0.002, 7}, camera);
  const DepthWarp again({0.002, 7}, camera);
  const DepthWarp other({0.002, 8}, camera);
  const DepthWarp larger({0.004, 7}, camera);
  double largest_difference = 0.0;
  for (int v = 0; v < camera.height; v += 5) {
    for (int u = 0; u < camera.width; u += 5) {
      ASSERT_EQ(first.at(u, v), again.at(u, v));
      ASSERT_NEAR(larger.at(u, v), 2.0 * first.at(u, v), 1e-15);  // the amplitude only scales it
      largest_difference = std::max(largest_difference, std::abs(first.at(u, v) - other.at(u, v)));
    }
  }
  EXPECT_GT(largest_difference, 0.0005);
}

// The warp is a function of the ray: the same camera at half the resolution gets the same
// warp where its pixels see the same rays (pixel (u, v) at 320 x 240 covers (2u, 2v) to
// (2u + 1, 2v + 1) at 640 x 480), up to the half-pixel step between the two grids' rays.
TEST(DepthWarp, TheSameCameraAtAnotherResolutionGetsAboutTheSameWarp) {
  const CameraIntrinsics full;
  const CameraIntrinsics half = full.scaledTo(320, 240);
  const DepthWarp warp_full({0.003, 3}, full);
  const DepthWarp warp_half({0.003, 3}, half);
  for (int v = 0; v < half.height; v += 7) {
    for (int u = 0; u < half.width; u += 7) {
      const double corners = (warp_full.at(2 * u, 2 * v) + warp_full.at(2 * u + 1, 2 * v) +
                              warp_full.at(2 * u, 2 * v + 1) + warp_full.at(2 * u + 1, 2 * v + 1)) /
                             4.0;
      ASSERT_NEAR(warp_half.at(u, v), corners, 0.02 * 0.003) << "pixel " << u << ", " << v;
    }
  }
}

TEST(DepthWarp, ZeroAmplitudeIsNoWarpAndBadAmplitudesAreRejected) {
  const CameraIntrinsics camera;
  const DepthWarp none({0.0, 5}, camera);
  EXPECT_EQ(extentOver(none, camera).peak, 0.0);
  EXPECT_THROW(DepthWarp({-0.001, 1}, camera), std::invalid_argument);
  EXPECT_THROW(DepthWarp({std::numeric_limits<double>::quiet_NaN(), 1}, camera), std::invalid_argument);
  EXPECT_THROW(DepthWarp({std::numeric_limits<double>::infinity(), 1}, camera), std::invalid_argument);
  // The renderer passes a bad amplitude on.
  Scene scene;
  scene.name = "test";
  scene.source = "test scene";
  scene.primitives = {
      {"wall", Rectangle{Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(0, 10, 0)}}};
  RenderSettings settings;
  settings.sensor = SensorModel::kinect;
  settings.warp.amplitude = -0.002;
  EXPECT_THROW(renderScene(scene, settings), std::invalid_argument);
}

// ---- Rendered frames ---------------------------------------------------------------------

Scene wallScene(const CameraIntrinsics& camera, double z) {
  Scene scene;
  scene.name = "test";
  scene.source = "test scene";
  scene.intrinsics = camera;
  scene.primitives = {
      {"wall", Rectangle{Eigen::Vector3d(0, 0, z), Eigen::Vector3d(20, 0, 0), Eigen::Vector3d(0, 20, 0)}}};
  return scene;
}

// Both sensor models without noise, steps, losses or a projector field narrower than the
// camera's: what is left is the exact depth and the warp.
RenderSettings noiselessSettings(SensorModel sensor) {
  RenderSettings settings;
  settings.sensor = sensor;
  settings.kinect.sigma_constant = 0.0;
  settings.kinect.sigma_quadratic = 0.0;
  settings.kinect.disparity_step = 0.0;
  settings.kinect.dropout_probability = 0.0;
  settings.scanner.sigma_at_1m = 0.0;
  settings.scanner.depth_step_at_1m = 0.0;
  settings.scanner.dropout_probability = 0.0;
  settings.scanner.projector_half_width = 10.0;
  settings.scanner.projector_half_height = 10.0;
  return settings;
}

TEST(DepthWarp, RenderedPointsMoveAlongTheirRaysByTheWarp) {
  for (const SensorModel sensor : {SensorModel::kinect, SensorModel::scanner}) {
    SCOPED_TRACE(sensorModelName(sensor));
    const CameraIntrinsics camera = sensor == SensorModel::scanner ? scannerIntrinsics() : CameraIntrinsics{};
    const double z = sensor == SensorModel::scanner ? 1.0 : 2.5;
    RenderSettings settings = noiselessSettings(sensor);
    settings.warp = {0.004, 11};
    const RenderedFrame frame = renderScene(wallScene(camera, z), settings);
    const DepthWarp warp(settings.warp, camera);
    std::size_t returns = 0;
    for (int v = 0; v < camera.height; ++v) {
      for (int u = 0; u < camera.width; ++u) {
        const Eigen::Vector3f& point = frame.points[static_cast<std::size_t>(v) * camera.width + u];
        if (std::isnan(point.z())) continue;
        ++returns;
        const Eigen::Vector3d expected = (z + warp.at(u, v)) * camera.rayThroughPixel(u, v);
        ASSERT_LT((point.cast<double>() - expected).norm(), 1e-6) << "pixel " << u << ", " << v;
      }
    }
    EXPECT_GT(returns, frame.points.size() * 9 / 10);
    EXPECT_EQ(frame.quirks.warp_amplitude, 0.004);
    EXPECT_EQ(frame.quirks.warp_seed, 11U);
  }
}

// A wall facing the scanner at 1 m (0.32 m across), rendered with the scanner's noise, fitted
// with a plane; the residuals averaged over 16 x 16 pixel blocks (noise 1 mm / 16) show the
// shape. With a 3 mm warp the largest block deviation is 0.5-1.2 times the amplitude (the
// plane takes up the tilt and part of the bowl; see depth_warp.h), without it below 0.15 of it.
double largestBlockDeviation(const RenderedFrame& frame) {
  const CameraIntrinsics& camera = frame.intrinsics;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::size_t> pixels;
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    if (std::isnan(frame.points[i].z())) continue;
    points.push_back(frame.points[i].cast<double>());
    pixels.push_back(i);
  }
  // z = a x + b y + c over the returns: the wall faces the camera, so depth is a function of x, y.
  Eigen::MatrixXd design(points.size(), 3);
  Eigen::VectorXd depth(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    design.row(static_cast<Eigen::Index>(k)) << points[k].x(), points[k].y(), 1.0;
    depth(static_cast<Eigen::Index>(k)) = points[k].z();
  }
  const Eigen::Vector3d plane = design.colPivHouseholderQr().solve(depth);
  constexpr int kBlock = 16;
  const int columns = camera.width / kBlock;
  const int rows = camera.height / kBlock;
  std::vector<double> sum(static_cast<std::size_t>(columns * rows), 0.0);
  std::vector<int> count(sum.size(), 0);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const int u = static_cast<int>(pixels[k] % static_cast<std::size_t>(camera.width));
    const int v = static_cast<int>(pixels[k] / static_cast<std::size_t>(camera.width));
    const auto block = static_cast<std::size_t>((v / kBlock) * columns + u / kBlock);
    sum[block] += points[k].z() - design.row(static_cast<Eigen::Index>(k)).dot(plane);
    ++count[block];
  }
  double largest = 0.0;
  for (std::size_t b = 0; b < sum.size(); ++b) {
    if (count[b] > kBlock * kBlock / 2) largest = std::max(largest, std::abs(sum[b] / count[b]));
  }
  return largest;
}

TEST(DepthWarp, AFlatWallDeviatesFromItsBestFitPlaneByAboutTheAmplitude) {
  const Scene scene = wallScene(scannerIntrinsics(), 1.0);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    RenderSettings settings;
    settings.sensor = SensorModel::scanner;
    settings.seed = seed;
    settings.scanner.projector_half_width = 10.0;
    const double plain = largestBlockDeviation(renderScene(scene, settings));
    settings.warp = {0.003, seed};
    const double warped = largestBlockDeviation(renderScene(scene, settings));
    EXPECT_LT(plain, 0.15 * 0.003);
    EXPECT_GT(warped, 0.5 * 0.003);
    EXPECT_LT(warped, 1.2 * 0.003);
  }
}

}  // namespace
