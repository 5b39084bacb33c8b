// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "full_resolution_write.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <cstdio>

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
  for (int bx = 0; bx < width; ++bx) {
    const std::size_t i = static_cast<std::size_t>(by) * static_cast<std::size_t>(width) + static_cast<std::size_t>(bx);
    const std::uint32_t k = block_labels[i];
    Block& block = blocks_[static_cast<std::size_t>(bx)];
    block.candidate_count = 0;
    bool uniform = true;
    for (int y = std::max(0, by - 1); y <= std::min(height - 1, by + 1); ++y) {
      for (int x = std::max(0, bx - 1); x <= std::min(width - 1, bx + 1); ++x) {
        const std::uint32_t l =
            block_labels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
        uniform = uniform && l == k;
        if (l == 0) continue;
        const auto end = block.candidates.begin() + block.candidate_count;
        if (std::find(block.candidates.begin(), end, l) == end) block.candidates[block.candidate_count++] = l;
      }
    }
    if (block.candidate_count == 0) {
      block.kind = Kind::kNone;
    } else if (!std::getenv("FP_TESTALL") && uniform && !blocks.split(i) && insideBand(blocks, i, criteria[k - 1])) {
      block.kind = Kind::kInside;
      block.plane = k;
    } else {
      block.kind = Kind::kBorder;
    }
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
  const int s = blocks.factor();
  const PointGrid& grid = blocks.means();
  const std::size_t frame_width = static_cast<std::size_t>(frame.width);
  std::size_t n_inside = 0, n_border = 0, n_none = 0;
  for (int by = 0; by < grid.height; ++by) {
    classifyRow(blocks, block_labels, criteria, by);
    for (const Block& b : blocks_) (b.kind == Kind::kInside ? n_inside : b.kind == Kind::kBorder ? n_border : n_none)++;
    const std::size_t first_block = static_cast<std::size_t>(by) * static_cast<std::size_t>(grid.width);
    // A block inside a plane adds its sums once.
    for (int bx = 0; bx < grid.width; ++bx) {
      const Block& block = blocks_[static_cast<std::size_t>(bx)];
      if (block.kind == Kind::kInside) blocks.addTo(first_block + static_cast<std::size_t>(bx), planes[block.plane].sums);
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
            } else {
              for (int u = u_begin; u < u_end; ++u) {
                const std::size_t pixel = row_start + static_cast<std::size_t>(u);
                const bool measured = finitePoint(frame.point(pixel));
                out_row[u] = measured ? k : 0u;
                if (measured && plane.first_pixel == kNoPixel) plane.first_pixel = pixel;
              }
            }
            break;
          }
          case Kind::kBorder:
            decidePixels(frame, row_start, u_begin, u_end, block, criteria, centroids, planes, out_row);
            break;
        }
      }
    }
  }
  if (std::getenv("FP_DEBUG")) std::fprintf(stderr, "blocks inside %zu border %zu none %zu\n", n_inside, n_border, n_none);
}

}  // namespace floodplane
