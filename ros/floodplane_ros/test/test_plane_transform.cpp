// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Planes moved into a target frame: a camera's floor seen from a robot's base, and the
// invariants of any rigid transform (distances kept, the sensor's side kept).

#include "plane_transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>

namespace {

using floodplane::conversion::PlaneDescription;
using floodplane::conversion::RigidTransform;
using floodplane::conversion::transformPlane;

RigidTransform transformOf(const Eigen::Quaterniond& rotation, const Eigen::Vector3d& translation) {
  RigidTransform transform;
  transform.translation = {translation.x(), translation.y(), translation.z()};
  transform.rotation = {rotation.x(), rotation.y(), rotation.z(), rotation.w()};
  return transform;
}

// An optical frame (x right, y down, z forward) 1.2 m above the floor, looking forward and
// 30 degrees down, in a base frame with z up whose origin is on the floor.
Eigen::Quaterniond downwardCamera() {
  const double pitch = 30.0 * M_PI / 180.0;
  const Eigen::Quaterniond optical =
      Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX());
  return Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) * optical;
}

TEST(PlaneTransform, PutsACamerasFloorAtTheBasesFloor) {
  const Eigen::Quaterniond rotation = downwardCamera();
  const Eigen::Vector3d translation(0.1, 0.0, 1.2);
  // The floor z = 0 of the base, in the camera's frame: the normal facing the camera (up).
  const Eigen::Vector3d normal = rotation.inverse() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d centroid = rotation.inverse() * (Eigen::Vector3d(2.0, 0.5, 0.0) - translation);
  PlaneDescription floor;
  floor.coefficients = {normal.x(), normal.y(), normal.z(), -normal.dot(centroid)};
  floor.centroid = {centroid.x(), centroid.y(), centroid.z()};
  floor.label = 3;
  floor.inlier_count = 1234;
  floor.plane_class = floodplane::PlaneClass::kFloor;
  floor.height_above_floor = 0.002;
  // The camera is 1.2 m above the floor, on the side its normal points to.
  EXPECT_NEAR(floor.coefficients[3], 1.2, 1e-12);

  const PlaneDescription moved = transformPlane(floor, transformOf(rotation, translation));
  EXPECT_NEAR(moved.coefficients[0], 0.0, 1e-12);
  EXPECT_NEAR(moved.coefficients[1], 0.0, 1e-12);
  EXPECT_NEAR(moved.coefficients[2], 1.0, 1e-12);
  EXPECT_NEAR(moved.coefficients[3], 0.0, 1e-12);
  EXPECT_NEAR(moved.centroid[0], 2.0, 1e-12);
  EXPECT_NEAR(moved.centroid[1], 0.5, 1e-12);
  EXPECT_NEAR(moved.centroid[2], 0.0, 1e-12);
  EXPECT_EQ(moved.label, 3u);
  EXPECT_EQ(moved.inlier_count, 1234u);
  // What it is and its height do not depend on the frame.
  EXPECT_EQ(moved.plane_class, floodplane::PlaneClass::kFloor);
  EXPECT_EQ(moved.height_above_floor, 0.002);
}

TEST(PlaneTransform, KeepsEveryPointsDistanceAndTheSensorsSide) {
  const Eigen::Quaterniond rotation(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()));
  const Eigen::Vector3d translation(-0.4, 2.5, 0.3);
  const Eigen::Vector3d normal = Eigen::Vector3d(0.2, -0.3, -0.9).normalized();
  PlaneDescription plane;
  plane.coefficients = {normal.x(), normal.y(), normal.z(), 1.7};
  plane.centroid = {0.5, 0.1, 1.6};
  // A quaternion of another length than 1 is the same rotation (tf2 normalizes it too).
  RigidTransform transform = transformOf(rotation, translation);
  for (double& q : transform.rotation) q *= 3.0;
  const PlaneDescription moved = transformPlane(plane, transform);
  const Eigen::Vector3d moved_normal(moved.coefficients[0], moved.coefficients[1], moved.coefficients[2]);
  EXPECT_NEAR(moved_normal.norm(), 1.0, 1e-12);
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-2, 0.5, 4)}) {
    const double before = normal.dot(p) + plane.coefficients[3];
    const double after = moved_normal.dot(rotation * p + translation) + moved.coefficients[3];
    EXPECT_NEAR(after, before, 1e-12);
  }
  const Eigen::Vector3d centroid = rotation * Eigen::Vector3d(0.5, 0.1, 1.6) + translation;
  EXPECT_NEAR(moved.centroid[0], centroid.x(), 1e-12);
  EXPECT_NEAR(moved.centroid[2], centroid.z(), 1e-12);
}

TEST(PlaneTransform, RefusesATransformThatIsNone) {
  PlaneDescription plane;
  plane.coefficients = {0, 0, -1, 2};
  RigidTransform zero;
  zero.rotation = {0, 0, 0, 0};
  EXPECT_THROW(transformPlane(plane, zero), std::invalid_argument);
  RigidTransform nan;
  nan.translation[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(transformPlane(plane, nan), std::invalid_argument);
  const PlaneDescription same = transformPlane(plane, RigidTransform());
  EXPECT_EQ(same.coefficients, plane.coefficients);
}

}  // namespace
