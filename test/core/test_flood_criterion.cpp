// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Sec. III-B: the distance functions of the flood (Eqs. 2, 3) and the membership test of
// Eq. 1 with range-dependent tolerances (depth noise, Eq. 8 spacing).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "models/flood_criterion.h"

namespace floodplane {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// --- Eq. 2 -------------------------------------------------------------------------------

TEST(PlaneDistance, IsZeroForAPointOnThePlane) {
  // z = 2 facing the camera: n = (0, 0, -1), d = 2.
  EXPECT_FLOAT_EQ(planeDistance({0, 0, -1}, 2.f, {0.3f, -0.7f, 2.f}), 0.f);
}

TEST(PlaneDistance, IsTheAbsoluteOffsetOnBothSidesOfThePlane) {
  const Vec3 n{0, 0, -1};
  EXPECT_FLOAT_EQ(planeDistance(n, 2.f, {0, 0, 2.25f}), 0.25f);  // behind the plane
  EXPECT_FLOAT_EQ(planeDistance(n, 2.f, {0, 0, 1.75f}), 0.25f);  // in front of it
}

TEST(PlaneDistance, MatchesTheSeedFormOfEquationTwo) {
  // |(P_seed - P') . n| with d = -n . P_seed, on a tilted plane.
  const float s = 1.0f / std::sqrt(2.0f);
  const Vec3 n{0, s, -s};
  const Vec3 seed{0.1f, 0.2f, 1.5f};
  const float d = -n.dot(seed);
  const Vec3 p{-0.4f, 0.9f, 1.1f};
  const float expected = std::abs((seed - p).dot(n));  // |(-0.7 * s) + (0.4 * -s)| = 1.1 s
  EXPECT_NEAR(expected, 1.1f * s, 1e-6f);
  EXPECT_NEAR(planeDistance(n, d, p), expected, 1e-6f);
}

TEST(PlaneDistance, IsNaNForAHoleSoEveryAcceptanceTestFails) {
  const float distance = planeDistance({0, 0, -1}, 2.f, {kNaN, kNaN, kNaN});
  EXPECT_TRUE(std::isnan(distance));
  EXPECT_FALSE(distance < 1e9f);
  EXPECT_FALSE(distance < std::numeric_limits<float>::infinity());
}

// --- Eq. 3 -------------------------------------------------------------------------------

TEST(SquaredEuclideanDistance, IsTheSumOfSquaredDifferences) {
  EXPECT_FLOAT_EQ(squaredEuclideanDistance({1, 2, 3}, {4, 6, 3}), 25.f);  // 3-4-5
  EXPECT_FLOAT_EQ(squaredEuclideanDistance({1, 2, 3}, {1, 2, 3}), 0.f);
  EXPECT_FLOAT_EQ(squaredEuclideanDistance({0, 0, 0}, {0, 0, -0.5f}), 0.25f);
}

TEST(SquaredEuclideanDistance, IsSymmetric) {
  const Vec3 a{0.1f, -0.2f, 1.3f}, b{-0.5f, 0.4f, 2.0f};
  EXPECT_FLOAT_EQ(squaredEuclideanDistance(a, b), squaredEuclideanDistance(b, a));
}

TEST(SquaredEuclideanDistance, IsNaNWhenEitherPointIsAHole) {
  EXPECT_FALSE(squaredEuclideanDistance({kNaN, 0, 0}, {0, 0, 1}) < 1e9f);
  EXPECT_FALSE(squaredEuclideanDistance({0, 0, 1}, {0, kNaN, 0}) < 1e9f);
}

// --- Depth noise (depth_noise.h) -----------------------------------------------------------

NoiseModel quadraticNoise(double c) {
  NoiseModel noise;
  noise.sigma_quadratic = c;
  return noise;
}

TEST(DepthNoise, GrowsWithTheSquareOfTheRange) {
  const NoiseModel noise = quadraticNoise(0.002);
  EXPECT_DOUBLE_EQ(depthSigma(noise, 1.0), 0.002);
  EXPECT_DOUBLE_EQ(depthSigma(noise, 9.0), 0.018);  // r = 3 m
  EXPECT_DOUBLE_EQ(depthSigma(noise, 9.0), noise.sigma(3.0));
}

TEST(DepthNoise, NamesThreeDeviationsForAPointAndThreeRootTwoForADifferenceOfTwo) {
  EXPECT_EQ(kPointDeviations, 3.0);
  EXPECT_EQ(kDifferenceDeviations, 3.0 * std::sqrt(2.0));
}

TEST(DepthNoise, DeviationsAreThatManySigmasAtTheRange) {
  const NoiseModel noise = quadraticNoise(0.002);
  EXPECT_DOUBLE_EQ(noiseDeviations(noise, kPointDeviations, 1.0), 0.006);
  EXPECT_DOUBLE_EQ(noiseDeviations(noise, kPointDeviations, 4.0), 0.024);
  EXPECT_DOUBLE_EQ(noiseDeviations(noise, kPointDeviations, 25.0), 0.15);  // r = 5 m
  EXPECT_DOUBLE_EQ(noiseDeviations(noise, kDifferenceDeviations, 4.0), 3.0 * std::sqrt(2.0) * 0.008);
  // In float for float ranges, as the hot paths take it.
  EXPECT_FLOAT_EQ(noiseDeviations(noise, kPointDeviations, 4.0f), 0.024f);
}

TEST(DepthNoise, AddsSigmaZeroAtEveryRange) {
  NoiseModel noise = quadraticNoise(0.002);
  noise.sigma_constant = 0.001;
  EXPECT_DOUBLE_EQ(depthSigma(noise, 0.0), 0.001);
  EXPECT_DOUBLE_EQ(depthSigma(noise, 4.0), 0.009);
  EXPECT_DOUBLE_EQ(noiseDeviations(noise, kPointDeviations, 1.0), 0.009);
}

TEST(DepthNoise, ZeroCoefficientsGiveNoNoiseAtAnyRange) {
  const NoiseModel noise;  // default: no noise
  EXPECT_DOUBLE_EQ(depthSigma(noise, 100.0), 0.0);
  EXPECT_DOUBLE_EQ(noiseDeviations(noise, kDifferenceDeviations, 100.0), 0.0);
}

// Exact data, and exact data rounded to a 0.2 mm depth lattice (a TUM depth PNG: the noise
// estimator measures about 0.067 mm), count as noise-free for a Kinect's pixels (1/525 rad);
// a Kinect's own noise, a 1 mm depth lattice at close range and a structured-light scanner's
// noise (1 mm at 1 m, pixels of 1/1600 rad) do not.
TEST(DepthNoise, IsNegligibleAgainstPixelsBelowATenthOfTheirFootprint) {
  const double kinect_pitch = 1.0 / 525.0;
  NoiseModel exact;
  EXPECT_TRUE(negligibleNoise(exact));
  EXPECT_TRUE(negligibleAgainstPixels(exact, kinect_pitch));
  NoiseModel lattice;
  lattice.sigma_constant = 6.7e-5;
  EXPECT_FALSE(negligibleNoise(lattice));
  EXPECT_TRUE(negligibleAgainstPixels(lattice, kinect_pitch));
  NoiseModel millimetres;  // a depth PNG in millimetres: 0.29 mm against 0.1 mm at 0.5 m
  millimetres.sigma_constant = 2.9e-4;
  EXPECT_FALSE(negligibleAgainstPixels(millimetres, kinect_pitch));
  EXPECT_FALSE(negligibleAgainstPixels(quadraticNoise(0.0015), kinect_pitch));  // a Kinect
  EXPECT_FALSE(negligibleAgainstPixels(quadraticNoise(0.001), 1.0 / 1600.0));   // a scanner
}

// Exact depths rounded to millimetres (the noise estimator measures 0.35 mm on a 1 mm lattice
// where the rounding alone gives 0.29 mm) are rounding only; a Kinect's noise (0.5-0.7 of its
// disparity step), a scanner's (0.8 of its 1.3 mm step at 1 m) and noise without a lattice
// are not.
TEST(DepthNoise, IsRoundingOnlyWhereTheLatticeExplainsAllOfIt) {
  NoiseModel millimetres;
  millimetres.sigma_constant = 3.5e-4;
  millimetres.step_constant = 1e-3;
  EXPECT_TRUE(roundingOnly(millimetres));
  millimetres.sigma_constant = 5e-4;  // more than the rounding explains: real noise on top
  EXPECT_FALSE(roundingOnly(millimetres));
  NoiseModel kinect = quadraticNoise(0.0015);
  kinect.step_quadratic = 0.0022;
  EXPECT_FALSE(roundingOnly(kinect));
  NoiseModel scanner = quadraticNoise(0.001);
  scanner.step_quadratic = 0.0013;
  EXPECT_FALSE(roundingOnly(scanner));
  EXPECT_FALSE(roundingOnly(quadraticNoise(0.0015)));  // no lattice
  EXPECT_FALSE(roundingOnly(NoiseModel()));            // exact: negligibleNoise's case
}

// --- FloodCriterion ------------------------------------------------------------------------

// The plane z = 2 facing the camera, sigma_plane = 1 cm, neighbouring pixels 1 cm apart at the
// seed's range of 2 m.
FloodCriterion criterion(double noise_coefficient) {
  static Params params;
  params.distance_threshold = 0.01;
  NoiseModel noise;
  noise.sigma_quadratic = noise_coefficient;
  const Tolerances tolerances(params, noise, 1.0 / 525.0, 640 * 480);
  return FloodCriterion::make({0, 0, -1}, 2.f, 2.0, /*spacing_per_range_sq=*/0.01 / 4.0, tolerances);
}

TEST(FloodCriterion, PlaneToleranceIsTheMaximumOfSigmaPlaneAndThreeCRSquared) {
  const FloodCriterion c = criterion(0.002f);       // 3 c = 0.006
  EXPECT_FLOAT_EQ(c.planeTolerance(1.f), 0.01f);    // 0.006 < 0.01
  EXPECT_FLOAT_EQ(c.planeTolerance(4.f), 0.024f);   // 0.006 * 4
  EXPECT_FLOAT_EQ(c.planeTolerance(16.f), 0.096f);  // 0.006 * 16
}

TEST(FloodCriterion, PlaneToleranceIsConstantWithoutDepthNoise) {
  const FloodCriterion c = criterion(0.f);
  EXPECT_FLOAT_EQ(c.planeTolerance(0.25f), 0.01f);
  EXPECT_FLOAT_EQ(c.planeTolerance(4.f), 0.01f);
  EXPECT_FLOAT_EQ(c.planeTolerance(64.f), 0.01f);
}

TEST(FloodCriterion, EuclideanToleranceIsTwiceTheSeedSpacingAtTheSeedRange) {
  // No noise: K = 2 s0 / r0^2 = 2 * 0.01 / 4 = 0.005; sigma_e(r0) = K r0^2 = 0.02.
  const FloodCriterion c = criterion(0.f);
  EXPECT_FLOAT_EQ(c.euclidean_factor, 0.005f);
  EXPECT_NEAR(std::sqrt(c.euclideanToleranceSq(4.f)), 0.02f, 1e-7f);
}

TEST(FloodCriterion, EuclideanToleranceFollowsThePixelSpacingAsRangeSquared) {
  // On a plane the spacing of neighbours grows with r^2: at 4 m it is four times that at
  // 2 m, at 1 m a quarter.
  const FloodCriterion c = criterion(0.f);
  EXPECT_NEAR(std::sqrt(c.euclideanToleranceSq(16.f)), 0.08f, 1e-6f);
  EXPECT_NEAR(std::sqrt(c.euclideanToleranceSq(1.f)), 0.005f, 1e-8f);
}

TEST(FloodCriterion, EuclideanToleranceAddsTheDepthNoiseOfBothPoints) {
  // K = 2 s0 / r0^2 + 3 sqrt(2) c = 0.005 + 3 * 1.41421 * 0.002 = 0.0134853
  const FloodCriterion c = criterion(0.002f);
  const float k = 0.005f + 3.f * std::sqrt(2.f) * 0.002f;
  EXPECT_NEAR(c.euclidean_factor, k, 1e-7f);
  EXPECT_NEAR(std::sqrt(c.euclideanToleranceSq(4.f)), 4.f * k, 1e-6f);  // 0.0539 at 2 m
  EXPECT_GT(c.euclideanToleranceSq(4.f), criterion(0.f).euclideanToleranceSq(4.f));
}

TEST(FloodCriterion, GrowsBothTolerancesBySigmaZeroToo) {
  Params params;
  params.distance_threshold = 0.001;
  NoiseModel noise;
  noise.sigma_constant = 0.002;  // 3 sigma_0 = 6 mm
  noise.sigma_quadratic = 0.001;
  const Tolerances tolerances(params, noise, 1.0 / 525.0, 640 * 480);
  const FloodCriterion c = FloodCriterion::make({0, 0, -1}, 2.f, 2.0, 0.0025, tolerances);
  EXPECT_FLOAT_EQ(c.planeTolerance(1.f), 0.009f);  // 3 (0.002 + 0.001)
  EXPECT_FLOAT_EQ(c.planeTolerance(4.f), 0.018f);  // 3 (0.002 + 0.004)
  // sigma_e(r) = 3 sqrt(2) sigma(r) + 2 spacing(r): at 2 m 3 sqrt(2) 0.006 + 0.02.
  EXPECT_NEAR(std::sqrt(c.euclideanToleranceSq(4.f)), 3.f * std::sqrt(2.f) * 0.006f + 0.02f, 1e-6f);
}

TEST(FloodCriterion, DerivesSigmaPlaneFromThePixelFootprintWhenItIsNotSet) {
  const Params automatic;
  const Tolerances tolerances(automatic, NoiseModel(), 0.002, 640 * 480);
  // Half a footprint of 2 mrad at the seed's range: 2 mm at 2 m, 4 mm at 4 m.
  EXPECT_FLOAT_EQ(FloodCriterion::make({0, 0, -1}, 2.f, 2.0, 0.001, tolerances).planeTolerance(4.f), 0.002f);
  EXPECT_FLOAT_EQ(FloodCriterion::make({0, 0, -1}, 4.f, 4.0, 0.001, tolerances).planeTolerance(16.f), 0.004f);
}

TEST(FloodCriterion, AcceptsANeighbourOnThePlaneAndRejectsOneOffIt) {
  const FloodCriterion c = criterion(0.f);
  const Vec3 from{0.f, 0.f, 2.f};
  const Vec3 on{0.015f, 0.f, 2.f};     // 1.5 cm away, on the plane
  const Vec3 off{0.015f, 0.f, 2.02f};  // 2 cm behind the plane
  const Vec3 far{0.05f, 0.f, 2.f};     // on the plane, but 5 cm away: beyond sigma_e = 2 cm
  const auto accepts = [&](const Vec3& p) {
    float distance = -1.f;
    const bool accepted = c.accepts(from, p, distance);
    if (accepted) {
      EXPECT_FLOAT_EQ(distance, planeDistance(c.normal, c.offset, p));
    }
    return accepted;
  };
  EXPECT_TRUE(accepts(on));
  EXPECT_FALSE(accepts(off));
  EXPECT_FALSE(accepts(far));
  EXPECT_FALSE(accepts({kNaN, kNaN, kNaN}));
}

}  // namespace
}  // namespace floodplane
