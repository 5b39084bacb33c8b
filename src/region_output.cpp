// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "region_output.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "refinement.h"
#include "row_search.h"
#include "simd.h"

namespace floodplane {

namespace {

// About this many pixels of a plane take part in its planarity test (see samplePlanarity).
constexpr double kPlanaritySamples = 4000.0;

}  // namespace

// ---- RegionBuilder ---------------------------------------------------------------------

void RegionBuilder::build(const PointGrid& measured, const PointGrid& full, const PointGrid& segmented,
                          const HoleFilling& holes, int subsampling, const MergedSegments& merged, const Params& params,
                          const Tolerances& tolerances, float angular_pitch, bool refine, Segmentation& out) {
  holes_ = &holes;
  const std::uint32_t min_inliers = tolerances.minInliers();
  selectCandidates(subsampling, merged, params, tolerances, angular_pitch);
  out.width = full.width;
  out.height = full.height;
  out.labels.resize(full.size());
  // The plane tests of selectCandidates ran on the merged clusters; full-resolution
  // labelling and refinement add pixels, which can tip a plane over the curvature limit or,
  // rarely (an outlier far along a ray), make its fit degenerate. The last sort of the
  // candidates checks them again, so that what is reported passes. (With s = 1 and no
  // refinement the labels add no pixel to the clusters, and there is nothing to check again.)
  // Filled-in holes (HoleFilling) leave the clusters when their pixels are labelled, so their
  // counts are known only afterwards.
  bool renumbered = false;  // labels still to be renumbered by remap()
  if (subsampling == 1 && !holes.filled()) {
    // Counts are known: number the planes by size before writing any label.
    candidates_.sortBySize(min_inliers, nullptr);
    for (std::size_t s = 1; s < merged.segment_count; ++s)
      candidate_of_segment_[s] = candidates_.remap(candidate_of_segment_[s]);
    labelFullResolution(full, segmented, subsampling, merged, out.labels);
  } else {
    labelFullResolution(full, segmented, subsampling, merged, out.labels);
    renumbered = candidates_.sortBySize(min_inliers, refine ? nullptr : &params);
  }
  if (refine) {
    refinePlanes(full, holes, out.labels, candidates_, renumbered, queue_);  // renumbers on its way
    // Refinement may also have changed the order by size.
    renumbered = candidates_.sortBySize(0, &params);
  }
  // Each stage below renumbers the planes and reads the labels by their current numbers:
  // through the pending renumbering, so that the image is rewritten once, at the end.
  candidates_.deferRenumbering(renumbered);
  if (occlusion_merging_.run(full, candidates_.labels(out.labels), candidates_, MergeCriterion(params, tolerances),
                             tolerances, angular_pitch))
    candidates_.composeRenumbering();
  if (dropCurvedPlanes(full, candidates_.labels(out.labels), tolerances)) candidates_.composeRenumbering();
  // A plane's centroid, covariance and fit are those of its inliers as the caller measured
  // them, not as they were smoothed for segmenting.
  if (measured.data != full.data) sumMeasuredPoints(measured, candidates_.labels(out.labels));
  candidates_.applyRenumbering(out.labels);

  out.planes.clear();
  for (const PlaneCandidate& candidate : candidates_.list()) {
    SegmentedPlane plane;
    plane.fit = candidate.sums.fit();
    plane.inlier_count = static_cast<std::uint32_t>(candidate.sums.count);
    plane.first_pixel = candidate.first_pixel;
    out.planes.push_back(plane);
  }
}

void RegionBuilder::selectCandidates(int subsampling, const MergedSegments& merged, const Params& params,
                                     const Tolerances& tolerances, float angular_pitch) {
  std::vector<PlaneCandidate>& list = candidates_.list();
  list.clear();
  candidate_of_segment_.assign(merged.segment_count, 0);
  for (std::size_t s = 1; s < merged.segment_count; ++s) {
    if (merged.root[s] != static_cast<std::int32_t>(s)) continue;
    const PlaneSums& sums = merged.sums[s];
    // With s = 1 the counts are exact and refinement only adds pixels: drop small ones now.
    if (subsampling == 1 && sums.count < tolerances.minInliers()) continue;
    const PlaneFit fit = sums.fit();
    if (!acceptablePlane(fit, params)) continue;
    PlaneCandidate candidate;
    candidate.criterion = planeCriterion(fit, tolerances, angular_pitch);
    if (subsampling == 1) candidate.sums = sums;  // otherwise counted at full resolution
    list.push_back(candidate);
    candidate_of_segment_[s] = static_cast<std::uint32_t>(list.size());
  }
  for (std::size_t s = 1; s < merged.segment_count; ++s)
    candidate_of_segment_[s] = candidate_of_segment_[static_cast<std::size_t>(merged.root[s])];
}

void RegionBuilder::labelFullResolution(const PointGrid& full, const PointGrid& segmented, int subsampling,
                                        const MergedSegments& merged, std::vector<std::uint32_t>& labels) {
  if (subsampling == 1) {
    // Run by run of one segment: its plane is looked up once.
    const std::uint32_t* table = candidate_of_segment_.data();
    const std::size_t width = static_cast<std::size_t>(full.width);
    for (std::size_t row = 0; row < full.size(); row += width) {
      forEachRunInRow(merged.labels + row, 0, full.width - 1, [&](std::int32_t segment, int begin, int end) {
        const std::uint32_t k = table[segment];
        const std::size_t first = row + static_cast<std::size_t>(begin), last = row + static_cast<std::size_t>(end);
        if (k == 0 || !holes_->filled()) {
          std::fill(labels.begin() + static_cast<std::ptrdiff_t>(first),
                    labels.begin() + static_cast<std::ptrdiff_t>(last), k);
          if (k != 0 && candidates_[k].first_pixel == kNoPixel) candidates_[k].first_pixel = first;
          return;
        }
        for (std::size_t i = first; i < last; ++i) {
          // A filled-in hole: it helped the flood across, but it was never measured.
          const bool filled = holes_->isFilled(i);
          if (filled) candidates_[k].sums.remove(Vec3::load(segmented.point(i)));
          labels[i] = filled ? 0u : k;
          if (!filled && candidates_[k].first_pixel == kNoPixel) candidates_[k].first_pixel = i;
        }
      });
    }
    return;
  }
  // Each full-resolution pixel takes the best-fitting plane of the four samples around it:
  // those of the grid cell it lies in (its sample and the next ones right and down). What a
  // cell holds is worked out once for the s image rows that cross it.
  cells_.resize(static_cast<std::size_t>(segmented.width));
  column_range_sq_.resize(static_cast<std::size_t>(segmented.width) * static_cast<std::size_t>(subsampling));
  for (int gy = 0; gy < segmented.height; ++gy) {
    prepareCellRow(segmented, subsampling, gy, merged);
    const int v_end = std::min((gy + 1) * subsampling, full.height);
    for (int v = gy * subsampling; v < v_end; ++v) {
      const std::size_t row_start = static_cast<std::size_t>(v) * static_cast<std::size_t>(full.width);
      labelRowFromCells(full, row_start, subsampling, labels.data() + row_start);
      if (holes_->filled()) {  // filled-in holes are never labelled
        for (std::size_t u = 0; u < static_cast<std::size_t>(full.width); ++u)
          if (holes_->isFilled(row_start + u)) labels[row_start + u] = 0;
      }
      // The sums in a second pass over the row, so that the labelling loops stay short.
      addRowToSums(full, row_start, labels.data() + row_start);
    }
  }
}

void RegionBuilder::prepareCellRow(const PointGrid& segmented, int subsampling, int gy, const MergedSegments& merged) {
  const std::uint32_t* table = candidate_of_segment_.data();
  const std::size_t width = static_cast<std::size_t>(segmented.width);
  const std::size_t sample_row = static_cast<std::size_t>(gy) * width;
  const std::int32_t* row0 = merged.labels + sample_row;
  const std::int32_t* row1 = merged.labels + static_cast<std::size_t>(std::min(gy + 1, segmented.height - 1)) * width;
  for (std::size_t gx = 0; gx < width; ++gx) {
    const std::size_t gx1 = std::min(gx + 1, width - 1);
    Cell& cell = cells_[gx];
    cell.around = {table[row0[gx]], table[row0[gx1]], table[row1[gx]], table[row1[gx1]]};
    const auto& k = cell.around;
    cell.plane = (k[0] | k[1] | k[2] | k[3]) == 0                 ? 0u
                 : (k[0] == k[1] && k[0] == k[2] && k[0] == k[3]) ? k[0]
                                                                  : kMixedCell;
    // The nearer of a pixel and its cell's sample sets the noise tolerance.
    cell.sample_range_sq = Vec3::load(segmented.point(sample_row + gx)).squaredNorm();
    // Per pixel column, the squared range of its cell's sample, for the four-pixel loop.
    std::fill_n(column_range_sq_.begin() + static_cast<std::ptrdiff_t>(gx) * subsampling, subsampling,
                cell.sample_range_sq);
  }
}

void RegionBuilder::labelRowFromCells(const PointGrid& full, std::size_t row_start, int subsampling,
                                      std::uint32_t* out_row) const {
  // Cell by cell; consecutive cells with no plane, or inside one plane, as one run.
  const std::size_t grid_width = cells_.size();
  std::size_t gx = 0;
  while (gx < grid_width) {
    const Cell& cell = cells_[gx];
    std::size_t gx_end = gx + 1;
    if (cell.plane != kMixedCell) {
      while (gx_end < grid_width && cells_[gx_end].plane == cell.plane) ++gx_end;
    }
    const int u_begin = static_cast<int>(gx) * subsampling;
    const int u_end = std::min(static_cast<int>(gx_end) * subsampling, full.width);
    if (cell.plane == 0) {
      std::fill(out_row + u_begin, out_row + u_end, 0u);
    } else if (cell.plane != kMixedCell) {
      labelRun(full, row_start, u_begin, u_end, cell.plane, out_row);
    } else {
      labelMixedCell(full, row_start, u_begin, u_end, gx, out_row);
    }
    gx = gx_end;
  }
}

void RegionBuilder::labelRun(const PointGrid& full, std::size_t row_start, int u_begin, int u_end, std::uint32_t k,
                             std::uint32_t* out_row) const {
  const FloodCriterion& c = candidates_.list()[k - 1].criterion;
  const float* sample_range_sq = column_range_sq_.data();
  int u = u_begin;
#if FLOODPLANE_SIMD
  if (fourPixelsAtATime(full)) {
    for (; u + 4 <= u_end; u += 4) {
      const PointLanes q = PointLanes::load(full, row_start + static_cast<std::size_t>(u));
      const Float4 range_sq = Float4::min(Float4::load(sample_range_sq + u), q.squaredNorm());
      // A NaN range (a hole) gives a NaN tolerance here where the scalar code has sigma_plane,
      // but the hole's own distance is NaN and fails either.
      Float4 distance;
      c.fitsPlane(q, range_sq, distance).storeLabels(out_row + u, k);
    }
  }
#endif
  for (; u < u_end; ++u) {
    const Vec3 q = Vec3::load(full.point(row_start + static_cast<std::size_t>(u)));
    float distance = 0.f;
    out_row[u] = c.fitsPlane(q, nearerRangeSq(sample_range_sq[u], q.squaredNorm()), distance) ? k : 0u;
  }
}

void RegionBuilder::labelMixedCell(const PointGrid& full, std::size_t row_start, int u_begin, int u_end, std::size_t gx,
                                   std::uint32_t* out_row) const {
  const Cell& cell = cells_[gx];
  for (int u = u_begin; u < u_end; ++u) {
    const Vec3 q = Vec3::load(full.point(row_start + static_cast<std::size_t>(u)));
    const float range_sq = nearerRangeSq(cell.sample_range_sq, q.squaredNorm());
    float best_distance = std::numeric_limits<float>::infinity();
    std::uint32_t best = 0;
    for (const std::uint32_t k : cell.around) {
      if (k == 0 || k == best) continue;
      float distance = 0.f;  // along q's ray: the plane that explains q with the smaller depth error
      if (candidates_.list()[k - 1].criterion.fitsPlane(q, range_sq, distance) && distance < best_distance) {
        best_distance = distance;
        best = k;
      }
    }
    out_row[u] = best;
  }
}

void RegionBuilder::sumMeasuredPoints(const PointGrid& measured, const RenumberedLabels& labels) {
  for (PlaneCandidate& candidate : candidates_.list()) candidate.sums = PlaneSums();
  const std::size_t width = static_cast<std::size_t>(measured.width);
  const std::size_t size = width * static_cast<std::size_t>(measured.height);
  for (std::size_t row = 0; row < size; row += width) {
    const std::uint32_t* image_row = labels.image + row;
    int u = 0;
    while (u < measured.width) {
      // A run of one plane: runs of image numbers that now carry the same number join.
      const std::uint32_t k = labels.number[image_row[u]];
      int end = findInRow(image_row, u, measured.width - 1, image_row[u], false);
      while (end < measured.width && labels.number[image_row[end]] == k)
        end = findInRow(image_row, end, measured.width - 1, image_row[end], false);
      if (k != 0)
        addRunToSums(candidates_[k].sums, measured, row + static_cast<std::size_t>(u),
                     static_cast<std::size_t>(end - u));
      u = end;
    }
  }
}

void RegionBuilder::samplePlanarity(const PointGrid& full, const RenumberedLabels& labels, PlanarityTest& test) {
  // Interior pixels only (no neighbour in another plane or none): the pixels along a plane's
  // border may be a neighbouring surface's within the tolerance band, and would fake a bend.
  // A neighbour without a return does not make a border: on a speckled surface there would be
  // no inside.
  //
  // A large plane is sampled on a lattice (every s-th pixel of every s-th row) of about
  // kPlanaritySamples pixels: its test is then still sensitive to a bend a tenth of the noise
  // deep (see PlanarityTest), and the walls and floor, most of a frame, cost little.
  const std::vector<PlaneCandidate>& list = candidates_.list();
  strides_.assign(list.size() + 1, 1);
  for (std::size_t k = 1; k <= list.size(); ++k) {
    const double s = std::floor(std::sqrt(list[k - 1].sums.count / kPlanaritySamples));
    strides_[k] = static_cast<std::uint32_t>(std::max(1.0, s));
  }
  const std::size_t width = static_cast<std::size_t>(full.width);
  const auto inside = [&](std::size_t j, std::uint32_t k) {
    return labels[j] == k || !full.isFinite(j) || holes_->isFilled(j);
  };
  // Run by run along each row (labels come in long runs): a run's plane and lattice are looked
  // up once. Points are added in raster order, as pixel by pixel.
  for (std::size_t y = 1; y + 1 < static_cast<std::size_t>(full.height); ++y) {
    const std::size_t row = y * width;
    forEachRunInRow(labels.image + row, 1, full.width - 2, [&](std::uint32_t image_label, int begin, int end) {
      const std::uint32_t k = labels.number[image_label];
      if (k == 0 || y % strides_[k] != 0) return;
      const std::uint32_t s = strides_[k];
      // The first column of the run on the plane's lattice.
      const std::uint32_t first = (static_cast<std::uint32_t>(begin) + s - 1) / s * s;
      for (std::size_t u = first; u < static_cast<std::size_t>(end); u += s) {
        const std::size_t i = row + u;
        if (inside(i - 1, k) && inside(i + 1, k) && inside(i - width, k) && inside(i + width, k))
          test.add(k, Vec3::load(full.point(i)));
      }
    });
  }
}

bool RegionBuilder::dropCurvedPlanes(const PointGrid& full, const RenumberedLabels& labels,
                                     const Tolerances& tolerances) {
  const std::vector<PlaneCandidate>& list = candidates_.list();
  if (list.empty()) return false;
  fits_.clear();
  for (const PlaneCandidate& candidate : list) fits_.push_back(candidate.sums.fit());
  planarity_.reset(fits_);
  samplePlanarity(full, labels, planarity_);
  curved_.assign(list.size() + 1, false);
  for (std::uint32_t k = 1; k <= list.size(); ++k) curved_[k] = planarity_.curved(k, tolerances);
  // Touching planes judged as one surface: the facets of a curved one are curved together.
  // (A pair of planes both dropped already has nothing to add.)
  judgeable_.assign(list.size() + 1, false);
  for (std::uint32_t k = 1; k <= list.size(); ++k) judgeable_[k] = planarity_.judgeable(k);
  facet_pairs_.find(full, labels, list, fits_, judgeable_);
  for (const auto& [k, l] : facet_pairs_.pairs()) {
    if (curved_[k] && curved_[l]) continue;
    PlaneSums joint = list[k - 1].sums;
    joint.merge(list[l - 1].sums);
    if (planarity_.curvedPair(k, l, joint.fit(), tolerances)) curved_[k] = curved_[l] = true;
  }
  return candidates_.drop(curved_);
}

void RegionBuilder::addRowToSums(const PointGrid& full, std::size_t row_start, const std::uint32_t* row) {
  // Most of a row is long runs of one label; each run is summed in one tight loop.
  forEachRunInRow(row, 0, full.width - 1, [&](std::uint32_t k, int begin, int end) {
    if (k == 0) return;
    PlaneCandidate& candidate = candidates_[k];
    // Rows come in raster order: a plane's first run starts at its first pixel.
    if (candidate.first_pixel == kNoPixel) candidate.first_pixel = row_start + static_cast<std::size_t>(begin);
    addRunToSums(candidate.sums, full, row_start + static_cast<std::size_t>(begin),
                 static_cast<std::size_t>(end - begin));
  });
}

}  // namespace floodplane
