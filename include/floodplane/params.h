// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <optional>
#include <string>

/// \file
/// floodplane::Params, every parameter of the segmentation with its unit and default.

/// floodplane: plane segmentation of organized point clouds by seeded flood fill. The PCL
/// class FloodFillPlaneSegmentation, the PCL-free core Segmenter, and what works on their
/// results: PlaneTracker, describePlanes, segmentObjects.
namespace floodplane {

/// Every parameter of the segmentation, grouped by the stage that uses it. Lengths are metres,
/// angles radians.
///
/// The defaults are scale-free: the lengths the paper fixes in metres (sigma_plane,
/// sigma_seed, sigma_plane-merge) are left unset and derived, frame by frame, from the
/// sensor's depth noise (measured on the frame unless given) and the pixel footprint (range
/// times the angle between neighbouring rays), so that one set of defaults serves a Kinect at
/// 0.5-8 m, a structured-light scanner at 1 m with 0.5 mm pixels and exact data. Setting one
/// of them gives it the paper's meaning, a fixed length (the noise still widens it where 3
/// standard deviations are more). `problem()` names values the method cannot use.
///
/// A new field goes into the list of src/params/params_table.h too, from which its validation, JSON,
/// Python keyword and stub, ROS entry and command-line flag follow (CONTRIBUTING.md).
struct Params {
  // --- Sec. III-B, the distance function of the flood (Eqs. 1-4) ---
  /// sigma_plane [m]: largest point-to-plane distance of a pixel joining a flood (Eq. 2).
  /// Unset: three standard deviations of the depth noise at the pixel's range, and at least
  /// half the pixel footprint. The paper's value is 0.01.
  std::optional<double> distance_threshold;

  // --- Sec. III-C, seed selection (Eqs. 5-8) ---
  /// sigma_seed [m]: side of the cube around a seed candidate that must be free of distance
  /// and curvature discontinuities (Eqs. 5-7). Unset: the larger of six noise standard
  /// deviations and a few pixel footprints at the candidate's range. The paper's is 0.06.
  std::optional<double> seed_size;
  /// theta_angle [rad]: largest angle between normals in the seed tests (Eqs. 6, 7) and
  /// between two planes that may merge (Eq. 9). The paper's 0.1 rad (about 6 degrees).
  double angular_threshold = 0.1;

  // --- Sec. III-D, plane merging (Eq. 9) ---
  /// sigma_plane-merge [m]: largest distance of one segment's centroid from the other's
  /// plane for the two to merge (Eq. 9). Unset: three noise standard deviations at the
  /// segments' range, at least a pixel footprint. The paper's is 0.03.
  std::optional<double> merge_distance;

  // --- output (OrganizedMultiPlaneSegmentation's parameters) ---
  /// Smallest number of points (at full resolution) a plane must have to be reported.
  /// Unset: one pixel in a thousand of the frame (307 at 640 x 480), so that it scales with
  /// the resolution.
  std::optional<std::uint32_t> min_inliers;
  /// Largest surface curvature lambda_0 / (lambda_0 + lambda_1 + lambda_2) of a reported
  /// plane, as in OMPS. The default 1/3 (the largest possible value) accepts every plane:
  /// the planarity test judges flatness against the noise instead, and OMPS's default of
  /// 0.001 rejects far, noisy walls.
  double maximum_curvature = 1.0 / 3.0;

  // --- beyond the paper ---
  /// Coarse to fine: the side s in {1, 2, 4, 8} of the blocks the coarse pass segments first
  /// (their means, the frame read once); the big planes it finds start the pass over the
  /// pixels, which segments everything else with the tests of s = 1. Labels are always at full
  /// resolution. 4 (the default) finds what 1 finds, in less time on most frames; 1 segments
  /// every pixel from the start (the paper's method).
  int subsampling = 4;
  /// c [1/m] of the depth noise along a viewing ray, sigma(r) = sigma_0 + c r^2. Unset (and
  /// depth_noise_constant unset): both are measured on each frame (self-calibration). Set
  /// either to fix the model; the other is then 0 unless set too. A Kinect's is about 0.0015
  /// (Nguyen et al. 2012); 0 with sigma_0 = 0 is exact data.
  std::optional<double> depth_noise_coefficient;
  /// sigma_0 [m] of the same model.
  std::optional<double> depth_noise_constant;

  /// Whether the noise model is measured on each frame (neither noise field set).
  /// \return true when neither depth_noise_coefficient nor depth_noise_constant is set
  bool estimatesNoise() const { return !depth_noise_coefficient && !depth_noise_constant; }

  /// The first value the method cannot use, as a sentence naming its field
  /// ("seed_size must be a finite number of metres > 0, got -1.000000"); empty when all are
  /// fine. Every entry point validates through this one function.
  /// \return the first problem as a sentence, or an empty string
  std::string problem() const;
  /// Throws std::invalid_argument with problem() when there is one.
  void validate() const;
};

/// The sub-sampling factors the method supports.
/// \param factor a candidate for Params::subsampling
/// \return true for 1, 2, 4 and 8
bool isValidSubsampling(int factor);

}  // namespace floodplane
