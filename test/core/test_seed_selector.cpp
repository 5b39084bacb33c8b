// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Sec. III-C: seed selection. Each discontinuity test on a scene built to trip it alone.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "seeds/seed_selector.h"
#include "test_scenes.h"

namespace floodplane {
namespace {

using test::Pinhole;
using test::ScenePlane;

// 320 x 240 with the Kinect's field of view: f = 262.5 px, so rho = 8 px at 1 m.
Pinhole camera() { return test::kinectView(320, 240); }

// The pixel column of a point.
double column(const Eigen::Vector3d& p) { return camera().focal * p.x() / p.z() + camera().cx(); }

// The paper's tests exactly: its seed cube of 6 cm, no noise.
Params exactParams() {
  Params p;
  p.seed_size = 0.06;
  p.depth_noise_coefficient = 0.0;
  return p;
}

// A selector with what it refers to.
struct Selector {
  Params params;
  Tolerances tolerances;
  SeedSelector selector;

  Selector(const Params& p, int width, int height, float angular_pitch, double noise_coefficient = 0.0,
           double scale = 1.0)
      : params(p) {
    NoiseModel noise;
    noise.sigma_quadratic = noise_coefficient;
    tolerances = Tolerances(params, noise, angular_pitch, static_cast<std::size_t>(width * height));
    selector.configure(params, tolerances, scale, angular_pitch, width, height);
  }
  Selector(const Selector&) = delete;
};

Selector selectorFor(const test::RenderedGrid& scene, const Params& params, double noise_coefficient = 0.0) {
  return Selector(params, scene.width, scene.height, 1.0f / static_cast<float>(camera().focal), noise_coefficient);
}

constexpr int kX = 160, kY = 120;  // a seed candidate at the image centre (pixel 159.5 + 0.5)

TEST(SeedSelector, ProjectsTheSeedCubeToRhoPixels) {
  const Selector fixture(exactParams(), 640, 480, 1.0f / 525.0f);
  const SeedSelector& selector = fixture.selector;
  // rho = f (sigma_seed / 2) / (r + sigma_seed / 2)
  EXPECT_EQ(selector.rhoAt(1.0f), 15);  // 15.29
  EXPECT_EQ(selector.rhoAt(3.0f), 5);   // 5.20
  EXPECT_EQ(selector.rhoAt(0.3f), 48);  // 47.7, the cap that bounds Eq. 7's cost
  EXPECT_EQ(selector.rhoAt(40.0f), 2);  // never below 2: a cross needs points on its arms
}

TEST(SeedSelector, GrowsTheSeedCubeWithTheDepthNoise) {
  const Selector fixture(exactParams(), 640, 480, 1.0f / 525.0f, 0.0019);
  EXPECT_FLOAT_EQ(fixture.selector.seedSizeAt(1.0f), 0.06f);              // 6 sigma = 1.1 cm < 6 cm
  EXPECT_NEAR(fixture.selector.seedSizeAt(5.0f), 6 * 0.0019 * 25, 1e-6);  // 6 sigma = 28.5 cm
}

TEST(SeedSelector, DerivesTheSeedCubeFromThePixelFootprintWhenItIsNotSet) {
  // Six footprints either side: 12 * 2 mrad * r, the same number of pixels at any range.
  const Params automatic;
  const Selector fixture(automatic, 640, 480, 0.002f);
  EXPECT_NEAR(fixture.selector.seedSizeAt(1.0f), 0.024, 1e-7);
  EXPECT_NEAR(fixture.selector.seedSizeAt(3.0f), 0.072, 1e-7);
  EXPECT_EQ(fixture.selector.rhoAt(1.0f), fixture.selector.rhoAt(3.0f));
  // The second, finer pass: half the fixed part.
  const Selector fine(automatic, 640, 480, 0.002f, 0.0, 0.5);
  EXPECT_NEAR(fine.selector.seedSizeAt(2.0f), 0.024, 1e-7);
}

TEST(SeedSelector, FitsTheGridItIsGiven) {
  const Selector narrow(exactParams(), 4, 40, 1.0f / 525.0f);
  EXPECT_EQ(narrow.selector.maxRho(), 0);  // a 4-pixel-wide grid has no room for a cross of rho 2
  const Selector tiny(exactParams(), 5, 5, 1.0f / 525.0f);
  EXPECT_EQ(tiny.selector.maxRho(), 2);
  EXPECT_EQ(tiny.selector.rhoAt(1.0f), 2);
}

TEST(SeedSelector, AcceptsAFlatPatchWithItsNormalAndSpacing) {
  const test::RenderedGrid scene = test::render(camera(), {test::frontalPlane(1.0)});
  const Selector fixture = selectorFor(scene, exactParams());
  const SeedSelector& selector = fixture.selector;
  Seed seed;
  ASSERT_EQ(selector.test(scene.grid(), kX, kY, seed), SeedVerdict::kAccepted);
  EXPECT_EQ(seed.index, static_cast<std::size_t>(kY) * scene.width + kX);
  EXPECT_EQ(seed.rho, 8);
  EXPECT_NEAR(seed.normal.z, -1.0f, 1e-5f);  // unit, facing the sensor
  EXPECT_NEAR(std::hypot(seed.normal.x, seed.normal.y), 0.0f, 1e-3f);
  EXPECT_LT(seed.normal_uncertainty, 1e-3f);
  // Eq. 8: metres per pixel at 1 m is 1 / f.
  EXPECT_NEAR(seed.spacing, 1.0 / camera().focal, 0.01 / camera().focal);
}

TEST(SeedSelector, RejectsADepthJumpInsideTheSeedCube) {
  // Eq. 5: the right arm ends on a wall 60 cm behind.
  ScenePlane near = test::frontalPlane(1.0, 1);
  near.contains = [](const Eigen::Vector3d& p) { return column(p) < kX + 4; };
  const test::RenderedGrid scene = test::render(camera(), {near, test::frontalPlane(1.6, 2)});
  Seed seed;
  EXPECT_EQ(selectorFor(scene, exactParams()).selector.test(scene.grid(), kX, kY, seed),
            SeedVerdict::kDistanceDiscontinuity);
}

TEST(SeedSelector, RejectsACreaseThroughTheCandidate) {
  // Eq. 6: a ridge of two planes at 60 degrees runs through the candidate's column; the
  // centroid test of Eq. 5 cannot see it (both sides recede alike).
  const double angle = 30.0 * M_PI / 180.0;
  ScenePlane left, right;
  left.normal = Eigen::Vector3d(std::sin(angle), 0, -std::cos(angle));
  right.normal = Eigen::Vector3d(-std::sin(angle), 0, -std::cos(angle));
  left.offset = right.offset = std::cos(angle);  // both through (0, 0, 1)
  left.contains = [](const Eigen::Vector3d& p) { return p.x() < 0; };
  right.contains = [](const Eigen::Vector3d& p) { return p.x() >= 0; };
  right.id = 2;
  const test::RenderedGrid scene = test::render(camera(), {left, right});
  Seed seed;
  EXPECT_EQ(selectorFor(scene, exactParams()).selector.test(scene.grid(), kX, kY, seed), SeedVerdict::kCoarseCurvature);
}

TEST(SeedSelector, RejectsARidgeOnOneArmThatTheEndpointsMiss) {
  // Eq. 7: a 2 cm high, 3 pixel wide ridge halfway along the right arm. The endpoints lie on
  // the plane, so Eqs. 5 and 6 pass; the points of the arm do not.
  ScenePlane ridge = test::frontalPlane(0.98, 2);
  ridge.contains = [](const Eigen::Vector3d& p) { return std::abs(column(p) - (kX + 4)) < 1.5; };
  const test::RenderedGrid scene = test::render(camera(), {ridge, test::frontalPlane(1.0, 1)});
  Seed seed;
  EXPECT_EQ(selectorFor(scene, exactParams()).selector.test(scene.grid(), kX, kY, seed), SeedVerdict::kFineCurvature);
}

TEST(SeedSelector, RejectsAHoleOnAnArmOrAtTheCandidate) {
  ScenePlane holed = test::frontalPlane(1.0);
  holed.contains = [](const Eigen::Vector3d& p) { return std::abs(column(p) - (kX + 3)) > 0.5; };
  const test::RenderedGrid scene = test::render(camera(), {holed});
  const Selector fixture = selectorFor(scene, exactParams());
  const SeedSelector& selector = fixture.selector;
  Seed seed;
  EXPECT_EQ(selector.test(scene.grid(), kX, kY, seed), SeedVerdict::kHole);
  EXPECT_EQ(selector.test(scene.grid(), kX + 3, kY, seed), SeedVerdict::kHole);
}

TEST(SeedSelector, RejectsCandidatesWhoseCrossLeavesTheGrid) {
  const test::RenderedGrid scene = test::render(camera(), {test::frontalPlane(1.0)});
  const Selector fixture = selectorFor(scene, exactParams());
  const SeedSelector& selector = fixture.selector;
  Seed seed;
  // rho is 7 px at the edges of the image, where the wall is 1.1 to 1.2 m from the sensor.
  EXPECT_EQ(selector.test(scene.grid(), 6, kY, seed), SeedVerdict::kNearBorder);
  EXPECT_EQ(selector.test(scene.grid(), kX, scene.height - 7, seed), SeedVerdict::kNearBorder);
  EXPECT_EQ(selector.test(scene.grid(), 8, 8, seed), SeedVerdict::kAccepted);
}

TEST(SeedSelector, ToleratesDepthNoiseOnlyWhenItIsModelled) {
  // A wall at 3 m with Kinect-like noise (sigma = c r^2 = 1.7 cm): with the noise model the
  // seed tests see a plane; with the paper's fixed tolerances they see curvature everywhere.
  const double c = 0.0019;
  const test::RenderedGrid scene = test::render(camera(), {test::frontalPlane(3.0)}, c * 9.0, 7);
  const auto acceptedFraction = [&](double noise_coefficient) {
    const Selector fixture = selectorFor(scene, exactParams(), noise_coefficient);
    const SeedSelector& selector = fixture.selector;
    int accepted = 0, tested = 0;
    Seed seed;
    for (int y = 30; y < scene.height - 30; y += 4) {
      for (int x = 30; x < scene.width - 30; x += 4) {
        ++tested;
        accepted += selector.test(scene.grid(), x, y, seed) == SeedVerdict::kAccepted;
      }
    }
    return static_cast<double>(accepted) / tested;
  };
  const double with_model = acceptedFraction(c);
  const double without_model = acceptedFraction(0.0);
  EXPECT_GT(with_model, 0.5);
  EXPECT_LT(without_model, 0.2);
}

TEST(SeedSelector, EstimatesTheAngularPitchOfThePixels) {
  const test::RenderedGrid scene = test::render(camera(), test::roomCorner());
  std::vector<float> scratch;
  EXPECT_NEAR(SeedSelector::estimateAngularPitch(scene.grid(), scratch), 1.0 / camera().focal, 0.01 / camera().focal);
  ScenePlane nothing = test::frontalPlane(1.0);
  nothing.contains = [](const Eigen::Vector3d&) { return false; };
  const test::RenderedGrid empty = test::render(camera(), {nothing});
  EXPECT_FLOAT_EQ(SeedSelector::estimateAngularPitch(empty.grid(), scratch, 0.5f), 0.5f);
}

}  // namespace
}  // namespace floodplane
