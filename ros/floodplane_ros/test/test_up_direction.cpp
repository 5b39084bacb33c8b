// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The up direction a node classes its planes by: ~up as a launch file or rosparam gives it
// (text or numbers; a bad one refused with its reason), and ~target_frame's z axis turned
// into the sensor's frame.

#include "up_direction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace {

using floodplane::conversion::parseUpDirection;
using floodplane::conversion::RigidTransform;
using floodplane::conversion::targetUpInSource;
using floodplane::conversion::upDirection;
using floodplane::conversion::UpDirection;

std::string errorOf(const std::string& text) {
  try {
    parseUpDirection(text);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(UpDirection, ReadsThreeNumbersWrittenAnyUsualWay) {
  const UpDirection level_optical{0.0, -1.0, 0.0};
  EXPECT_EQ(parseUpDirection("[0, -1, 0]"), level_optical);
  EXPECT_EQ(parseUpDirection("0,-1,0"), level_optical);
  EXPECT_EQ(parseUpDirection("0 -1 0"), level_optical);
  EXPECT_EQ(parseUpDirection("  [ 0.0 , -1e0 ,0 ]\n"), level_optical);
  EXPECT_EQ(parseUpDirection("[0, -0.8660254037844386, -0.5]"), (UpDirection{0.0, -0.8660254037844386, -0.5}));
  EXPECT_EQ(parseUpDirection("0 0 9.81"), (UpDirection{0.0, 0.0, 9.81}));
}

TEST(UpDirection, NothingIsNoUpDirection) {
  EXPECT_FALSE(parseUpDirection(""));
  EXPECT_FALSE(parseUpDirection("   "));
}

TEST(UpDirection, RefusesWhatIsNotOneAndSaysWhy) {
  EXPECT_NE(errorOf("[0, 0, 0]").find("must not be zero"), std::string::npos) << errorOf("[0, 0, 0]");
  EXPECT_NE(errorOf("0 -1").find("3 numbers x y z, got 2"), std::string::npos) << errorOf("0 -1");
  EXPECT_NE(errorOf("0 -1 0 1").find("got 4"), std::string::npos);
  EXPECT_NE(errorOf("[]").find("got 0"), std::string::npos);
  EXPECT_NE(errorOf("0 down 0").find("'down', not a finite number"), std::string::npos) << errorOf("0 down 0");
  EXPECT_NE(errorOf("[0, -1, 0").find("no closing ']'"), std::string::npos);
  EXPECT_NE(errorOf("0, -1, 0]").find("'0]'"), std::string::npos);
  EXPECT_NE(errorOf("0 nan 1").find("finite"), std::string::npos);
  EXPECT_NE(errorOf("0 inf 1").find("finite"), std::string::npos);
  EXPECT_NE(errorOf("0 1e999 1").find("not a finite number"), std::string::npos);
  // The message quotes what was given.
  EXPECT_NE(errorOf("0 -1").find("'0 -1'"), std::string::npos);
}

TEST(UpDirection, TakesThreeFiniteNumbersNotAllZero) {
  EXPECT_EQ(upDirection({0.0, -1.0, 0.0}), (UpDirection{0.0, -1.0, 0.0}));
  EXPECT_THROW(upDirection({0.0, -1.0}), std::invalid_argument);
  EXPECT_THROW(upDirection({}), std::invalid_argument);
  EXPECT_THROW(upDirection({0.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(upDirection({0.0, std::numeric_limits<double>::quiet_NaN(), 1.0}), std::invalid_argument);
  EXPECT_THROW(upDirection({std::numeric_limits<double>::infinity(), 0.0, 1.0}), std::invalid_argument);
}

RigidTransform transformOf(const Eigen::Quaterniond& rotation, const Eigen::Vector3d& translation) {
  RigidTransform transform;
  transform.translation = {translation.x(), translation.y(), translation.z()};
  transform.rotation = {rotation.x(), rotation.y(), rotation.z(), rotation.w()};
  return transform;
}

TEST(UpDirection, IsTheTargetFramesZAxisInTheSensorsFrame) {
  // The same frame: z.
  const UpDirection same = targetUpInSource(RigidTransform{});
  EXPECT_EQ(same, (UpDirection{0.0, 0.0, 1.0}));
  // An optical frame (x right, y down, z forward) of a camera looking forward and 30 degrees
  // down, in a base frame with z up, as a robot's tf gives it: up is -y turned by the pitch
  // towards -z, whatever the translation.
  const double pitch = 30.0 * M_PI / 180.0;
  const Eigen::Quaterniond optical =
      Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX());
  const Eigen::Quaterniond camera = Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) * optical;
  const UpDirection up = targetUpInSource(transformOf(camera, Eigen::Vector3d(0.1, 0.0, 1.2)));
  EXPECT_NEAR(up[0], 0.0, 1e-12);
  EXPECT_NEAR(up[1], -std::cos(pitch), 1e-12);
  EXPECT_NEAR(up[2], -std::sin(pitch), 1e-12);
  // A level camera: -y.
  const UpDirection level = targetUpInSource(transformOf(optical, Eigen::Vector3d(0.0, 0.0, 0.5)));
  EXPECT_NEAR(level[0], 0.0, 1e-12);
  EXPECT_NEAR(level[1], -1.0, 1e-12);
  EXPECT_NEAR(level[2], 0.0, 1e-12);
  // A quaternion not of unit length is normalized, as tf2 normalizes it.
  RigidTransform scaled = transformOf(camera, Eigen::Vector3d::Zero());
  for (double& value : scaled.rotation) value *= 3.0;
  const UpDirection unscaled = targetUpInSource(scaled);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(unscaled[i], up[i], 1e-12);
}

TEST(UpDirection, RefusesARotationThatIsNone) {
  RigidTransform zero;
  zero.rotation = {0.0, 0.0, 0.0, 0.0};
  EXPECT_THROW(targetUpInSource(zero), std::invalid_argument);
  RigidTransform nan;
  nan.rotation = {0.0, std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0};
  EXPECT_THROW(targetUpInSource(nan), std::invalid_argument);
}

}  // namespace
