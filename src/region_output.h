// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "tolerances.h"
#include "distance_function.h"
#include "facet_pairs.h"
#include "floodplane/params.h"
#include "floodplane/point_grid.h"
#include "floodplane/segmenter.h"
#include "hole_filling.h"
#include "occlusion_merging.h"
#include "plane_candidates.h"
#include "planarity.h"
#include "plane_sums.h"

namespace floodplane {

/// The segments after merging, on the grid that was segmented.
struct MergedSegments {
  const std::int32_t* labels = nullptr;  ///< per pixel of the segmented grid: segment, 0 none
  const std::int32_t* root = nullptr;    ///< per segment: the segment it merged into
  const PlaneSums* sums = nullptr;       ///< per root segment: the sums of its whole cluster
  std::size_t segment_count = 0;         ///< labels are < segment_count
};

/// The last stage: from merged segments to the planes a user gets.
/// - Each cluster becomes a plane if it is flat enough (maximum curvature) and large enough
///   (min inliers, counted at full resolution); planes are numbered by size, largest first.
/// - With sub-sampling s > 1, every full-resolution pixel takes the best-fitting plane among
///   those of the four grid samples around it, if it is within the plane tolerance, so labels
///   are pixel-accurate although only every s-th pixel was segmented.
/// - Optionally the refinement (refinement.h) grows the planes into unlabelled pixels.
/// - Centroid, covariance and coefficients come from running sums of the inliers, updated as
///   pixels are added; there is no second pass over the cloud.
class RegionBuilder {
 public:
  /// `full` is the input grid, `segmented` the grid that was segmented (the same when s = 1),
  /// `angular_pitch` that of `full`.
  /// `measured` is the caller's grid; `full` the same frame as segmented (holes filled in,
  /// smoothed), `segmented` that grid sub-sampled when s > 1.
  void build(const PointGrid& measured, const PointGrid& full, const PointGrid& segmented, const HoleFilling& holes,
             int subsampling, const MergedSegments& merged, const Params& params, const Tolerances& tolerances,
             float angular_pitch, bool refine, Segmentation& out);

 private:
  // One candidate per flat cluster; candidate_of_segment_ maps every segment to its cluster's.
  void selectCandidates(int subsampling, const MergedSegments& merged, const Params& params,
                        const Tolerances& tolerances, float angular_pitch);
  void labelFullResolution(const PointGrid& full, const PointGrid& segmented, int subsampling,
                           const MergedSegments& merged, std::vector<std::uint32_t>& labels);
  // The cells of sample row gy (see Cell) and each pixel column's sample range.
  void prepareCellRow(const PointGrid& segmented, int subsampling, int gy, const MergedSegments& merged);
  // Labels one full-resolution row from the cells of its sample row.
  void labelRowFromCells(const PointGrid& full, std::size_t row_start, int subsampling, std::uint32_t* out_row) const;
  // Labels pixels [u_begin, u_end) of a full-resolution row whose cells all have plane k
  // alone: k where the pixel fits k, else 0.
  void labelRun(const PointGrid& full, std::size_t row_start, int u_begin, int u_end, std::uint32_t k,
                std::uint32_t* out_row) const;
  // Labels pixels [u_begin, u_end) of a cell whose samples have several planes: the
  // best-fitting one within the tolerance, else 0.
  void labelMixedCell(const PointGrid& full, std::size_t row_start, int u_begin, int u_end, std::size_t gx,
                      std::uint32_t* out_row) const;
  // Beyond the paper: the planarity test (planarity.h) on the final planes, alone and in
  // touching pairs (facet_pairs.h); drops the curved ones (a cylinder's, a ball's or a
  // person's facets). Returns whether any was dropped (the labels then need renumbering by
  // remap()).
  bool dropCurvedPlanes(const PointGrid& full, const RenumberedLabels& labels, const Tolerances& tolerances);
  // Adds the interior pixels of the planes to `test`.
  void samplePlanarity(const PointGrid& full, const RenumberedLabels& labels, PlanarityTest& test);
  // The planes' sums anew from the measured points of their pixels.
  void sumMeasuredPoints(const PointGrid& measured, const RenumberedLabels& labels);
  // Adds the labelled pixels of one full-resolution row to their planes' sums and notes
  // each plane's first pixel.
  void addRowToSums(const PointGrid& full, std::size_t row_start, const std::uint32_t* row);

  // A cell of the segmented grid, between samples (gx, gy) and (gx + 1, gy + 1): the planes
  // of its four samples, and whether they are none (0), one (that plane) or several.
  static constexpr std::uint32_t kMixedCell = 0xffffffffu;
  struct Cell {
    std::array<std::uint32_t, 4> around;
    std::uint32_t plane;
    float sample_range_sq;  // of sample (gx, gy)
  };
  std::vector<Cell> cells_;             // one row of cells
  std::vector<float> column_range_sq_;  // per pixel column: its cell's sample_range_sq
  PlaneCandidates candidates_;
  std::vector<std::uint32_t> candidate_of_segment_;  // 0 = none, k = candidates_[k]
  std::vector<std::size_t> queue_;                   // the refinement's
  const HoleFilling* holes_ = nullptr;
  PlanarityTest planarity_;
  std::vector<PlaneFit> fits_;
  std::vector<bool> curved_, judgeable_;
  std::vector<std::uint32_t> strides_;  // each plane's sampling stride in samplePlanarity
  FacetPairs facet_pairs_;
  OcclusionMerging occlusion_merging_;
};

}  // namespace floodplane
