// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Self-calibration: the depth noise measured on the frame recovers the noise a scene was
// rendered with (sigma(r) = sigma_0 + c r^2 along the rays), finds none on exact data, and
// finds the step of quantized depths.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "frame/noise_estimator.h"
#include "test_scenes.h"

namespace floodplane {
namespace {

using test::Pinhole;
using test::RenderedGrid;

Pinhole vga() {
  Pinhole camera;
  camera.width = 640;
  camera.height = 480;
  camera.focal = 525.0;
  return camera;
}

// A room corner seen from 1 m above the floor: ranges from about 1 m (floor below) to 5 m.
NoiseModel estimate(const RenderedGrid& scene) {
  NoiseEstimator estimator;
  return estimator.estimate(scene.grid());
}

TEST(NoiseEstimator, FindsNoNoiseOnExactData) {
  const NoiseModel model = estimate(test::render(vga(), test::roomCorner()));
  EXPECT_GE(model.patches, NoiseEstimator::kMinimumPatches);
  EXPECT_TRUE(model.estimated);
  EXPECT_LT(model.sigma(1.0), 1e-5);
  EXPECT_LT(model.sigma(4.0), 1e-5);
  EXPECT_EQ(model.step(2.0), 0.0);
}

TEST(NoiseEstimator, RecoversAQuadraticNoiseCoefficientWithinTwentyPercent) {
  for (const double c : {0.001, 0.0019, 0.004}) {
    const RenderedGrid scene = test::render(
        vga(), test::roomCorner(), [c](double r) { return c * r * r; }, 3);
    const NoiseModel model = estimate(scene);
    for (const double range : {1.5, 3.0, 4.5})
      EXPECT_NEAR(model.sigma(range), c * range * range, 0.2 * c * range * range) << "c = " << c << ", r = " << range;
    EXPECT_NEAR(model.sigma_quadratic, c, 0.2 * c);
  }
}

TEST(NoiseEstimator, SeparatesAConstantFromAQuadraticTerm) {
  const double sigma_0 = 0.003, c = 0.001;
  const RenderedGrid scene = test::render(
      vga(), test::roomCorner(), [&](double r) { return sigma_0 + c * r * r; }, 5);
  const NoiseModel model = estimate(scene);
  for (const double range : {1.2, 2.5, 4.5})
    EXPECT_NEAR(model.sigma(range), sigma_0 + c * range * range, 0.2 * (sigma_0 + c * range * range)) << range;
}

TEST(NoiseEstimator, FindsTheStepOfQuantizedDepths) {
  // Depths rounded to 2 mm after 0.8 mm of noise, as a scanner that reports whole steps.
  const double step = 0.002;
  RenderedGrid scene = test::render(
      vga(), test::roomCorner(), [](double) { return 0.0008; }, 9);
  for (std::size_t i = 0; i < scene.xyz.size(); i += 3) {
    const float z = scene.xyz[i + 2];
    if (!std::isfinite(z)) continue;
    const float rounded = static_cast<float>(std::round(z / step) * step);
    for (int k = 0; k < 3; ++k) scene.xyz[i + static_cast<std::size_t>(k)] *= rounded / z;
  }
  const NoiseModel model = estimate(scene);
  EXPECT_NEAR(model.step(1.0), step, 0.1 * step);
  EXPECT_NEAR(model.step(4.0), step, 0.1 * step);
  // Rounding adds step^2 / 12 to the noise's variance: sqrt(0.8^2 + 0.58^2) = 0.99 mm.
  EXPECT_NEAR(model.sigma(2.0), 0.00099, 0.2 * 0.00099);
}

TEST(NoiseEstimator, IgnoresCurvedSurfacesAndEdgesUnlessTheyAreMostOfTheFrame) {
  // A third of the image is a bumpy surface (ridges 1 cm high every 10 cm), the rest a room
  // with c = 0.002: the low quantile of each range bin is still the room's noise.
  const double c = 0.002;
  test::ScenePlane bumps = test::frontalPlane(1.5, 9);
  bumps.contains = [](const Eigen::Vector3d& p) { return p.x() < -0.3; };
  std::vector<test::ScenePlane> planes = test::roomCorner();
  planes.push_back(bumps);
  RenderedGrid scene = test::render(
      vga(), planes, [c](double r) { return c * r * r; }, 11);
  for (std::size_t i = 0; i < scene.truth.size(); ++i) {
    if (scene.truth[i] != 9) continue;
    const float x = scene.xyz[3 * i];
    const float z = scene.xyz[3 * i + 2];
    const float bumped = z + 0.01f * static_cast<float>(std::sin(x * 2.0 * M_PI / 0.1));
    for (int k = 0; k < 3; ++k) scene.xyz[3 * i + static_cast<std::size_t>(k)] *= bumped / z;
  }
  const NoiseModel model = estimate(scene);
  EXPECT_NEAR(model.sigma(3.0), c * 9.0, 0.2 * c * 9.0);
}

TEST(NoiseEstimator, SaysWhenAFrameHasTooFewCleanPatches) {
  Pinhole tiny = vga();
  tiny.width = 30;
  tiny.height = 20;
  tiny.focal = 24.6;
  const NoiseModel model = estimate(test::render(tiny, test::roomCorner(), 0.001));
  EXPECT_LT(model.patches, NoiseEstimator::kMinimumPatches);
}

}  // namespace
}  // namespace floodplane
