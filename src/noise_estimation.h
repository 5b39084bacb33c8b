#pragma once

#include <cstddef>
#include <vector>

#include "floodplane/point_grid.h"
#include "floodplane/segmenter.h"

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
/// a Kinect's disparity steps), the depths inside a patch differ by whole steps, so the
/// smallest gap between a patch's distinct depths is one step. A bin counts as quantized when
/// its patches agree on that gap; the steps are fitted as q(r) = q_0 + q_2 r^2 the same way.
class NoiseEstimator {
 public:
  /// Measures the noise of `grid`. Fewer than kMinimumPatches flat patches give an estimate
  /// with patches < kMinimumPatches, which the caller should not trust.
  NoiseModel estimate(const PointGrid& grid);

  static constexpr std::size_t kMinimumPatches = 24;

 private:
  struct Patch {
    float range;      // of its centroid [m]
    float sigma;      // residual along the viewing ray [m], unbiased for the degrees of freedom
    float depth_gap;  // smallest gap between its distinct depths [m]; 0 with fewer than two
  };
  void measurePatch(const PointGrid& grid, int x0, int y0);

  std::vector<Patch> patches_;
  std::vector<float> scratch_;
};

}  // namespace floodplane
