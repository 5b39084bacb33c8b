// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "floodplane/params.h"
#include "floodplane/point_grid.h"
#include "floodplane/segmenter.h"
#include "models/facet_pairs.h"
#include "models/flood_criterion.h"
#include "models/planarity_test.h"
#include "models/plane_sums.h"
#include "stages/full_resolution_write.h"
#include "stages/occlusion_merging.h"
#include "stages/plane_candidates.h"
#include "stages/prepared_frame.h"
#include "stages/tolerances.h"

namespace floodplane {

/// The segments after merging, on the grid that was segmented.
struct MergedSegments {
  const std::int32_t* labels = nullptr;  ///< per pixel of the segmented grid: segment, 0 none
  const std::int32_t* root = nullptr;    ///< per segment: the segment it merged into
  const PlaneSums* sums = nullptr;       ///< per root segment: the sums of its whole cluster
  std::size_t segment_count = 0;         ///< labels are < segment_count
};

/// From merged segments to the planes a user gets, on the grid that was segmented, then at full
/// resolution.
/// - Each cluster becomes a plane if it is flat enough (maximum curvature) and large enough
///   (min inliers, counted in measured pixels); planes are numbered by size, largest first.
/// - Optionally the refinement (refinement.h) grows the planes into unlabelled points; then
///   occlusion merging (occlusion_merging.h) and the planarity test (planarity_test.h,
///   facet_pairs.h) renumber them, through one pending renumbering of the label image.
/// - At sub-sampling 1 the segmented grid is the frame: its label image is the output, and a
///   plane's sums are those of its measured points. At s > 1 the label image is one of blocks,
///   and FullResolutionWrite brings it to the frame's pixels with the planes' exact sums.
/// Centroid, covariance and coefficients come from running sums of the inliers; there is no
/// second pass over the cloud for them.
class RegionBuilder {
 public:
  /// The planes on the segmented grid (`out.labels` holds their label image at s = 1).
  void assemble(const PreparedFrame& frame, const MergedSegments& merged, const Params& params, bool refine,
                Segmentation& out);
  /// The labels at full resolution and the planes of `out`.
  void write(const PreparedFrame& frame, const Params& params, Segmentation& out);

 private:
  // One candidate per flat cluster; candidate_of_segment_ maps every segment to its cluster's.
  void selectCandidates(const PreparedFrame& frame, const MergedSegments& merged, const Params& params);
  // The candidates' numbers per point of the segmented grid, from the segments' (filled-in
  // points get none).
  void labelSegmentedGrid(const PreparedFrame& frame, const MergedSegments& merged, std::vector<std::uint32_t>& labels);
  // Beyond the paper: the planarity test (planarity_test.h) on the final planes, alone and in
  // touching pairs (facet_pairs.h); drops the curved ones (a cylinder's, a ball's or a
  // person's facets). Returns whether any was dropped (the labels then need renumbering by
  // remap()).
  bool dropCurvedPlanes(const PreparedFrame& frame, const RenumberedLabels& labels);
  // Adds the interior points of the planes to `test`.
  void samplePlanarity(const PreparedFrame& frame, const RenumberedLabels& labels, PlanarityTest& test);
  // The planes' sums anew from the measured points of their pixels (s = 1).
  void sumMeasuredPoints(const PointGrid& measured, const RenumberedLabels& labels);
  // s > 1: the labels at full resolution, the planes' exact sums, sizes and order.
  void writeFullResolution(const PreparedFrame& frame, const Params& params, Segmentation& out);

  Params params_;
  PlaneCandidates candidates_;
  std::vector<std::uint32_t> candidate_of_segment_;  // 0 = none, k = candidates_[k]
  std::vector<std::uint32_t> block_labels_;          // s > 1: the label image of the blocks
  std::vector<PlaneSums> cluster_sums_;              // s > 1: per cluster, of its blocks' means
  std::vector<PlaneSums> cluster_pixel_sums_;        // s > 1: per cluster, of its measured pixels
  std::vector<std::size_t> queue_;                   // the refinement's
  PlanarityTest planarity_;
  std::vector<PlaneFit> fits_;
  std::vector<bool> curved_, judgeable_;
  std::vector<std::uint32_t> strides_;  // each plane's sampling stride in samplePlanarity
  FacetPairs facet_pairs_;
  OcclusionMerging occlusion_merging_;
  std::vector<FloodCriterion> criteria_;  // the planes' tests at full resolution
  std::vector<PlaneSums> inner_sums_;     // per plane: the sums of its inner blocks
  std::vector<Vec3> centroids_;           // per plane: the centroid of its inner blocks
  FullResolutionWrite full_resolution_;
};

}  // namespace floodplane
