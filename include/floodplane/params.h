#pragma once

#include <cstdint>
#include <string>

namespace floodplane {

/// Every parameter of the segmentation, grouped by the stage that uses it. Defaults are the
/// values of the paper's Sec. IV where the paper has one; the rest are stated with a reason.
/// Lengths are metres, angles radians. `validate()` rejects values the method cannot use.
struct Params {
  // --- Sec. III-B, the distance function of the flood (Eqs. 1-4) ---
  /// sigma_plane: largest point-to-plane distance of a pixel joining a flood (Eq. 2). [m]
  double distance_threshold = 0.01;

  // --- Sec. III-C, seed selection (Eqs. 5-8) ---
  /// sigma_seed: side of the cube around a seed candidate that must be free of distance and
  /// curvature discontinuities (Eq. 5-7). [m]
  double seed_size = 0.06;
  /// theta_angle: largest angle between normals in the seed tests (Eqs. 6, 7) and between
  /// two planes that may merge (Eq. 9). [rad] The paper's 0.1 rad (about 6 degrees).
  double angular_threshold = 0.1;

  // --- Sec. III-D, plane merging (Eq. 9) ---
  /// sigma_plane-merge: largest distance of one segment's centroid from the other's plane
  /// for the two to merge (Eq. 9). [m]
  double merge_distance = 0.03;

  // --- output (OrganizedMultiPlaneSegmentation's parameters) ---
  /// Smallest number of points (at full resolution) a plane must have to be reported.
  /// The paper gives none; 300 keeps table tops and stair steps at a few metres while
  /// dropping the scraps that noise leaves at object borders.
  std::uint32_t min_inliers = 300;
  /// Largest surface curvature lambda_0 / (lambda_0 + lambda_1 + lambda_2) of a reported
  /// plane, as in OMPS. The default 1/3 (the largest possible value) accepts every plane:
  /// the flood's distance test already bounds the thickness of a plane, and OMPS's default
  /// of 0.001 rejects far, noisy walls.
  double maximum_curvature = 1.0 / 3.0;
  /// Project each plane's boundary contour onto the plane along the viewing rays (as OMPS).
  bool project_points = false;

  // --- beyond the paper ---
  /// Sub-sampling factor s in {1, 2, 4, 8}: segment every s-th pixel of every s-th row
  /// (Table III), then bring the labels back to full resolution, pixel by pixel.
  int subsampling = 1;
  /// c in sigma_depth(r) = c * r^2: how fast the sensor's depth noise grows with range r.
  /// The flood, seed and merge tolerances widen to 3 sigma_depth where that exceeds the
  /// fixed thresholds above. The default fits a Kinect-class structured-light camera
  /// (axial noise of Nguyen et al. 2012 plus 1/8-pixel disparity quantisation); 0 gives
  /// the paper's fixed thresholds, right for noise-free or laser data.
  double depth_noise_coefficient = 0.0019;

  /// The first value the method cannot use, as a sentence naming its field
  /// ("seed_size must be a finite number of metres > 0, got -1.000000"); empty when all are
  /// fine. Every entry point validates through this one function.
  std::string problem() const;
  /// Throws std::invalid_argument with problem() when there is one.
  void validate() const;
};

/// The sub-sampling factors the method supports.
bool isValidSubsampling(int factor);

}  // namespace floodplane
