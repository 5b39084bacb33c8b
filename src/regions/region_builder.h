// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "flood/flood_pass.h"
#include "floodplane/params.h"
#include "floodplane/point_grid.h"
#include "floodplane/segmentation.h"
#include "frame/prepared_frame.h"
#include "models/facet_pairs.h"
#include "models/flood_criterion.h"
#include "models/planarity_test.h"
#include "models/plane_candidates.h"
#include "models/plane_sums.h"
#include "models/tolerances.h"
#include "regions/bend_merging.h"
#include "regions/occlusion_merging.h"

namespace floodplane {

/// From the fine pass's merged segments to the planes a user gets.
/// - Each cluster becomes a plane if it is flat enough (maximum curvature) and large enough
///   (min inliers, counted in measured pixels); planes are numbered by size, largest first.
/// - Optionally the refinement (refinement.h) grows the planes into unlabelled points; then
///   occlusion merging (occlusion_merging.h) and the planarity test (planarity_test.h,
///   facet_pairs.h) renumber them. The label image is the candidates' (PlaneCandidates), which
///   keep it in step with every renumbering.
/// - The segmented grid is the frame at full resolution: its label image is the output, and a
///   plane's sums are those of its measured points.
/// Centroid, covariance and coefficients come from running sums of the inliers; there is no
/// second pass over the cloud for them.
class RegionBuilder {
 public:
  /// The planes on the segmented grid, and their label image.
  void assemble(const PreparedFrame& frame, const MergedSegments& merged, const Params& params, bool refine);
  /// The labels and the planes of `out`, from the last assemble.
  void write(const PreparedFrame& frame, Segmentation& out);

 private:
  // One candidate per flat cluster; candidate_of_segment_ maps every segment to its cluster's.
  void selectCandidates(const PreparedFrame& frame, const MergedSegments& merged, const Params& params);
  // The candidates' image: their numbers per point of the segmented grid, from the segments'
  // (filled-in points get none).
  void labelSegmentedGrid(const PreparedFrame& frame, const MergedSegments& merged);
  // Beyond the paper: the planarity test (planarity_test.h) on the final planes, alone and in
  // touching pairs (facet_pairs.h); drops the curved ones (a cylinder's, a ball's or a
  // person's facets).
  void dropCurvedPlanes(const PreparedFrame& frame);
  // Adds the interior points of the planes to `test`.
  void samplePlanarity(const PreparedFrame& frame, const CurrentLabels& labels, PlanarityTest& test);
  // The planes' sums anew from the measured points of their pixels.
  void sumMeasuredPoints(const PointGrid& measured);

  Params params_;
  PlaneCandidates candidates_;                       // and their label image, until write() hands it over
  std::vector<std::uint32_t> candidate_of_segment_;  // 0 = none, k = candidates_[k]
  std::vector<std::size_t> queue_;                   // the refinement's
  PlanarityTest planarity_;
  std::vector<PlaneFit> fits_;
  std::vector<bool> curved_, judgeable_;
  std::vector<bool> union_bends_;              // per facet pair: its union bends (PlanarityTest::curvedPair)
  std::vector<std::uint32_t> strides_;         // per plane, samplePlanarity's rows: every strides_[k]-th
  std::vector<std::uint32_t> column_strides_;  // ... and in them every column_strides_[k]-th point
  FacetPairs facet_pairs_;
  OcclusionMerging occlusion_merging_;
  BendMerging bend_merging_;
  std::vector<std::uint32_t> group_;    // bend_merging_'s
  std::vector<std::uint32_t> members_;  // per plane after bend merging: the planes it joined
};

}  // namespace floodplane
