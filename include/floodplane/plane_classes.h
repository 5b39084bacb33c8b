// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "floodplane/segmenter.h"

/// \file
/// floodplane::describePlanes: what each plane is (floor, ceiling, wall, horizontal surface)
/// given the up direction.

namespace floodplane {

/// What a plane is, told by its orientation to the up direction and its place among the
/// others (describePlanes).
enum class PlaneClass : std::uint8_t {
  kOther = 0,              ///< inclined (a ramp, a tilted board), or horizontal but not one of the classes below
  kFloor = 1,              ///< the lowest large up-facing horizontal plane, and its pieces at its height
  kCeiling = 2,            ///< a large down-facing horizontal plane high above the floor
  kWall = 3,               ///< any vertical plane
  kHorizontalSurface = 4,  ///< another up-facing horizontal plane: a table top, a shelf, a step's tread
};

/// "other", "floor", "ceiling", "wall", "horizontal_surface" (the names of the JSON output and
/// of the Python module); "unknown" for a value outside the enumeration.
/// \param plane_class the class to name
/// \return its name, a static string
const char* planeClassName(PlaneClass plane_class);

/// The limits of describePlanes. Every field must be finite and at least 0; the two angles
/// below pi/4, so that no plane is both horizontal and vertical.
struct PlaneClassOptions {
  /// A plane is horizontal when its normal is within this angle of up or of down [rad].
  /// 0.1 rad (5.7 degrees): wider than the fitted normal's error on a small plane under Kinect
  /// noise (in the bundled scenes, a horizontal plane's fit is within 0.018 rad of level: a
  /// box top and the 28 cm treads 3 m away), narrower than a steep ramp (10 degrees, 0.17
  /// rad), which is then "other"; a ramp of 1:12 (4.8 degrees, the steepest a wheelchair
  /// takes) is horizontal.
  double horizontal_tolerance_rad = 0.1;
  /// A plane is vertical (a wall) when its normal is within this angle of perpendicular to up
  /// [rad]. 0.1 rad for the same reason: the fit's error on a narrow face at range (in the
  /// bundled scenes under Kinect noise, 0.07 rad off upright on a table top's 4 cm edge, 0.05
  /// on a 17 cm riser).
  double vertical_tolerance_rad = 0.1;
  /// The floor is the lowest up-facing horizontal plane at least this large [m^2]. The area is
  /// that of a rectangle with the inliers' spread along the plane, 12 sqrt(lambda_1 lambda_2)
  /// from the fit's two larger covariance eigenvalues (exact for a uniformly covered
  /// rectangle): a property of the surface seen, not of the sensor's resolution or the
  /// distance. Pixels crowd where the surface is near, so a floor running away from the camera
  /// comes out smaller than it is. 0.75 m^2: the floors of the bundled scenes' views measure
  /// 1.06-15.9 m^2, a box top or a step far less; but a table top can be as large (0.6-0.9
  /// there, a platform 1.26), so with no floor in view a large table may be taken for it.
  double min_floor_area_m2 = 0.75;
  /// Up-facing horizontal planes within this distance of the floor's plane (along up) [m] are
  /// floor too: the floor seen in pieces between furniture legs and boxes. 0.05 m: a floor
  /// piece's fit far away under Kinect noise is a few centimetres off; a doorstep or a rug is
  /// floor, a step (15 cm or more) is not.
  double floor_height_tolerance_m = 0.05;
  /// A down-facing horizontal plane is the ceiling when it is at least this large [m^2] (the
  /// area as for the floor) ...
  double min_ceiling_area_m2 = 0.75;
  /// ... and, when a floor was found, at least this high above it [m]: below that, a large
  /// down-facing plane is the underside of a table or a shelf seen from below (other). 1.8 m:
  /// under a door's head.
  double min_ceiling_height_m = 1.8;
};

/// What describePlanes says of one plane.
struct PlaneDescription {
  PlaneClass plane_class = PlaneClass::kOther;  ///< what the plane is
  /// The signed distance along up from the floor's plane to the plane's centroid [m]: 0 for
  /// the floor, 0.75 for a table top 0.75 m high, negative below the floor; NaN when no floor
  /// was found (and for a plane whose centroid is not finite).
  double height_above_floor = 0.0;
};

/// Classes the planes of one frame by the up direction: one description per plane, in the
/// order of `planes`. `up` is the up direction (opposite gravity) in the planes' frame (for a
/// Segmentation, the cloud's axes); it need not be unit length. Throws std::invalid_argument
/// when `up` is zero or not finite, or an option is out of range (naming it).
///
/// A plane's normal faces the sensor (as every fit of the segmenter does), so its sign tells
/// an up-facing plane (a floor, seen from above) from a down-facing one (a ceiling, seen from
/// below). In order:
///  - normal within horizontal_tolerance_rad of up: up-facing horizontal. The lowest (along
///    up, at its centroid) of those at least min_floor_area_m2 large is the floor; every
///    up-facing horizontal plane within floor_height_tolerance_m of its plane is floor too,
///    the others are horizontal surfaces (tables, shelves, treads; below the floor too). With
///    no floor, all are horizontal surfaces.
///  - normal within horizontal_tolerance_rad of down: ceiling when at least
///    min_ceiling_area_m2 large and, if there is a floor, min_ceiling_height_m above it;
///    otherwise other.
///  - normal within vertical_tolerance_rad of perpendicular to up: wall, whatever its size (a
///    cupboard's side and a stair's riser too: what a robot cannot pass through).
///  - anything else, and a plane whose normal is zero or not finite: other.
/// Costs O(planes).
/// \param planes  the planes of one frame (Segmentation::planes)
/// \param up      the up direction in the planes' frame, any length but 0
/// \param options the limits (PlaneClassOptions)
/// \return one description per plane, in the order of `planes`
std::vector<PlaneDescription> describePlanes(const std::vector<SegmentedPlane>& planes, const Eigen::Vector3d& up,
                                             const PlaneClassOptions& options = PlaneClassOptions());

}  // namespace floodplane
