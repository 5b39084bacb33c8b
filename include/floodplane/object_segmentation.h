// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "floodplane/point_grid.h"
#include "floodplane/segmenter.h"

/// \file
/// floodplane::segmentObjects, the objects standing on the planes of a segmentation.

namespace floodplane {

/// The limits of segmentObjects. Every field must be finite and at least 0 (the counts at
/// least 1, concavity_tolerance_rad below pi/2); segmentObjects throws std::invalid_argument
/// naming the field otherwise.
struct ObjectOptions {
  /// A plane is a support (a table, a floor, a wall things stand or lean on) when the surface
  /// its inliers cover is at least this large [m^2]: the area of the rectangle with their
  /// spread along the plane, 12 sqrt(lambda_1 lambda_2) from the fit's two larger covariance
  /// eigenvalues (as describePlanes measures it). 0.15 m^2: a table top seen from a robot
  /// covers 0.3 m^2 or more; a box's face (30 x 40 cm at most for what a hand grasps) less.
  double min_support_area_m2 = 0.15;
  /// Smaller planes in the plane of a support are pieces of it (a table cut in two by what
  /// stands on it) when their normals are within this angle of the support's [rad] ...
  double support_piece_angle_rad = 0.1;
  /// ... and their centroids within this distance of its plane [m].
  double support_piece_distance_m = 0.02;
  /// A point belongs to an object only when it lies above every support (on the side the
  /// camera sees) by more than three depth noise deviations and the depth step at its range
  /// (the frame's noise model), plus this margin [m]: the support's own points, wherever the
  /// plane left them out, are never in objects. 0: the noise alone (on the mOSD frames no
  /// table pixel is then in an object; a margin only cuts the objects' feet).
  double support_clearance_m = 0.0;
  /// Neighbouring pixels are on one surface when their points are at most this many pixel
  /// footprints apart (the footprint: the angle between neighbouring viewing rays times the
  /// range), in addition to the difference of two noisy depths (3 sqrt(2) sigma(r) and the
  /// depth step of the noise model). 4: a surface seen 76 degrees from face-on still joins; a
  /// depth step between one object and the next, several centimetres, splits.
  double max_step_footprints = 4.0;
  /// Two neighbouring surface patches join when the line between their centroids is convex
  /// with respect to their normals (LCCP's test, Stein et al., CVPR 2014), or when their normals
  /// are within this angle of each other [rad] (LCCP's concavity tolerance, 10 degrees): noise
  /// on a flat or gently curved surface does not split it.
  double concavity_tolerance_rad = 0.1745;
  /// The side of the small patches that cover the points on no plane (a can's wall, a mug's
  /// handle) [pixels].
  int local_patch_pixels = 8;
  /// Objects of fewer pixels are dropped (their pixels labelled 0): a stray fringe of points
  /// is not an object.
  std::uint32_t min_object_pixels = 100;
};

/// One object found on the supports.
struct SegmentedObject {
  std::uint32_t id = 0;                                ///< 1..K, its label; the largest object is 1
  std::uint32_t pixel_count = 0;                       ///< its pixels at full resolution
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< mean of its points (sensor frame) [m]
  Eigen::Vector3d min = Eigen::Vector3d::Zero();       ///< axis-aligned bounding box, sensor frame [m]: its low corner
  Eigen::Vector3d max = Eigen::Vector3d::Zero();       ///< the bounding box's high corner [m]
  /// The label of the plane it stands on (Segmentation::labels' numbering, k for
  /// planes[k - 1]): of the supports, the one nearest below its lowest point; 0 when no plane
  /// is a support.
  std::uint32_t support = 0;
};

/// The objects of one frame.
struct ObjectSegmentation {
  int width = 0;                         ///< the grid's width (points per row)
  int height = 0;                        ///< the grid's height (rows)
  std::vector<std::uint32_t> labels;     ///< row-major, as the grid; 0 = no object, k = objects[k - 1]
  std::vector<SegmentedObject> objects;  ///< largest first
  std::vector<std::uint32_t> supports;   ///< the labels of the planes taken for supports, largest first
};

/// The objects on the planes: the points on no support (large planes, see ObjectOptions, and
/// their pieces) that lie above every support, joined on the image grid where neighbouring
/// points are on one surface (no depth step beyond the frame's noise) and split at concave
/// creases: the surfaces are cut into patches (the segmentation's small planes, a box's faces
/// and a lid, and small square patches over the points on no plane), and neighbouring patches
/// join when they meet convexly (LCCP's test). So a box's faces are one object, while two
/// boxes side by side, a box on a box or a can on a box stay apart where they meet in a
/// concave crease or at a depth step. `planes` must be the segmentation of `grid` (same size);
/// its noise model sets the tolerances. Throws std::invalid_argument when the sizes differ or
/// an option is out of range. Costs O(pixels). Its working buffers are kept per calling thread
/// between calls (about 40 bytes per object point of the largest frame that thread has seen:
/// about 12 MB at 640x480), since fresh pages for them on every frame cost as much as the work
/// in them; they are freed when the thread ends. Safe to call from several threads at once.
/// \param grid    the frame's points
/// \param planes  the segmentation of `grid` (Segmenter::segment)
/// \param options the limits (ObjectOptions)
/// \return the objects, largest first, and a label per pixel
ObjectSegmentation segmentObjects(const PointGrid& grid, const Segmentation& planes,
                                  const ObjectOptions& options = ObjectOptions());

}  // namespace floodplane
