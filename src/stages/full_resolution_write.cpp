// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "stages/full_resolution_write.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/simd.h"

namespace floodplane {

namespace {

bool finitePoint(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// Whether the points of block i lie within plane c's noise band on average: their RMS distance
// from it at most the band across the plane (the noise band along the ray times the cosine of
// the incidence, or sigma_plane's fixed part). Noise alone gives a third of that.
bool insideBand(const BlockGrid& blocks, std::size_t i, const FloodCriterion& c) {
  const Vec3 mean = Vec3::load(blocks.means().point(i));
  const float range_sq = mean.squaredNorm();
  const float incidence = std::abs(c.normal.dot(mean)) / std::sqrt(range_sq);
  const double band = std::max(c.plane_threshold, c.noiseTolerance(range_sq) * incidence);
  return blocks.meanSquaredDistance(i, c.normal, c.offset) <= band * band;
}

}  // namespace

void FullResolutionWrite::classifyRow(const BlockGrid& blocks, const RenumberedLabels& block_labels,
                                      const std::vector<FloodCriterion>& criteria, int by) {
  const PointGrid& grid = blocks.means();
  const int width = grid.width, height = grid.height;
  blocks_.resize(static_cast<std::size_t>(width));
  // The labels of the block rows above, at and below `by`, read once: kEmpty for a block
  // without a measured pixel, which borders nothing (a hole next to a plane has no pixel to
  // decide), and beyond the grid's edge.
  const auto rowLabels = [&](int y, std::vector<std::uint32_t>& row) {
    row.assign(static_cast<std::size_t>(width) + 2, kEmpty);
    if (y < 0 || y >= height) return;
    const std::size_t first = static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
    for (int x = 0; x < width; ++x) {
      const std::size_t i = first + static_cast<std::size_t>(x);
      const std::uint32_t k = block_labels[i];
      row[static_cast<std::size_t>(x) + 1] = k == 0 && blocks.count(i) == 0 ? kEmpty : k;
    }
  };
  rowLabels(by - 1, above_);
  rowLabels(by, row_);
  rowLabels(by + 1, below_);
  const std::size_t first = static_cast<std::size_t>(by) * static_cast<std::size_t>(width);
  for (int bx = 0; bx < width; ++bx) {
    const std::size_t i = first + static_cast<std::size_t>(bx);
    Block& block = blocks_[static_cast<std::size_t>(bx)];
    block.candidate_count = 0;
    const std::uint32_t k = block_labels[i];
    const std::size_t x = static_cast<std::size_t>(bx) + 1;
    const std::uint32_t around[9] = {above_[x - 1], above_[x],     above_[x + 1], row_[x - 1],  row_[x],
                                     row_[x + 1],   below_[x - 1], below_[x],     below_[x + 1]};
    bool uniform = true;
    for (const std::uint32_t l : around) {
      if (l == kEmpty || l == k) continue;
      uniform = false;
      if (l == 0) continue;
      const auto end = block.candidates.begin() + block.candidate_count;
      if (std::find(block.candidates.begin(), end, l) == end) block.candidates[block.candidate_count++] = l;
    }
    if (uniform) {
      if (k == 0) {
        block.kind = Kind::kNone;
      } else if (!blocks.split(i) && insideBand(blocks, i, criteria[k - 1])) {
        block.kind = Kind::kInside;
        block.plane = k;
      } else {
        block.kind = Kind::kBorder;
        block.candidates[0] = k;
        block.candidate_count = 1;
      }
      continue;
    }
    if (k != 0) {
      const auto end = block.candidates.begin() + block.candidate_count;
      if (std::find(block.candidates.begin(), end, k) == end) block.candidates[block.candidate_count++] = k;
    }
    block.kind = block.candidate_count == 0 ? Kind::kNone : Kind::kBorder;
  }
}

void FullResolutionWrite::decidePixels(const PointGrid& frame, std::size_t row_start, int u_begin, int u_end,
                                       const Block& block, const std::vector<FloodCriterion>& criteria,
                                       const std::vector<Vec3>& centroids, PlaneCandidates& planes,
                                       std::uint32_t* out_row) const {
  for (int u = u_begin; u < u_end; ++u) {
    const std::size_t pixel = row_start + static_cast<std::size_t>(u);
    const float* p = frame.point(pixel);
    std::uint32_t best = 0;
    if (finitePoint(p)) {
      const Vec3 q = Vec3::load(p);
      const float range_sq = q.squaredNorm();
      float best_distance = 0.f, best_depth = 0.f;
      for (int c = 0; c < block.candidate_count; ++c) {
        const std::uint32_t k = block.candidates[static_cast<std::size_t>(c)];
        const FloodCriterion& plane = criteria[k - 1];
        // The noise is taken at the nearer of q and the plane's point on q's ray: an outlier
        // far along its ray must not widen its own band until it fits (see nearerRangeSq).
        const float dot = plane.normal.dot(q);
        const float plane_range_sq = plane.offset * plane.offset * range_sq / (dot * dot);
        float distance = 0.f;  // along q's ray
        if (!plane.fitsPlane(q, nearerRangeSq(plane_range_sq, range_sq), distance)) continue;
        const float depth = -plane.offset / dot;  // where q's ray meets the plane, in units of q
        if (best == 0 || prefers(k, depth, distance, best, best_depth, best_distance, criteria, centroids)) {
          best = k;
          best_distance = distance;
          best_depth = depth;
        }
      }
      if (best != 0) {
        PlaneCandidate& plane = planes[best];
        plane.sums.add(q);
        if (plane.first_pixel == kNoPixel) plane.first_pixel = pixel;
      }
    }
    out_row[u] = best;
  }
}

void FullResolutionWrite::decideForOnePlane(const PointGrid& frame, std::size_t row_start, int u_begin, int u_end,
                                            std::uint32_t k, const std::vector<FloodCriterion>& criteria,
                                            PlaneCandidates& planes, std::uint32_t* out_row) const {
  // decidePixels for a block with one plane around (a plane's edge next to no plane, the
  // commonest border): four pixels at a time where the frame has four floats a point, with
  // the scalar code's operations in its order lane by lane; only the order in which the
  // points reach the sums differs.
  const FloodCriterion& plane = criteria[k - 1];
  PlaneCandidate& candidate = planes[k];
  int u = u_begin;
#if FLOODPLANE_SIMD
  if (fourPixelsAtATime(frame)) {
    LaneSums lanes;
    const Float4 offset_sq = Float4::broadcast(plane.offset * plane.offset);
    for (; u + 4 <= u_end; u += 4) {
      const std::size_t pixel = row_start + static_cast<std::size_t>(u);
      const PointLanes q = PointLanes::load(frame, pixel);
      const Float4 range_sq = q.squaredNorm();
      const Float4 dot = q.dot(plane.normal);
      const Float4 plane_range_sq = offset_sq * range_sq / (dot * dot);
      Float4 distance;
      // A hole (NaN) fails: its distance is NaN.
      const Mask4 fits = plane.fitsPlane(q, Float4::min(plane_range_sq, range_sq), distance);
      fits.storeLabels(out_row + u, k);
      lanes.add(q, fits);
      if (candidate.first_pixel == kNoPixel && fits.any())
        candidate.first_pixel = pixel + static_cast<std::size_t>(fits.firstSet());
    }
    lanes.addTo(candidate.sums);
  }
#endif
  for (; u < u_end; ++u) {
    const std::size_t pixel = row_start + static_cast<std::size_t>(u);
    const float* p = frame.point(pixel);
    bool fits = false;
    if (finitePoint(p)) {
      const Vec3 q = Vec3::load(p);
      const float range_sq = q.squaredNorm();
      const float dot = plane.normal.dot(q);
      const float plane_range_sq = plane.offset * plane.offset * range_sq / (dot * dot);
      float distance = 0.f;
      fits = plane.fitsPlane(q, nearerRangeSq(plane_range_sq, range_sq), distance);
      if (fits) {
        candidate.sums.add(q);
        if (candidate.first_pixel == kNoPixel) candidate.first_pixel = pixel;
      }
    }
    out_row[u] = fits ? k : 0u;
  }
}

bool FullResolutionWrite::prefers(std::uint32_t a, float depth_a, float distance_a, std::uint32_t b, float depth_b,
                                  float distance_b, const std::vector<FloodCriterion>& criteria,
                                  const std::vector<Vec3>& centroids) {
  // Near the line where two planes meet, a pixel fits both within the noise, and the smaller
  // depth error picks one by the noise's coin flip: the border frays, over a band as wide as
  // the noise makes the two planes indistinguishable (20 pixels along a room's corner at 4 m
  // from a Kinect). Which plane the ray sees there follows from the geometry instead: at a
  // concave crease (each plane's points in front of the other plane: a room's corner) the
  // ray meets the surface where it meets the nearer plane; at a convex one (each behind the
  // other: a box's edge) where it meets the farther. Elsewhere (a board in front of a wall,
  // where one plane's points lie in front of the other and the other's behind the first) the
  // smaller depth error decides.
  const FloodCriterion& pa = criteria[a - 1];
  const FloodCriterion& pb = criteria[b - 1];
  const float a_before_b = pb.normal.dot(centroids[a - 1]) + pb.offset;
  const float b_before_a = pa.normal.dot(centroids[b - 1]) + pa.offset;
  if (a_before_b > 0.f && b_before_a > 0.f) return depth_a < depth_b;
  if (a_before_b < 0.f && b_before_a < 0.f) return depth_a > depth_b;
  return distance_a < distance_b;
}

void FullResolutionWrite::write(const PointGrid& frame, const BlockGrid& blocks, const RenumberedLabels& block_labels,
                                const std::vector<FloodCriterion>& criteria, const std::vector<Vec3>& centroids,
                                PlaneCandidates& planes, std::vector<std::uint32_t>& labels) {
  labels.resize(frame.size());
  for (PlaneCandidate& plane : planes.list()) {
    plane.sums = PlaneSums();
    plane.first_pixel = kNoPixel;
  }
  body_start_.assign(planes.list().size() + 1, kNoPixel);
  const int s = blocks.factor();
  const PointGrid& grid = blocks.means();
  const std::size_t frame_width = static_cast<std::size_t>(frame.width);
  for (int by = 0; by < grid.height; ++by) {
    classifyRow(blocks, block_labels, criteria, by);
    const std::size_t first_block = static_cast<std::size_t>(by) * static_cast<std::size_t>(grid.width);
    // A block inside a plane adds its sums once.
    for (int bx = 0; bx < grid.width; ++bx) {
      const Block& block = blocks_[static_cast<std::size_t>(bx)];
      if (block.kind == Kind::kInside)
        blocks.addTo(first_block + static_cast<std::size_t>(bx), planes[block.plane].sums);
    }
    const int v_end = std::min(blocks.firstRow(by) + s, frame.height);
    for (int v = blocks.firstRow(by); v < v_end; ++v) {
      const std::size_t row_start = static_cast<std::size_t>(v) * frame_width;
      std::uint32_t* out_row = labels.data() + row_start;
      for (int bx = 0; bx < grid.width; ++bx) {
        const Block& block = blocks_[static_cast<std::size_t>(bx)];
        const int u_begin = blocks.firstColumn(bx), u_end = std::min(u_begin + s, frame.width);
        switch (block.kind) {
          case Kind::kNone:
            std::fill(out_row + u_begin, out_row + u_end, 0u);
            break;
          case Kind::kInside: {
            const std::uint32_t k = block.plane;
            PlaneCandidate& plane = planes[k];
            if (blocks.complete(first_block + static_cast<std::size_t>(bx))) {
              std::fill(out_row + u_begin, out_row + u_end, k);
              if (plane.first_pixel == kNoPixel) plane.first_pixel = row_start + static_cast<std::size_t>(u_begin);
              if (body_start_[k] == kNoPixel) body_start_[k] = row_start + static_cast<std::size_t>(u_begin);
            } else {
              for (int u = u_begin; u < u_end; ++u) {
                const std::size_t pixel = row_start + static_cast<std::size_t>(u);
                const bool measured = finitePoint(frame.point(pixel));
                out_row[u] = measured ? k : 0u;
                if (measured && plane.first_pixel == kNoPixel) plane.first_pixel = pixel;
                if (measured && body_start_[k] == kNoPixel) body_start_[k] = pixel;
              }
            }
            break;
          }
          case Kind::kBorder:
            if (block.candidate_count == 1)
              decideForOnePlane(frame, row_start, u_begin, u_end, block.candidates[0], criteria, planes, out_row);
            else
              decidePixels(frame, row_start, u_begin, u_end, block, criteria, centroids, planes, out_row);
            break;
        }
      }
    }
  }
  // A pixel decided one by one can fit a plane without touching it (a pixel of clutter within
  // the plane's band), and the first pixel in raster order may be such a stray: its boundary
  // would be a single pixel. A plane's boundary starts instead on its body, at the left end of
  // the row through the first pixel of its first inner block; only a plane without one
  // starts at its first pixel.
  const std::size_t width = static_cast<std::size_t>(frame.width);
  for (std::uint32_t k = 1; k < body_start_.size(); ++k) {
    std::size_t start = body_start_[k];
    if (start == kNoPixel) continue;
    while (start % width != 0 && labels[start - 1] == k) --start;
    planes[k].first_pixel = start;
  }
}

}  // namespace floodplane
