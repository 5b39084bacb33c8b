// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "floodplane/noise_model.h"
#include "floodplane/point_grid.h"

namespace floodplane {

/// Self-calibration (beyond the paper): the sensor's depth noise, measured on the frame itself,
/// so that one set of defaults serves a Kinect, a structured-light scanner and exact data.
///
/// Small patches (5 x 5 pixels) on a sparse lattice are fitted with planes from their moment
/// sums. On a flat surface a patch's residual is the sensor's noise, seen across the surface:
/// divided by the cosine of the angle between the surface normal and the viewing ray it becomes
/// the noise along the ray, which is what a depth sensor's noise model describes. Patches that
/// straddle an edge or lie on a tight curve have larger residuals, and in clutter they are
/// many, so each range bin (equal numbers of patches) takes a low quantile of the residuals,
/// corrected for the bias of that quantile of a chi distribution, and the model
///   sigma(r) = sigma_0 + c r^2
/// is fitted to the bins by weighted least squares (relative errors), both terms >= 0.
///
/// Depth quantization: where a sensor reports depths on a lattice (a scanner's fixed steps,
/// a Kinect's disparity steps), the depths of a patch take a few values, a step apart, where
/// continuous depths would hardly ever repeat; the smallest gap between them is a step. The
/// steps are fitted as q(r) = q_0 + q_2 r^2 the same way as the noise.
class NoiseEstimator {
 public:
  /// Measures the noise of `grid`, whose patch points are `spacing` grid points apart.
  /// Fewer than kMinimumPatches flat patches give an estimate with patches < kMinimumPatches,
  /// which the caller should not trust.
  NoiseModel estimate(const PointGrid& grid, int spacing = kPatchSpacing);

  /// The spacing of a patch's points at full resolution [pixels]: real depth cameras' noise is
  /// correlated over neighbouring pixels (a Kinect's disparity comes from a correlation
  /// window), so a patch of adjacent pixels sees a fraction of the scatter that a plane shows
  /// over its extent (c = 0.001 on the real Kinect frames against 0.0015 at a spacing of 4, as
  /// the Kinect's published model).
  static constexpr int kPatchSpacing = 4;

  static constexpr std::size_t kMinimumPatches = 24;

 private:
  struct Patch {
    float range;                // of its centroid [m]
    float sigma;                // residual along the viewing ray [m], unbiased for the degrees of freedom
    int levels;                 // distinct depths (z) among its points
    float smallest_gap;         // between two of them [m]; 0 with one level
    std::uint32_t first_depth;  // its depths, sorted, in depths_
  };
  // The step of the lattice that the depths of patches [begin, end) lie on; 0 when they do not.
  double latticeStep(std::size_t begin, std::size_t end);
  void measurePatch(const PointGrid& grid, int x0, int y0, int spacing);

  std::vector<Patch> patches_;
  std::vector<float> depths_;
  std::vector<float> scratch_;
  std::vector<std::uint32_t> distinct_;  // latticeStep's set of depth bit patterns
};

}  // namespace floodplane
