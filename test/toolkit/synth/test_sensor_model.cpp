// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The Kinect sensor model's pieces, one at a time: the axial noise formula, the disparity
// lattice, the order of noise, quantization, range limits and dropouts. The statistics of
// the whole model on a rendered plane are in test_renderer.cpp.

#include "synth/sensor_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace floodplane::synth;

// f b = 525 px * 0.075 m: disparity = f b / z pixels, measured in steps of 1/8 px.
constexpr double kFocalBaseline = 525.0 * 0.075;

TEST(SensorModel, NamesRoundTripAndUnknownNamesAreRejected) {
  for (SensorModel model : {SensorModel::none, SensorModel::kinect, SensorModel::scanner}) {
    EXPECT_EQ(sensorModelFromName(sensorModelName(model)), model);
  }
  EXPECT_STREQ(sensorModelName(SensorModel::kinect), "kinect");
  EXPECT_STREQ(sensorModelName(SensorModel::scanner), "scanner");
  EXPECT_FALSE(sensorModelFromName("Kinect").has_value());
  EXPECT_FALSE(sensorModelFromName("").has_value());
}

TEST(SensorModel, AxialNoiseFollowsNguyenEtAl) {
  const KinectParams params;
  EXPECT_NEAR(axialNoiseSigma(0.4, params), 0.0012, 1e-15);  // the minimum
  EXPECT_NEAR(axialNoiseSigma(1.0, params), 0.0012 + 0.0019 * 0.36, 1e-15);
  EXPECT_NEAR(axialNoiseSigma(3.0, params), 0.0012 + 0.0019 * 6.76, 1e-15);
}

TEST(SensorModel, QuantizedDepthIsTheNearestStepOfTheDisparityLattice) {
  const KinectParams params;
  for (double z = 0.5; z < 8.0; z += 0.0137) {
    const double quantized = quantizeDepth(z, params);
    // On the lattice: 8 f b / z is a whole number of eighth pixels.
    const double eighths = 8.0 * kFocalBaseline / quantized;
    EXPECT_NEAR(eighths, std::round(eighths), 1e-9) << "z = " << z;
    // The nearest step: the disparity moved by at most half a step.
    EXPECT_LE(std::abs(eighths - 8.0 * kFocalBaseline / z), 0.5 + 1e-9) << "z = " << z;
  }
  // 1 m and 3 m are lattice depths (315 and 105 eighths of a pixel).
  EXPECT_NEAR(quantizeDepth(1.0, params), 1.0, 1e-12);
  EXPECT_NEAR(quantizeDepth(3.0, params), 3.0, 1e-12);
}

TEST(SensorModel, ZeroDisparityStepTurnsQuantizationOff) {
  KinectParams params;
  params.disparity_step = 0.0;
  EXPECT_EQ(quantizeDepth(1.2345, params), 1.2345);
}

TEST(SensorModel, WithoutNoiseTheMeasurementIsTheQuantizedDepth) {
  KinectParams params;
  params.sigma_constant = 0.0;
  params.sigma_quadratic = 0.0;
  params.dropout_probability = 0.0;
  for (int pixel = 0; pixel < 100; ++pixel) {
    PixelRandom random(1, static_cast<std::uint64_t>(pixel));
    const double z = 0.6 + 0.05 * pixel;
    const auto measured = measureKinectDepth(z, params, random);
    ASSERT_TRUE(measured.has_value()) << "z = " << z;
    EXPECT_EQ(*measured, quantizeDepth(z, params)) << "z = " << z;
  }
}

TEST(SensorModel, ReturnsOutsideTheRangeOrDroppedAreLost) {
  const KinectParams params;
  for (int pixel = 0; pixel < 1000; ++pixel) {
    PixelRandom near_random(1, static_cast<std::uint64_t>(pixel));
    EXPECT_FALSE(measureKinectDepth(0.40, params, near_random).has_value());
    PixelRandom far_random(1, static_cast<std::uint64_t>(pixel));
    EXPECT_FALSE(measureKinectDepth(12.0, params, far_random).has_value());
  }
  KinectParams always_dropped = params;
  always_dropped.dropout_probability = 1.0;
  PixelRandom random(1, 0);
  EXPECT_FALSE(measureKinectDepth(1.0, always_dropped, random).has_value());
}

// The bend's depth error e = (kappa / 2) rho^2 z^3 / z_ref: zero on the optical axis and when
// off, growing with rho^2 and with z^3, of the sign of kappa.
TEST(SensorModel, BendMovesTheDepthByHalfKappaRhoSquaredZCubedOverTheReferenceDepth) {
  KinectParams params;
  EXPECT_EQ(kinectBendOffset(3.5, 0.5, params), 0.0);  // off by default
  params.bend_curvature = 0.02;
  EXPECT_EQ(kinectBendOffset(3.5, 0.0, params), 0.0);
  // A 640 x 480 Kinect's corner, rho^2 = (319.5^2 + 239.5^2) / 525^2 = 0.578, at 3.5 m: 7.1 cm.
  const double corner = (319.5 * 319.5 + 239.5 * 239.5) / (525.0 * 525.0);
  EXPECT_NEAR(kinectBendOffset(3.5, corner, params), 0.01 * corner * 3.5 * 3.5, 1e-15);
  EXPECT_NEAR(kinectBendOffset(3.5, corner, params), 0.0708, 0.0001);
  EXPECT_NEAR(kinectBendOffset(1.75, corner, params), kinectBendOffset(3.5, corner, params) / 8.0, 1e-15);
  EXPECT_NEAR(kinectBendOffset(2.0, 0.4, params), 2.0 * kinectBendOffset(2.0, 0.2, params), 1e-15);
  params.bend_curvature = -0.02;
  EXPECT_NEAR(kinectBendOffset(3.5, corner, params), -0.0708, 0.0001);
}

}  // namespace
