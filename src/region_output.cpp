#include "region_output.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "point_lanes.h"
#include "row_search.h"

namespace floodplane {

namespace {

constexpr std::size_t kNoPixel = std::numeric_limits<std::size_t>::max();

// A plane's thresholds for pixels that join it after merging. The Euclidean tolerance
// follows from the plane itself: neighbouring pixels on n.P + d = 0 are alpha r^2 / |d| apart
// (see FloodCriterion); |d| is bounded below where the plane is seen almost edge-on.
FloodCriterion planeCriterion(const PlaneFit& fit, const Params& params, float angular_pitch) {
  FloodCriterion c;
  c.normal = {static_cast<float>(fit.normal.x()), static_cast<float>(fit.normal.y()),
              static_cast<float>(fit.normal.z())};
  c.offset = static_cast<float>(fit.offset);
  c.plane_threshold = static_cast<float>(params.distance_threshold);
  c.plane_noise_factor = static_cast<float>(3.0 * params.depth_noise_coefficient);
  const double distance = std::max(std::abs(fit.offset), 0.1 * fit.centroid.norm());
  const double spacing_per_range_sq = angular_pitch / std::max(distance, 1e-6);
  // Same slack as the flood: twice the spacing, plus the noise of two points.
  const double k = 2.0 * spacing_per_range_sq + 3.0 * std::sqrt(2.0) * params.depth_noise_coefficient;
  c.euclidean_factor_sq = static_cast<float>(k * k);
  return c;
}

// What a reported plane must be: a valid fit, no more curved than allowed, facing the sensor.
bool acceptablePlane(const PlaneFit& fit, const Params& params) {
  return fit.valid && fit.curvature <= params.maximum_curvature && facesSensor(fit.normal, fit.centroid);
}

}  // namespace

void RegionBuilder::build(const PointGrid& full, const PointGrid& segmented, int subsampling,
                          const MergedSegments& merged, const Params& params, float angular_pitch, bool refine,
                          Segmentation& out) {
  // One candidate plane per flat cluster.
  candidates_.clear();
  candidate_of_segment_.assign(merged.segment_count, 0);
  for (std::size_t s = 1; s < merged.segment_count; ++s) {
    if (merged.root[s] != static_cast<std::int32_t>(s)) continue;
    const PlaneSums& sums = merged.sums[s];
    // With s = 1 the counts are exact and refinement only adds pixels: drop small ones now.
    if (subsampling == 1 && sums.count < params.min_inliers) continue;
    const PlaneFit fit = sums.fit();
    if (!acceptablePlane(fit, params)) continue;
    Candidate candidate;
    candidate.criterion = planeCriterion(fit, params, angular_pitch);
    if (subsampling == 1) candidate.sums = sums;
    candidate.first_pixel = kNoPixel;
    candidates_.push_back(candidate);
    candidate_of_segment_[s] = static_cast<std::uint32_t>(candidates_.size());
  }
  for (std::size_t s = 1; s < merged.segment_count; ++s)
    candidate_of_segment_[s] = candidate_of_segment_[merged.root[s]];

  out.width = full.width;
  out.height = full.height;
  out.labels.resize(full.size());
  // The plane tests above ran on the merged clusters; full-resolution labelling and
  // refinement add pixels, which can tip a plane over the curvature limit or, rarely (an
  // outlier far along a ray), make its fit degenerate. The last sort of the candidates
  // checks them again, so that what is reported passes. (With s = 1 and no refinement the
  // labels add no pixel to the clusters, and there is nothing to check again.)
  bool renumbered = false;  // labels still to be renumbered by remap_
  if (subsampling == 1) {
    // Counts are known: number the planes by size before writing any label.
    sortBySize(params.min_inliers, nullptr);
    for (std::size_t s = 1; s < merged.segment_count; ++s) candidate_of_segment_[s] = remap_[candidate_of_segment_[s]];
    labelFullResolution(full, segmented, subsampling, merged, out.labels);
  } else {
    labelFullResolution(full, segmented, subsampling, merged, out.labels);
    renumbered = sortBySize(params.min_inliers, refine ? nullptr : &params);
  }
  if (refine) {
    this->refine(full, out.labels, renumbered);  // renumbers on its way
    // Refinement may also have changed the order by size.
    if (sortBySize(0, &params)) renumber(out.labels);
  } else if (renumbered) {
    renumber(out.labels);
  }

  out.planes.clear();
  for (const Candidate& candidate : candidates_) {
    SegmentedPlane plane;
    plane.fit = candidate.sums.fit();
    plane.inlier_count = static_cast<std::uint32_t>(candidate.sums.count);
    plane.first_pixel = candidate.first_pixel;
    out.planes.push_back(plane);
  }
}

void RegionBuilder::labelFullResolution(const PointGrid& full, const PointGrid& segmented, int subsampling,
                                        const MergedSegments& merged, std::vector<std::uint32_t>& labels) {
  const std::uint32_t* table = candidate_of_segment_.data();
  const std::int32_t* segment = merged.labels;
  if (subsampling == 1) {
    const std::size_t n = full.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t k = table[segment[i]];
      labels[i] = k;
      if (k != 0 && candidates_[k - 1].first_pixel == kNoPixel) candidates_[k - 1].first_pixel = i;
    }
    return;
  }

  // Each full-resolution pixel takes the best-fitting plane of the four samples around it:
  // those of the grid cell it lies in (its sample and the next ones right and down). What a
  // cell holds is worked out once for the s image rows that cross it; a cell whose samples
  // have one plane (most cells) tests its pixels against that plane alone.
  const int grid_width = segmented.width;
  const int grid_height = segmented.height;
  // Every plane has the same tolerance at a given range.
  const FloodCriterion* criteria = candidates_.empty() ? nullptr : &candidates_[0].criterion;
  cells_.resize(static_cast<std::size_t>(grid_width));
  column_range_sq_.resize(static_cast<std::size_t>(grid_width) * subsampling);
  for (int gy = 0; gy < grid_height; ++gy) {
    const std::size_t sample_row = static_cast<std::size_t>(gy) * grid_width;
    const std::int32_t* row0 = segment + sample_row;
    const std::int32_t* row1 = segment + static_cast<std::size_t>(std::min(gy + 1, grid_height - 1)) * grid_width;
    for (int gx = 0; gx < grid_width; ++gx) {
      const int gx1 = std::min(gx + 1, grid_width - 1);
      Cell& cell = cells_[static_cast<std::size_t>(gx)];
      cell.around = {table[row0[gx]], table[row0[gx1]], table[row1[gx]], table[row1[gx1]]};
      const auto& k = cell.around;
      cell.plane = (k[0] | k[1] | k[2] | k[3]) == 0                    ? 0u
                   : (k[0] == k[1] && k[0] == k[2] && k[0] == k[3]) ? k[0]
                                                                       : kMixedCell;
      // The nearer of a pixel and its cell's sample sets the noise tolerance.
      cell.sample_range_sq = Vec3::load(segmented.point(sample_row + static_cast<std::size_t>(gx))).squaredNorm();
    }
    // Per pixel column, the squared range of its cell's sample, for the four-pixel loop.
    for (int gx = 0; gx < grid_width; ++gx)
      std::fill_n(column_range_sq_.begin() + static_cast<std::ptrdiff_t>(gx) * subsampling, subsampling,
                  cells_[static_cast<std::size_t>(gx)].sample_range_sq);

    const int v_end = std::min((gy + 1) * subsampling, full.height);
    for (int v = gy * subsampling; v < v_end; ++v) {
      const std::size_t row_start = static_cast<std::size_t>(v) * full.width;
      std::uint32_t* out_row = labels.data() + row_start;
      // Cell by cell; consecutive cells with no plane, or inside one plane, as one run.
      int gx = 0;
      while (gx < grid_width) {
        const Cell& cell = cells_[static_cast<std::size_t>(gx)];
        int gx_end = gx + 1;
        if (cell.plane != kMixedCell) {
          while (gx_end < grid_width && cells_[static_cast<std::size_t>(gx_end)].plane == cell.plane) ++gx_end;
        }
        const int u_begin = gx * subsampling;
        const int u_end = std::min(gx_end * subsampling, full.width);
        if (cell.plane == 0) {
          std::fill(out_row + u_begin, out_row + u_end, 0u);
        } else if (cell.plane != kMixedCell) {
          labelRun(full, row_start, u_begin, u_end, cell.plane, out_row);
        } else {
          for (int u = u_begin; u < u_end; ++u) {
            const Vec3 q = Vec3::load(full.point(row_start + static_cast<std::size_t>(u)));
            float best_distance = criteria->planeTolerance(nearerRangeSq(cell.sample_range_sq, q.squaredNorm()));
            std::uint32_t best = 0;
            for (const std::uint32_t k : cell.around) {
              if (k == 0 || k == best) continue;
              const FloodCriterion& c = candidates_[k - 1].criterion;
              const float distance = planeDistance(c.normal, c.offset, q);
              if (distance < best_distance) {
                best_distance = distance;
                best = k;
              }
            }
            out_row[u] = best;
          }
        }
        gx = gx_end;
      }
      // The sums in a second pass over the row, so that the labelling loops above stay short.
      addRowToSums(full, row_start, out_row);
    }
  }
}

void RegionBuilder::labelRun(const PointGrid& full, std::size_t row_start, int u_begin, int u_end, std::uint32_t k,
                             std::uint32_t* out_row) const {
  const FloodCriterion& c = candidates_[k - 1].criterion;
  const float* sample_range_sq = column_range_sq_.data();
  int u = u_begin;
#if FLOODPLANE_POINT_LANES
  if (fourPixelsAtATime(full)) {
    const __m128i plane = _mm_set1_epi32(static_cast<std::int32_t>(k));
    for (; u + 4 <= u_end; u += 4) {
      const PointLanes q = PointLanes::load(full, row_start + static_cast<std::size_t>(u));
      const __m128 range_sq = nearerRangeSq(_mm_loadu_ps(sample_range_sq + u), q.squaredNorm());
      // A NaN range (a hole) gives a NaN tolerance here where the scalar code has sigma_plane,
      // but the hole's own distance is NaN and fails either.
      const __m128 fits = _mm_cmplt_ps(q.planeDistance(c.normal, c.offset), planeTolerance(c, range_sq));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out_row + u), _mm_and_si128(_mm_castps_si128(fits), plane));
    }
  }
#endif
  for (; u < u_end; ++u) {
    const Vec3 q = Vec3::load(full.point(row_start + static_cast<std::size_t>(u)));
    const float tolerance = c.planeTolerance(nearerRangeSq(sample_range_sq[u], q.squaredNorm()));
    out_row[u] = planeDistance(c.normal, c.offset, q) < tolerance ? k : 0u;
  }
}

void RegionBuilder::addRowToSums(const PointGrid& full, std::size_t row_start, const std::uint32_t* row) {
  // Most of a row is long runs of one label; each run is summed in one tight loop.
  const int width = full.width;
  int u = 0;
  while (u < width) {
    const std::uint32_t k = row[u];
    const int end = findInRow(row, u, width - 1, k, false);
    if (k != 0) {
      Candidate& candidate = candidates_[k - 1];
      // Rows come in raster order: a plane's first run starts at its first pixel.
      if (candidate.first_pixel == kNoPixel) candidate.first_pixel = row_start + static_cast<std::size_t>(u);
      addRunToSums(candidate.sums, full, row_start + static_cast<std::size_t>(u), static_cast<std::size_t>(end - u));
    }
    u = end;
  }
}

bool RegionBuilder::sortBySize(std::uint32_t min_inliers, const Params* recheck) {
  order_.resize(candidates_.size());
  std::iota(order_.begin(), order_.end(), 0);
  std::stable_sort(order_.begin(), order_.end(),
                   [&](std::size_t a, std::size_t b) { return candidates_[a].sums.count > candidates_[b].sums.count; });
  remap_.assign(candidates_.size() + 1, 0);
  kept_.clear();
  bool changed = false;
  for (std::size_t rank = 0; rank < order_.size(); ++rank) {
    const Candidate& candidate = candidates_[order_[rank]];
    if (candidate.sums.count < min_inliers || (recheck && !acceptablePlane(candidate.sums.fit(), *recheck))) {
      changed = true;
      continue;
    }
    kept_.push_back(candidate);
    remap_[order_[rank] + 1] = static_cast<std::uint32_t>(kept_.size());
    changed = changed || order_[rank] != rank;
  }
  candidates_.swap(kept_);
  return changed;
}

void RegionBuilder::renumber(std::vector<std::uint32_t>& labels) {
  for (Candidate& candidate : candidates_) candidate.first_pixel = kNoPixel;
  renumberPixels(labels, 0, labels.size());
}

void RegionBuilder::renumberPixels(std::vector<std::uint32_t>& labels, std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) {
    const std::uint32_t k = remap_[labels[i]];
    labels[i] = k;
    if (k != 0 && candidates_[k - 1].first_pixel == kNoPixel) candidates_[k - 1].first_pixel = i;
  }
}

void RegionBuilder::refine(const PointGrid& full, std::vector<std::uint32_t>& labels, bool renumber_first) {
  if (candidates_.empty()) {
    if (renumber_first) renumber(labels);
    return;
  }
  const int width = full.width;
  const int height = full.height;
  // renumber() one row ahead of the scan below (which reads the rows above and below the
  // pixel it looks at): one pass over the label image instead of two.
  const auto renumberRow = [&](int y) {
    const std::size_t row_start = static_cast<std::size_t>(y) * width;
    renumberPixels(labels, row_start, row_start + static_cast<std::size_t>(width));
  };
  if (renumber_first) {
    for (Candidate& candidate : candidates_) candidate.first_pixel = kNoPixel;
    renumberRow(0);
  }
  // Does pixel `to`, next to `from`, join plane k (Eqs. 1-3 with the plane's thresholds)?
  const auto fits = [&](std::uint32_t k, std::size_t from, std::size_t to, float& distance) {
    const FloodCriterion& c = candidates_[k - 1].criterion;
    const Vec3 p = Vec3::load(full.point(from));
    const Vec3 q = Vec3::load(full.point(to));
    const float range_sq = noiseRangeSq(p, q);
    if (!(squaredEuclideanDistance(p, q) < c.euclideanToleranceSq(range_sq))) return false;
    distance = planeDistance(c.normal, c.offset, q);
    return distance < c.planeTolerance(range_sq);
  };
  const auto take = [&](std::uint32_t k, std::size_t pixel) {
    labels[pixel] = k;
    Candidate& candidate = candidates_[k - 1];
    candidate.sums.add(Vec3::load(full.point(pixel)));
    if (pixel < candidate.first_pixel) candidate.first_pixel = pixel;
    queue_.push_back(pixel);
  };

  // Seeds of the growth: unlabelled pixels next to a plane they fit, the best plane first.
  queue_.clear();
  for (int y = 0; y < height; ++y) {
    if (renumber_first && y + 1 < height) renumberRow(y + 1);
    const std::uint32_t* row = labels.data() + static_cast<std::size_t>(y) * width;
    for (int x = findInRow(row, 0, width - 1, 0u, true); x < width; x = findInRow(row, x + 1, width - 1, 0u, true)) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      const std::size_t neighbours[4] = {x > 0 ? i - 1 : i, x + 1 < width ? i + 1 : i,
                                         y > 0 ? i - width : i, y + 1 < height ? i + width : i};
      // Most unlabelled pixels (holes, clutter) have no labelled neighbour at all.
      if ((labels[neighbours[0]] | labels[neighbours[1]] | labels[neighbours[2]] | labels[neighbours[3]]) == 0)
        continue;
      std::uint32_t best = 0;
      float best_distance = std::numeric_limits<float>::infinity();
      for (const std::size_t j : neighbours) {
        const std::uint32_t k = labels[j];
        float distance = 0.f;
        if (k != 0 && k != best && fits(k, j, i, distance) && distance < best_distance) {
          best = k;
          best_distance = distance;
        }
      }
      if (best != 0) take(best, i);
    }
  }
  // Breadth-first growth from them.
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const std::size_t i = queue_[head];
    const std::uint32_t k = labels[i];
    const int x = static_cast<int>(i % static_cast<std::size_t>(width));
    const int y = static_cast<int>(i / static_cast<std::size_t>(width));
    float distance = 0.f;
    if (x > 0 && labels[i - 1] == 0 && fits(k, i, i - 1, distance)) take(k, i - 1);
    if (x + 1 < width && labels[i + 1] == 0 && fits(k, i, i + 1, distance)) take(k, i + 1);
    if (y > 0 && labels[i - width] == 0 && fits(k, i, i - width, distance)) take(k, i - width);
    if (y + 1 < height && labels[i + width] == 0 && fits(k, i, i + width, distance)) take(k, i + width);
  }
}

}  // namespace floodplane
