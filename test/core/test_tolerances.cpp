// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Every length tolerance of the method at a range r: the paper's fixed lengths where Params sets
// them, otherwise derived from the depth noise sigma(r) = sigma_0 + c r^2 and the pixel
// footprint alpha r; kPointDeviations (3) of the noise widen every one of them.
#include <gtest/gtest.h>

#include <cstddef>

#include "floodplane/params.h"
#include "models/tolerances.h"

namespace floodplane {
namespace {

constexpr double kPitch = 0.002;  // alpha [rad]: a 2 mm footprint at 1 m
constexpr std::size_t kVga = 640 * 480;

NoiseModel quadraticNoise(double c) {
  NoiseModel noise;
  noise.sigma_quadratic = c;
  return noise;
}

// The defaults: every length derived.
Tolerances derived(const NoiseModel& noise = NoiseModel()) { return Tolerances(Params(), noise, kPitch, kVga); }

TEST(Tolerances, FootprintIsTheAngularPitchTimesTheRange) {
  const Tolerances tolerances = derived();
  EXPECT_DOUBLE_EQ(tolerances.footprint(1.0), 0.002);
  EXPECT_DOUBLE_EQ(tolerances.footprint(3.0), 0.006);
}

TEST(Tolerances, KeepsTheNoiseModelItWasGiven) {
  NoiseModel noise = quadraticNoise(0.0015);
  noise.sigma_constant = 0.0004;
  const Tolerances tolerances = derived(noise);
  EXPECT_EQ(tolerances.noise().sigma_quadratic, 0.0015);
  EXPECT_EQ(tolerances.noise().sigma_constant, 0.0004);
}

// --- sigma_plane (Eq. 2) ---------------------------------------------------------------------

TEST(Tolerances, PlaneFloorIsHalfAFootprintWhenSigmaPlaneIsUnset) {
  const Tolerances tolerances = derived();
  EXPECT_DOUBLE_EQ(tolerances.planeFloor(2.0), 0.002);
  EXPECT_DOUBLE_EQ(tolerances.planeFloor(4.0), 0.004);  // scale-free: grows with the range
}

TEST(Tolerances, PlaneFloorLeavesTheNoiseToTheFloodsTestAlongTheRay) {
  // The noise enters Eq. 2 as a band along the viewing ray (FloodCriterion), not here.
  EXPECT_DOUBLE_EQ(derived(quadraticNoise(0.01)).planeFloor(2.0), derived().planeFloor(2.0));
}

TEST(Tolerances, AFixedSigmaPlaneTakesThePapersMeaningAtEveryRange) {
  Params params;
  params.distance_threshold = 0.01;
  const Tolerances tolerances(params, quadraticNoise(0.002), kPitch, kVga);
  EXPECT_DOUBLE_EQ(tolerances.planeFloor(0.5), 0.01);
  EXPECT_DOUBLE_EQ(tolerances.planeFloor(8.0), 0.01);
}

// --- sigma_seed (Sec. III-C) -----------------------------------------------------------------

TEST(Tolerances, SeedHalfSideIsSixFootprintsWithoutNoise) {
  EXPECT_DOUBLE_EQ(derived().seedHalfSide(2.0), 0.024);
  EXPECT_DOUBLE_EQ(derived().seedHalfSide(4.0), 0.048);
}

TEST(Tolerances, SeedHalfSideGrowsToThreeNoiseDeviationsWhereTheyAreMore) {
  const Tolerances tolerances = derived(quadraticNoise(0.002));
  EXPECT_DOUBLE_EQ(tolerances.seedHalfSide(1.0), 0.012);  // 3 sigma = 0.006 < six footprints
  EXPECT_DOUBLE_EQ(tolerances.seedHalfSide(4.0), 0.096);  // 3 sigma = 3 * 0.002 * 16 > 0.048
}

TEST(Tolerances, AFixedSeedSizeIsTheCubesSideAndTheNoiseStillWidensIt) {
  Params params;
  params.seed_size = 0.06;
  const Tolerances tolerances(params, quadraticNoise(0.002), kPitch, kVga);
  EXPECT_DOUBLE_EQ(tolerances.seedHalfSide(1.0), 0.03);
  EXPECT_DOUBLE_EQ(tolerances.seedHalfSide(3.0), 0.054);  // 3 * 0.002 * 9
}

TEST(Tolerances, ScaleShrinksTheFixedPartOfTheSeedCubeNotTheNoise) {
  Params params;
  params.seed_size = 0.06;
  const Tolerances tolerances(params, quadraticNoise(0.002), kPitch, kVga);
  EXPECT_DOUBLE_EQ(tolerances.seedHalfSide(1.0, 0.5), 0.015);
  EXPECT_DOUBLE_EQ(tolerances.seedHalfSide(3.0, 0.5), 0.054);
  EXPECT_DOUBLE_EQ(derived().seedHalfSide(2.0, 0.5), 0.012);
}

// --- sigma_plane-merge (Eq. 9) ---------------------------------------------------------------

TEST(Tolerances, MergeDistanceIsAFootprintOrThreeNoiseDeviations) {
  EXPECT_DOUBLE_EQ(derived().mergeDistance(2.0), 0.004);
  EXPECT_DOUBLE_EQ(derived(quadraticNoise(0.002)).mergeDistance(1.0), 0.006);  // 3 sigma > 2 mm
}

TEST(Tolerances, AFixedMergeDistanceIsWidenedOnlyWhereThreeNoiseDeviationsAreMore) {
  Params params;
  params.merge_distance = 0.03;
  const Tolerances tolerances(params, quadraticNoise(0.002), kPitch, kVga);
  EXPECT_DOUBLE_EQ(tolerances.mergeDistance(1.0), 0.03);
  EXPECT_DOUBLE_EQ(tolerances.mergeDistance(3.0), 0.054);
  EXPECT_DOUBLE_EQ(tolerances.mergeDistance(5.0), 0.15);
}

TEST(Tolerances, MergeFitIsHalfOfSigmaPlaneOrTwoNoiseDeviations) {
  Params params;
  params.distance_threshold = 0.01;
  const Tolerances exact(params, NoiseModel(), kPitch, kVga);
  EXPECT_DOUBLE_EQ(exact.mergeFit(1.0), 0.005);
  EXPECT_DOUBLE_EQ(exact.mergeFit(6.0), 0.005);
  const Tolerances noisy(params, quadraticNoise(0.002), kPitch, kVga);
  EXPECT_DOUBLE_EQ(noisy.mergeFit(1.0), 0.005);      // 2 sigma = 0.004
  EXPECT_DOUBLE_EQ(noisy.mergeFit(3.0), 0.036);      // 2 sigma = 2 * 0.002 * 9
  EXPECT_DOUBLE_EQ(derived().mergeFit(2.0), 0.001);  // half of half a footprint
}

// --- sigma_0 ---------------------------------------------------------------------------------

TEST(Tolerances, SigmaZeroWidensTheNoiseTolerancesAtEveryRange) {
  NoiseModel noise;
  noise.sigma_constant = 0.01;  // 3 sigma_0 = 3 cm
  const Tolerances tolerances = derived(noise);
  EXPECT_DOUBLE_EQ(tolerances.seedHalfSide(0.5), 0.03);
  EXPECT_DOUBLE_EQ(tolerances.mergeDistance(0.5), 0.03);
  EXPECT_DOUBLE_EQ(tolerances.mergeFit(0.5), 0.02);
  EXPECT_DOUBLE_EQ(tolerances.planeFloor(0.5), 0.0005);
}

// --- the smallest plane ----------------------------------------------------------------------

TEST(Tolerances, MinInliersIsOnePixelInAThousandUnlessSet) {
  EXPECT_EQ(derived().minInliers(), 307u);                                                 // 640 x 480
  EXPECT_EQ(Tolerances(Params(), NoiseModel(), kPitch, 1920 * 1080).minInliers(), 2074u);  // 2073.6
  EXPECT_EQ(Tolerances(Params(), NoiseModel(), kPitch, 1500).minInliers(), 2u);            // 1.5 rounds up
  Params params;
  params.min_inliers = 50;
  EXPECT_EQ(Tolerances(params, NoiseModel(), kPitch, kVga).minInliers(), 50u);
}

}  // namespace
}  // namespace floodplane
