// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "regions/region_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "models/lane_sums.h"
#include "regions/refinement.h"
#include "util/row_search.h"
#include "util/simd.h"

namespace floodplane {

namespace {

// About this many pixels of a plane take part in its planarity test (see samplePlanarity).
constexpr double kPlanaritySamples = 4000.0;

}  // namespace

// ---- RegionBuilder ---------------------------------------------------------------------

void RegionBuilder::assemble(const PreparedFrame& frame, const MergedSegments& merged, const Params& params,
                             bool refine) {
  params_ = params;
  const std::uint32_t min_inliers = frame.tolerances.minInliers();
  selectCandidates(frame, merged, params);
  // The plane tests of selectCandidates ran on the merged clusters; refinement adds points,
  // which can tip a plane over the curvature limit or, rarely (an outlier far along a ray),
  // make its fit degenerate. The last sort of the candidates checks them again, so that what
  // is reported passes. Filled-in holes (HoleFilling) leave the clusters when their points are
  // labelled, so the counts are known only afterwards.
  if (!frame.holes->filled()) {
    // Counts are known: number the planes by size before writing any label.
    candidates_.sortBySize(min_inliers, nullptr);
    for (std::size_t segment = 1; segment < merged.segment_count; ++segment)
      candidate_of_segment_[segment] = candidates_.remap(candidate_of_segment_[segment]);
    labelSegmentedGrid(frame, merged);
  } else {
    labelSegmentedGrid(frame, merged);
    candidates_.sortBySize(min_inliers, refine ? nullptr : &params);
  }
  if (refine) {
    refinePlanes(frame.grid, *frame.holes, candidates_, queue_);
    // Refinement may also have changed the order by size.
    candidates_.sortBySize(0, &params);
  }
  occlusion_merging_.run(frame.grid, candidates_, MergeCriterion(params, frame.tolerances), frame.tolerances,
                         frame.pitch);
  dropCurvedPlanes(frame);
}

void RegionBuilder::write(const PreparedFrame& frame, Segmentation& out) {
  out.width = frame.measured.width;
  out.height = frame.measured.height;
  // A plane's centroid, covariance and fit are those of its inliers as the caller measured
  // them, not as they were smoothed for segmenting, nor the block means that stood for the
  // pixels of a coarse plane (s > 1).
  if (frame.measured.data != frame.grid.data || frame.blocks) sumMeasuredPoints(frame.measured);
  candidates_.releaseImage(out.labels);
  out.planes.clear();
  for (const PlaneCandidate& candidate : candidates_.list()) {
    SegmentedPlane plane;
    plane.fit = candidate.sums.fit();
    plane.inlier_count = static_cast<std::uint32_t>(candidate.sums.count);
    plane.first_pixel = candidate.first_pixel;
    out.planes.push_back(plane);
  }
}

void RegionBuilder::selectCandidates(const PreparedFrame& frame, const MergedSegments& merged, const Params& params) {
  candidates_.clear();
  std::vector<PlaneCandidate>& list = candidates_.list();
  candidate_of_segment_.assign(merged.segment_count, 0);
  // Refinement only adds pixels: drop small ones now. (A filled-in hole counts here, and
  // leaves the count when the labels are written.)
  const double smallest = frame.tolerances.minInliers();
  for (std::size_t segment = 1; segment < merged.segment_count; ++segment) {
    if (merged.root[segment] != static_cast<std::int32_t>(segment)) continue;
    const PlaneSums& sums = merged.sums[segment];
    if (sums.count < smallest) continue;
    const PlaneFit fit = sums.fit();
    if (!acceptablePlane(fit, params)) continue;
    PlaneCandidate candidate;
    candidate.criterion = planeCriterion(fit, frame.tolerances, frame.pitch);
    candidate.sums = sums;
    list.push_back(candidate);
    candidate_of_segment_[segment] = static_cast<std::uint32_t>(list.size());
  }
  for (std::size_t segment = 1; segment < merged.segment_count; ++segment)
    candidate_of_segment_[segment] = candidate_of_segment_[static_cast<std::size_t>(merged.root[segment])];
}

void RegionBuilder::labelSegmentedGrid(const PreparedFrame& frame, const MergedSegments& merged) {
  std::uint32_t* labels = candidates_.newImage(frame.grid.width, frame.grid.height);
  // Run by run of one segment: its plane is looked up once.
  const std::uint32_t* table = candidate_of_segment_.data();
  const HoleFilling& holes = *frame.holes;
  const std::size_t width = static_cast<std::size_t>(frame.grid.width);
  for (std::size_t row = 0; row < frame.grid.size(); row += width) {
    forEachRunInRow(merged.labels + row, 0, frame.grid.width - 1, [&](std::int32_t segment, int begin, int end) {
      const std::uint32_t k = table[segment];
      const std::size_t first = row + static_cast<std::size_t>(begin), last = row + static_cast<std::size_t>(end);
      if (k == 0 || !holes.filled()) {
        std::fill(labels + first, labels + last, k);
        if (k != 0 && candidates_[k].first_pixel == kNoPixel) candidates_[k].first_pixel = first;
        return;
      }
      PlaneCandidate& candidate = candidates_[k];
      for (std::size_t i = first; i < last; ++i) {
        // A filled-in hole: it helped the flood across, but it was never measured (a filled
        // block has no measured pixel, and added nothing to the sums).
        const bool filled = holes.isFilled(i);
        labels[i] = filled ? 0u : k;
        if (filled) candidate.sums.remove(Vec3::load(frame.grid.point(i)));
        if (!filled && candidate.first_pixel == kNoPixel) candidate.first_pixel = i;
      }
    });
  }
}

void RegionBuilder::sumMeasuredPoints(const PointGrid& measured) {
  for (PlaneCandidate& candidate : candidates_.list()) candidate.sums = PlaneSums();
  const CurrentLabels labels = candidates_.labels();
  const std::size_t width = static_cast<std::size_t>(measured.width);
  const std::size_t size = width * static_cast<std::size_t>(measured.height);
  // Run by run of one plane (pieces merged since the image was written are one run): the
  // sums are added in the same order whatever numbers the image carries.
  for (std::size_t row = 0; row < size; row += width) {
    labels.forEachPlaneRunInRow(row, measured.width, [&](std::uint32_t k, int begin, int end) {
      if (k != 0)
        addRunToSums(candidates_[k].sums, measured, row + static_cast<std::size_t>(begin),
                     static_cast<std::size_t>(end - begin));
    });
  }
}

void RegionBuilder::samplePlanarity(const PreparedFrame& frame, const CurrentLabels& labels, PlanarityTest& test) {
  // Interior points only (no neighbour in another plane or none): the points along a plane's
  // border may be a neighbouring surface's within the tolerance band, and would fake a bend.
  // A neighbour without a return does not make a border: on a speckled surface there would be
  // no inside.
  //
  // A large plane is sampled on a lattice (every c-th point of every r-th row, c >= r >= 1,
  // c r as near its pixels / kPlanaritySamples as whole numbers get) of kPlanaritySamples to
  // twice that many measured pixels: its test is then still sensitive to a bend a tenth of the
  // noise deep (see PlanarityTest), and the walls and floor, most of a frame, cost little. (A
  // square lattice, c = r, would sample a plane of just under 4 kPlanaritySamples pixels whole.)
  const PointGrid& grid = frame.grid;
  const std::vector<PlaneCandidate>& list = candidates_.list();
  strides_.assign(list.size() + 1, 1);
  column_strides_.assign(list.size() + 1, 1);
  for (std::size_t k = 1; k <= list.size(); ++k) {
    const double ratio = list[k - 1].sums.count / kPlanaritySamples;
    const double rows = std::max(1.0, std::floor(std::sqrt(ratio)));
    strides_[k] = static_cast<std::uint32_t>(rows);
    column_strides_[k] = static_cast<std::uint32_t>(std::max(1.0, std::floor(ratio / rows)));
  }
  const std::size_t width = static_cast<std::size_t>(grid.width);
  const HoleFilling& holes = *frame.holes;
  const auto inside = [&](std::size_t j, std::uint32_t k) {
    return labels[j] == k || !grid.isFinite(j) || holes.isFilled(j);
  };
  // Run by run along each row (labels come in long runs): a run's plane and lattice are looked
  // up once. Points are added in raster order of the grid.
  for (std::size_t y = 1; y + 1 < static_cast<std::size_t>(grid.height); ++y) {
    const std::size_t row = y * width;
    labels.forEachRunInRow(row, 1, grid.width - 2, [&](std::uint32_t k, int begin, int end) {
      if (k == 0 || y % strides_[k] != 0) return;
      const std::uint32_t s = column_strides_[k];
      // The first column of the run on the plane's lattice.
      const std::uint32_t first = (static_cast<std::uint32_t>(begin) + s - 1) / s * s;
      for (std::size_t u = first; u < static_cast<std::size_t>(end); u += s) {
        const std::size_t i = row + u;
        // Within the run the left and right neighbours are on k: only its ends look.
        const bool across = (u > static_cast<std::size_t>(begin) || inside(i - 1, k)) &&
                            (u + 1 < static_cast<std::size_t>(end) || inside(i + 1, k));
        if (across && inside(i - width, k) && inside(i + width, k)) test.add(k, Vec3::load(grid.point(i)));
      }
    });
  }
}

void RegionBuilder::dropCurvedPlanes(const PreparedFrame& frame) {
  const Tolerances& tolerances = frame.tolerances;
  const std::vector<PlaneCandidate>& list = candidates_.list();
  if (list.empty()) return;
  const CurrentLabels labels = candidates_.labels();
  fits_.clear();
  for (const PlaneCandidate& candidate : list) fits_.push_back(candidate.sums.fit());
  planarity_.reset(fits_);
  samplePlanarity(frame, labels, planarity_);
  curved_.assign(list.size() + 1, false);
  for (std::uint32_t k = 1; k <= list.size(); ++k) curved_[k] = planarity_.curved(k, tolerances);
  // Touching planes judged as one surface: the facets of a curved one are curved together.
  // (A pair of planes both dropped already has nothing to add.)
  judgeable_.assign(list.size() + 1, false);
  for (std::uint32_t k = 1; k <= list.size(); ++k) judgeable_[k] = planarity_.judgeable(k);
  facet_pairs_.find(frame.grid, labels, list, fits_, judgeable_);
  // (Whether each pair's union bends is kept for bend merging below.)
  union_bends_.assign(facet_pairs_.pairs().size(), false);
  for (std::size_t pair = 0; pair < facet_pairs_.pairs().size(); ++pair) {
    const std::uint32_t k = facet_pairs_.pairs()[pair].first, l = facet_pairs_.pairs()[pair].second;
    if (curved_[k] && curved_[l]) continue;
    PlaneSums joint = list[k - 1].sums;
    joint.merge(list[l - 1].sums);
    bool bends = false;
    if (planarity_.curvedPair(k, l, joint.fit(), tolerances, &bends)) curved_[k] = curved_[l] = true;
    union_bends_[pair] = bends;
  }
  // Touching flat planes that meet without a crease or a step: one plane the sensor bent.
  const std::uint32_t count = static_cast<std::uint32_t>(list.size());
  if (bend_merging_.judge(frame.grid, labels, facet_pairs_, union_bends_, list, curved_, planarity_,
                          MergeCriterion(params_, tolerances), group_)) {
    candidates_.regroup(group_);
    // A merged plane passed the planarity test as a union; a plane that merged with none
    // keeps its verdict.
    members_.assign(candidates_.list().size() + 1, 0);
    for (std::uint32_t k = 1; k <= count; ++k) ++members_[candidates_.remap(k)];
    std::vector<bool> curved(candidates_.list().size() + 1, false);
    for (std::uint32_t k = 1; k <= count; ++k)
      if (members_[candidates_.remap(k)] == 1) curved[candidates_.remap(k)] = curved_[k];
    curved_.swap(curved);
  }
  candidates_.drop(curved_);
}

}  // namespace floodplane
