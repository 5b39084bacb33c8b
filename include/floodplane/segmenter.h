// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "floodplane/params.h"
#include "floodplane/point_grid.h"
#include "floodplane/segmentation.h"

/// \file
/// floodplane::Segmenter, the PCL-free core (its result, floodplane::Segmentation, is in
/// floodplane/segmentation.h).

namespace floodplane {

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
