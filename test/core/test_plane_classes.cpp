// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// describePlanes on planes made by hand in a camera's frame (x right, y down, z forward), the
// camera 1.5 m above the floor: classes, heights, the rules' edges and bad input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "floodplane/plane_classes.h"

namespace floodplane {
namespace {

const Eigen::Vector3d kUp(0.0, -1.0, 0.0);  // the camera's y points down
constexpr double kCameraHeight = 1.5;

// A plane through `centroid` with unit `normal` (which must face the camera at the origin),
// its inliers covering a rectangle `width` x `length` [m] uniformly (the fit's eigenvalues).
SegmentedPlane plane(const Eigen::Vector3d& normal, const Eigen::Vector3d& centroid, double width, double length) {
  SegmentedPlane p;
  p.fit.normal = normal.normalized();
  p.fit.centroid = centroid;
  p.fit.offset = -p.fit.normal.dot(centroid);
  p.fit.eigenvalues = Eigen::Vector3d(1e-6, std::min(width, length) * std::min(width, length) / 12.0,
                                      std::max(width, length) * std::max(width, length) / 12.0);
  p.fit.valid = true;
  p.inlier_count = 1000;
  return p;
}

// A horizontal plane facing up at `height` above the floor, `depth` metres ahead.
SegmentedPlane upFacing(double height, double depth, double width, double length) {
  return plane(kUp, Eigen::Vector3d(0.2, kCameraHeight - height, depth), width, length);
}

// The up-facing normal turned by `angle` about the camera's x axis (towards the camera).
Eigen::Vector3d tilted(double angle) { return Eigen::AngleAxisd(-angle, Eigen::Vector3d::UnitX()) * kUp; }

// The normal of a wall ahead, facing the camera, turned by `angle` about the camera's x axis.
Eigen::Vector3d leaning(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()) * -Eigen::Vector3d::UnitZ();
}

std::vector<PlaneClass> classesOf(const std::vector<PlaneDescription>& descriptions) {
  std::vector<PlaneClass> classes;
  for (const PlaneDescription& d : descriptions) classes.push_back(d.plane_class);
  return classes;
}

TEST(PlaneClasses, NamesEveryClass) {
  EXPECT_STREQ(planeClassName(PlaneClass::kOther), "other");
  EXPECT_STREQ(planeClassName(PlaneClass::kFloor), "floor");
  EXPECT_STREQ(planeClassName(PlaneClass::kCeiling), "ceiling");
  EXPECT_STREQ(planeClassName(PlaneClass::kWall), "wall");
  EXPECT_STREQ(planeClassName(PlaneClass::kHorizontalSurface), "horizontal_surface");
  EXPECT_STREQ(planeClassName(static_cast<PlaneClass>(9)), "unknown");
}

// A room: the floor below the camera, a table, a wall ahead, the ceiling above, a ramp.
TEST(PlaneClasses, TellsFloorTableWallCeilingAndRamp) {
  const std::vector<SegmentedPlane> planes = {
      upFacing(0.0, 3.0, 4.0, 4.0),                                                             // floor
      upFacing(0.75, 1.8, 1.2, 0.8),                                                            // table top
      plane(Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0.5, 0.3, 5.0), 4.0, 2.8),               // wall ahead
      plane(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, kCameraHeight - 2.7, 3.0), 4.0, 5.0),  // ceiling
      plane(tilted(10.0 * M_PI / 180.0), Eigen::Vector3d(-1.0, 1.3, 3.0), 1.0, 2.0),            // ramp
  };
  const std::vector<PlaneDescription> described = describePlanes(planes, kUp);
  ASSERT_EQ(described.size(), planes.size());
  EXPECT_EQ(classesOf(described),
            (std::vector<PlaneClass>{PlaneClass::kFloor, PlaneClass::kHorizontalSurface, PlaneClass::kWall,
                                     PlaneClass::kCeiling, PlaneClass::kOther}));
  EXPECT_NEAR(described[0].height_above_floor, 0.0, 1e-12);
  EXPECT_NEAR(described[1].height_above_floor, 0.75, 1e-12);
  EXPECT_NEAR(described[2].height_above_floor, kCameraHeight - 0.3, 1e-12);
  EXPECT_NEAR(described[3].height_above_floor, 2.7, 1e-12);
  EXPECT_NEAR(described[4].height_above_floor, 0.2, 1e-12);
}

// The floor is the lowest large up-facing plane, not the largest: a big platform above it is a
// horizontal surface; pieces of the floor (between furniture) are floor, a step and a pit not.
TEST(PlaneClasses, FloorIsTheLowestLargePlaneAndItsPiecesAtItsHeight) {
  const std::vector<SegmentedPlane> planes = {
      upFacing(0.4, 3.0, 5.0, 5.0),    // a platform larger than the floor
      upFacing(0.0, 2.0, 1.0, 1.0),    // the floor: 1 m^2
      upFacing(0.03, 4.0, 0.3, 0.3),   // a floor piece, fitted 3 cm high
      upFacing(-0.04, 2.5, 0.2, 0.5),  // and one 4 cm low
      upFacing(0.17, 3.5, 0.28, 1.0),  // a step
      upFacing(-0.3, 1.5, 0.5, 0.5),   // a pit, too small to be the floor
  };
  const std::vector<PlaneDescription> described = describePlanes(planes, kUp);
  EXPECT_EQ(
      classesOf(described),
      (std::vector<PlaneClass>{PlaneClass::kHorizontalSurface, PlaneClass::kFloor, PlaneClass::kFloor,
                               PlaneClass::kFloor, PlaneClass::kHorizontalSurface, PlaneClass::kHorizontalSurface}));
  EXPECT_NEAR(described[0].height_above_floor, 0.4, 1e-12);
  EXPECT_NEAR(described[5].height_above_floor, -0.3, 1e-12);
}

// A plane smaller than min_floor_area_m2 is never the floor, however low.
TEST(PlaneClasses, SmallPlanesAreNotTheFloor) {
  PlaneClassOptions options;
  options.min_floor_area_m2 = 2.0;
  const std::vector<SegmentedPlane> planes = {upFacing(0.0, 3.0, 1.0, 1.5), upFacing(0.7, 2.0, 2.0, 1.5)};
  const std::vector<PlaneDescription> described = describePlanes(planes, kUp, options);
  EXPECT_EQ(classesOf(described), (std::vector<PlaneClass>{PlaneClass::kHorizontalSurface, PlaneClass::kFloor}));
  EXPECT_NEAR(described[0].height_above_floor, -0.7, 1e-12);
}

// Without a floor in view: heights are NaN, horizontal planes are surfaces, walls walls, and a
// large down-facing plane is the ceiling by its size alone.
TEST(PlaneClasses, WithoutAFloorHeightsAreNaNAndOrientationStillCounts) {
  const std::vector<SegmentedPlane> planes = {
      upFacing(0.75, 1.0, 0.6, 0.5),                                               // a small table top
      plane(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-1.0, 0.5, 2.0), 2.0, 2.0),  // a wall on the left
      plane(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, -1.0, 2.0), 3.0, 3.0),    // a ceiling
      plane(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, -0.5, 1.0), 0.3, 0.3),    // a shelf's underside
  };
  const std::vector<PlaneDescription> described = describePlanes(planes, kUp);
  EXPECT_EQ(classesOf(described), (std::vector<PlaneClass>{PlaneClass::kHorizontalSurface, PlaneClass::kWall,
                                                           PlaneClass::kCeiling, PlaneClass::kOther}));
  for (const PlaneDescription& d : described) EXPECT_TRUE(std::isnan(d.height_above_floor));
}

// The normal's sign tells a floor from the underside of something: a large down-facing plane
// low over the floor (a table's underside seen from below) is other, not the ceiling.
TEST(PlaneClasses, DownFacingPlanesLowOverTheFloorAreNotTheCeiling) {
  const std::vector<SegmentedPlane> planes = {
      upFacing(0.0, 3.0, 4.0, 4.0),
      plane(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, kCameraHeight - 0.7, 2.0), 1.8, 1.0),  // underside
      plane(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, kCameraHeight - 2.4, 2.0), 3.0, 3.0),  // ceiling
  };
  EXPECT_EQ(classesOf(describePlanes(planes, kUp)),
            (std::vector<PlaneClass>{PlaneClass::kFloor, PlaneClass::kOther, PlaneClass::kCeiling}));
}

// The tolerances are angles from horizontal and from vertical, either side.
TEST(PlaneClasses, TolerancesBoundHorizontalAndVertical) {
  const PlaneClassOptions defaults;
  const double inside = 0.9 * defaults.horizontal_tolerance_rad;
  const double outside = 1.1 * defaults.horizontal_tolerance_rad;
  const std::vector<SegmentedPlane> planes = {
      upFacing(0.0, 3.0, 4.0, 4.0),
      plane(tilted(inside), Eigen::Vector3d(0, 0.8, 2.0), 0.5, 0.5),
      plane(tilted(outside), Eigen::Vector3d(0, 0.8, 2.0), 0.5, 0.5),
      // Walls ahead leaning towards or away from the camera.
      plane(leaning(0.9 * defaults.vertical_tolerance_rad), Eigen::Vector3d(0, 0, 3.0), 1.0, 1.0),
      plane(leaning(-0.9 * defaults.vertical_tolerance_rad), Eigen::Vector3d(0, 0, 3.0), 1.0, 1.0),
      plane(leaning(1.1 * defaults.vertical_tolerance_rad), Eigen::Vector3d(0, 0, 3.0), 1.0, 1.0),
      plane(leaning(-1.1 * defaults.vertical_tolerance_rad), Eigen::Vector3d(0, 0, 3.0), 1.0, 1.0),
  };
  EXPECT_EQ(classesOf(describePlanes(planes, kUp)),
            (std::vector<PlaneClass>{PlaneClass::kFloor, PlaneClass::kHorizontalSurface, PlaneClass::kOther,
                                     PlaneClass::kWall, PlaneClass::kWall, PlaneClass::kOther, PlaneClass::kOther}));
  PlaneClassOptions wider;
  wider.horizontal_tolerance_rad = 1.2 * defaults.horizontal_tolerance_rad;
  EXPECT_EQ(describePlanes(planes, kUp, wider)[2].plane_class, PlaneClass::kHorizontalSurface);
}

// Any length of up gives the same answer, and so does any frame: the planes and up turned
// together (a camera rolled and pitched) describe the same room.
TEST(PlaneClasses, UpNeedNotBeUnitNorTheCamerasY) {
  std::vector<SegmentedPlane> planes = {upFacing(0.0, 3.0, 4.0, 4.0), upFacing(0.75, 1.8, 1.2, 0.8),
                                        plane(Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0.5, 0.3, 5.0), 4.0, 2.8),
                                        plane(tilted(0.3), Eigen::Vector3d(-1.0, 1.3, 3.0), 1.0, 2.0)};
  const std::vector<PlaneDescription> reference = describePlanes(planes, kUp);
  const std::vector<PlaneDescription> scaled = describePlanes(planes, 9.81 * kUp);
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  for (SegmentedPlane& p : planes) {
    p.fit.normal = turn * p.fit.normal;
    p.fit.centroid = turn * p.fit.centroid;
  }
  const std::vector<PlaneDescription> turned = describePlanes(planes, 0.01 * (turn * kUp));
  ASSERT_EQ(scaled.size(), reference.size());
  ASSERT_EQ(turned.size(), reference.size());
  for (std::size_t k = 0; k < reference.size(); ++k) {
    EXPECT_EQ(scaled[k].plane_class, reference[k].plane_class) << "plane " << k;
    EXPECT_EQ(turned[k].plane_class, reference[k].plane_class) << "plane " << k;
    EXPECT_NEAR(scaled[k].height_above_floor, reference[k].height_above_floor, 1e-12);
    EXPECT_NEAR(turned[k].height_above_floor, reference[k].height_above_floor, 1e-12);
  }
  EXPECT_EQ(classesOf(reference), (std::vector<PlaneClass>{PlaneClass::kFloor, PlaneClass::kHorizontalSurface,
                                                           PlaneClass::kWall, PlaneClass::kOther}));
}

// The height is measured along up from the floor's plane, which may be tilted a little by
// its fit: the point below the centroid on the floor's plane, not the floor's centroid.
TEST(PlaneClasses, HeightIsAlongUpFromTheFloorsPlane) {
  const double tilt = 0.05;  // rad, within the tolerance
  SegmentedPlane floor = plane(tilted(tilt), Eigen::Vector3d(0, kCameraHeight, 3.0), 4.0, 4.0);
  const Eigen::Vector3d table_centroid(0, kCameraHeight - 0.75, 2.0);
  const std::vector<PlaneDescription> described = describePlanes({floor, plane(kUp, table_centroid, 1.0, 1.0)}, kUp);
  // The tilted floor rises towards the camera by tan(tilt) a metre: below the table's centroid,
  // 1 m nearer than its own, it is tan(tilt) higher.
  EXPECT_NEAR(described[1].height_above_floor, 0.75 - std::tan(tilt), 1e-9);
  EXPECT_GT(std::abs(described[1].height_above_floor - 0.75), 0.04) << "the tilt shows";
}

TEST(PlaneClasses, NoPlanesNoDescriptions) { EXPECT_TRUE(describePlanes({}, kUp).empty()); }

// A plane whose fit says nothing (a zero or NaN normal) is other, and does not stop the rest.
TEST(PlaneClasses, PlanesWithoutANormalAreOther) {
  SegmentedPlane zero = upFacing(0.5, 2.0, 1.0, 1.0);
  zero.fit.normal = Eigen::Vector3d::Zero();
  SegmentedPlane nan = upFacing(0.5, 2.0, 1.0, 1.0);
  nan.fit.normal.x() = std::numeric_limits<double>::quiet_NaN();
  const std::vector<PlaneDescription> described = describePlanes({zero, nan, upFacing(0.0, 3.0, 4.0, 4.0)}, kUp);
  EXPECT_EQ(classesOf(described),
            (std::vector<PlaneClass>{PlaneClass::kOther, PlaneClass::kOther, PlaneClass::kFloor}));
  EXPECT_NEAR(described[0].height_above_floor, 0.5, 1e-12);
}

TEST(PlaneClasses, RefusesAZeroOrNonFiniteUp) {
  const std::vector<SegmentedPlane> planes = {upFacing(0.0, 3.0, 4.0, 4.0)};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& up :
       {Eigen::Vector3d::Zero().eval(), Eigen::Vector3d(0, nan, 0), Eigen::Vector3d(inf, 0, 0)}) {
    try {
      describePlanes(planes, up);
      ADD_FAILURE() << "accepted up " << up.transpose();
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("up direction"), std::string::npos) << error.what();
    }
  }
  // Lengths whose squares would underflow or overflow are still directions.
  EXPECT_EQ(describePlanes(planes, Eigen::Vector3d(0, -1e-200, 0))[0].plane_class, PlaneClass::kFloor);
  EXPECT_EQ(describePlanes(planes, Eigen::Vector3d(0, -1e300, 0))[0].plane_class, PlaneClass::kFloor);
}

TEST(PlaneClasses, RefusesOptionsOutOfRangeNamingThem) {
  const std::vector<SegmentedPlane> planes = {upFacing(0.0, 3.0, 4.0, 4.0)};
  const auto expectRefused = [&planes](PlaneClassOptions options, const std::string& field) {
    try {
      describePlanes(planes, kUp, options);
      ADD_FAILURE() << field << " accepted";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find(field), std::string::npos) << error.what();
    }
  };
  PlaneClassOptions o;
  o.horizontal_tolerance_rad = -0.1;
  expectRefused(o, "horizontal_tolerance_rad");
  o = PlaneClassOptions();
  o.vertical_tolerance_rad = 0.8;  // above pi/4: a plane could be horizontal and vertical
  expectRefused(o, "vertical_tolerance_rad");
  o = PlaneClassOptions();
  o.min_floor_area_m2 = std::numeric_limits<double>::quiet_NaN();
  expectRefused(o, "min_floor_area_m2");
  o = PlaneClassOptions();
  o.floor_height_tolerance_m = -1.0;
  expectRefused(o, "floor_height_tolerance_m");
  o = PlaneClassOptions();
  o.min_ceiling_area_m2 = std::numeric_limits<double>::infinity();
  expectRefused(o, "min_ceiling_area_m2");
  o = PlaneClassOptions();
  o.min_ceiling_height_m = -0.5;
  expectRefused(o, "min_ceiling_height_m");
}

}  // namespace
}  // namespace floodplane
