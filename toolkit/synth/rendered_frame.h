// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the renderer produces: measured points, ground-truth labels and the plane listing.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "synth/camera.h"
#include "synth/sensor_model.h"

namespace floodplane::synth {

/// One ground-truth plane of a scene, in the camera frame: n . P + d = 0 with `normal` of
/// unit length pointing towards the camera (so d >= 0 is the camera's distance to the
/// plane). Every flat surface of the scene has its own plane, even when two are coplanar.
struct GroundTruthPlane {
  std::uint32_t id = 0;  ///< the label its pixels carry; 1..K in the order of the scene file
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double d = 0.0;
  std::string primitive;  ///< the primitive's name, or its description if it has none
  std::string face;       ///< "" (rectangle, polygon), "+x" ... "-z" (box), "top"/"bottom"
  /// False when the camera sees the surface's back (a box face turned away, a face resting
  /// on the floor), so it cannot have pixels; true for two-sided rectangles and polygons
  /// unless seen exactly edge-on.
  bool faces_camera = false;
  std::size_t pixel_count = 0;  ///< pixels carrying `id` in the rendered frame
  /// The plane whose label this face's pixels carry instead of `id`, when the face touches a
  /// face of that plane in the image and lies in the same plane (a shelf board's front flush
  /// with the side panels' fronts): one continuous flat surface is one ground-truth plane,
  /// whichever primitives make it up. 0: none (the face is its own plane).
  std::uint32_t merged_into = 0;
};

/// The imperfections of a real sensor a frame was rendered with (pcd_synth --quantize-bits,
/// --warp, --speckle, --bend), each off (0, false) unless the frame's sensor model has it on:
/// so the ground truth says what data it describes.
struct SensorQuirks {
  int range_bits = 0;                 ///< scanner: N of the range code (ScannerParams::range_bits)
  double range_code_near = 0.0;       ///< metres, with range_bits
  double range_code_far = 0.0;        ///< metres, with range_bits
  double warp_amplitude = 0.0;        ///< scanner, kinect: peak of the calibration warp, metres
  std::uint64_t warp_seed = 0;        ///< with warp_amplitude
  bool speckle = false;               ///< scanner
  double bend_curvature = 0.0;        ///< kinect: kappa, 1/m (KinectParams::bend_curvature)
  double bend_reference_depth = 0.0;  ///< metres, with bend_curvature

  bool any() const { return range_bits > 0 || warp_amplitude > 0.0 || speckle || bend_curvature != 0.0; }
};

/// An organized frame, row-major, width * height entries in `points` and `labels`.
struct RenderedFrame {
  std::string scene_name;
  std::string scene_description;
  SensorModel sensor = SensorModel::none;
  std::uint64_t seed = 0;
  SensorQuirks quirks;
  CameraIntrinsics intrinsics;
  /// The camera's orientation: the rotation from the camera frame (x right, y down, z forward)
  /// to the scene's world frame, whose z is up (data/scenes/README.md).
  Eigen::Quaterniond world_from_camera = Eigen::Quaterniond::Identity();
  /// The measured point in the camera frame (metres); NaN where the ray hits nothing or the
  /// sensor returns nothing.
  std::vector<Eigen::Vector3f> points;
  /// The ground-truth plane id of the surface each ray hit; 0 where the surface is not
  /// planar or the point is NaN, so a label above 0 always comes with a finite point.
  std::vector<std::uint32_t> labels;
  std::vector<GroundTruthPlane> planes;  ///< ordered by id, planes[i].id == i + 1
};

}  // namespace floodplane::synth
