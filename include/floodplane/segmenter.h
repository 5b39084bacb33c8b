// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "floodplane/noise_model.h"
#include "floodplane/params.h"
#include "floodplane/plane_fit.h"
#include "floodplane/point_grid.h"

/// \file
/// floodplane::Segmenter, the PCL-free core, and its result floodplane::Segmentation.

namespace floodplane {

/// Time spent in each phase of one segmentation (the paper's Fig. 5), in milliseconds.
/// Filled only when Segmenter::Options::measure_phases is set.
struct PhaseTimes {
  double preparation = 0.0;     ///< noise estimation, hole filling, smoothing, sub-sampling
  double seed_selection = 0.0;  ///< scanning for seeds and testing them (Sec. III-C)
  double flood_fill = 0.0;      ///< growing segments (Sec. III-A, III-B); at s > 1 also the coarse planes claimed
                                ///< into the fine pass
  double relabelling = 0.0;     ///< connected components after Eq. 4 reassignments
  double merging = 0.0;         ///< agglomerative plane merging (Sec. III-D)
  double region_output = 0.0;   ///< labels at full resolution, refinement, plane fits
  /// The PCL class's work around the core: input checks, the shift to the sensor origin and
  /// PCL's outputs (regions, coefficients, indices, the label cloud). 0 from Segmenter.
  double pcl_conversion = 0.0;
  /// \return the sum of the phases [ms]
  double total() const {
    return preparation + seed_selection + flood_fill + relabelling + merging + region_output + pcl_conversion;
  }
};

/// What happened inside one segmentation, for tests, benchmarks and curious users.
struct SegmentationStats {
  std::size_t seed_candidates = 0;    ///< unclaimed pixels tested as seeds
  std::size_t seeds = 0;              ///< candidates that passed Eqs. 5-7 (one flood each)
  std::size_t pixels_taken_over = 0;  ///< pixels reassigned by Eq. 4
  std::size_t segments = 0;           ///< segments after relabelling
  std::size_t merges = 0;             ///< merges by Eq. 9
  /// The noise model was the previous frame's (Segmenter::Options::head_start), not measured.
  bool head_start = false;
};

/// One plane found in the cloud.
struct SegmentedPlane {
  PlaneFit fit;                    ///< least-squares plane of the inliers (sensor frame)
  std::uint32_t inlier_count = 0;  ///< pixels at full resolution
  /// Where its boundary starts: its first pixel in raster order; at sub-sampling s > 1 the left
  /// end of the row through the first pixel of its body (the first block inside it), so
  /// that a stray pixel that fits the plane apart from it does not stand for its boundary.
  std::size_t first_pixel = 0;
};

/// The result: a label per pixel of the full-resolution grid and the planes.
struct Segmentation {
  int width = 0;                       ///< the grid's width (points per row)
  int height = 0;                      ///< the grid's height (rows)
  std::vector<std::uint32_t> labels;   ///< row-major; 0 = no plane, k = planes[k - 1]
  std::vector<SegmentedPlane> planes;  ///< largest first
  NoiseModel noise;                    ///< the depth noise the segmentation assumed
  PhaseTimes phases;                   ///< time per phase, with Segmenter::Options::measure_phases
  SegmentationStats stats;             ///< counts of what happened inside

  /// Appends the outer boundary of planes[plane] to `contour`: linear pixel indices in order,
  /// clockwise on screen (y down), 8-connected, starting at the plane's first pixel; a pixel
  /// on a one-pixel-wide neck appears twice. Costs the boundary's length, not the area.
  /// \param plane        index into planes (label - 1)
  /// \param[out] contour the boundary's pixels are appended to it
  void boundary(std::size_t plane, std::vector<int>& contour) const;
};

/// The paper's method over a plain point grid, PCL-free: seed selection, span flood fill
/// with the distance buffer, union-find relabelling, plane merging, region output.
/// The sensor is at the grid's origin. One instance per thread; every buffer is kept between
/// calls, so segmenting frames of one size allocates nothing after the first frame.
class Segmenter {
 public:
  /// What one call of segment() does besides the segmentation.
  struct Options {
    /// After merging, grow each plane into neighbouring unlabelled pixels that fit it (the
    /// counterpart of OMPS's refinement; segmentAndRefine sets it).
    bool refine = true;
    /// Fill Segmentation::phases (a few clock reads per flood).
    bool measure_phases = false;
    /// The frame continues the last one this Segmenter segmented (a stream from one sensor):
    /// that frame's noise models (raw, smoothed, of the block means) are taken again instead of
    /// measured anew, which saves the noise measurements (bench/HISTORY.md, "Head start"); it is
    /// measured again every kNoiseRefreshFrames frames, and whenever the last estimate rested
    /// on too few flat patches. A cold start on the first frame, after setParams, after a
    /// failed call, when the size changed, and when Params fix the noise. Planes are those of
    /// a cold start up to the frame-to-frame scatter of the noise estimate (see
    /// bench/HISTORY.md, "Head start").
    bool head_start = false;
  };

  /// With head starts, the noise model is measured again on every this-many-th frame (one
  /// second at 30 Hz), so that it follows what the camera sees.
  static constexpr int kNoiseRefreshFrames = 30;

  /// A segmenter with these parameters; throws std::invalid_argument naming a bad one.
  /// \param params the parameters of the segmentation
  explicit Segmenter(const Params& params = Params());
  ~Segmenter();
  /// Takes over the other's buffers and parameters.
  Segmenter(Segmenter&&) noexcept;
  /// Takes over the other's buffers and parameters.
  /// \return this segmenter
  Segmenter& operator=(Segmenter&&) noexcept;

  /// Validates and sets the parameters; throws std::invalid_argument.
  /// \param params the parameters of the segmentation
  void setParams(const Params& params);
  /// \return the parameters in use
  const Params& params() const { return params_; }

  /// Segments an organized grid. The result stays valid until the next call.
  /// \param grid    the frame's points, the sensor at the origin
  /// \param options what the call does besides the segmentation
  /// \return the labels and planes, valid until the next call
  const Segmentation& segment(const PointGrid& grid, const Options& options);
  /// Segments an organized grid with the default Options.
  /// \param grid the frame's points, the sensor at the origin
  /// \return the labels and planes, valid until the next call
  const Segmentation& segment(const PointGrid& grid) { return segment(grid, Options()); }

 private:
  struct Workspace;
  Params params_;
  std::unique_ptr<Workspace> workspace_;
  Segmentation result_;
};

}  // namespace floodplane
