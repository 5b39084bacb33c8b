// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "stages/coarse_planes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/depth_noise.h"
#include "stages/plane_candidates.h"

namespace floodplane {

namespace {

// A coarse plane has at least this many blocks: fewer have no block inside them (a block
// with its eight neighbours is 3 x 3).
constexpr std::uint32_t kSmallestCluster = 9;
// A pocket of more blocks than this is left to the fine pass: a large patch that is not inside
// the plane around it is another surface (an object on a table, a picture on a wall).
constexpr std::size_t kLargestPocket = 16;

}  // namespace

bool CoarsePlanes::insideBand(const BlockGrid& blocks, std::size_t i, const Vec3& normal, float offset,
                              const Tolerances& measured_tolerances) {
  // The band across the plane: one pixel's noise band along its ray (Eq. 2) times the cosine
  // of the incidence, or sigma_plane's fixed part. Noise alone gives a third of that.
  const Vec3 mean = Vec3::load(blocks.means().point(i));
  const double range_sq = mean.squaredNorm();
  const double range = std::sqrt(range_sq);
  const double incidence = std::abs(normal.dot(mean)) / range;
  const double band = std::max(measured_tolerances.planeFloor(range),
                               noiseDeviations(measured_tolerances.noise(), kPointDeviations, range_sq) * incidence);
  return blocks.meanSquaredDistance(i, normal, offset) <= band * band;
}

void CoarsePlanes::find(const BlockGrid& blocks, const FloodGrid& block_grid, const FloodPass& coarse,
                        const MergedSegments& merged, const Params& params, const Tolerances& measured_tolerances) {
  planes_.clear();
  const PointGrid& means = blocks.means();
  const Tolerances& block_tolerances = block_grid.tolerances;
  const std::size_t segment_count = merged.segment_count;
  const auto root = [&](std::size_t block) {
    const std::int32_t segment = merged.labels[block];
    return segment == 0 ? 0 : merged.root[segment];
  };
  // Each cluster's block means, one each: the sums whose scatter the block tolerances describe.
  cluster_sums_.assign(segment_count, PlaneSums());
  block_counts_.assign(segment_count, 0);
  for (std::size_t i = 0; i < means.size(); ++i) {
    const std::int32_t r = root(i);
    if (r == 0 || blocks.count(i) == 0) continue;
    cluster_sums_[static_cast<std::size_t>(r)].add(Vec3::load(means.point(i)));
    ++block_counts_[static_cast<std::size_t>(r)];
  }
  // The candidates: clusters large enough to have a block inside, planes as the output has them.
  plane_of_root_.assign(segment_count, 0);
  fits_.clear();
  candidate_root_.clear();
  for (std::size_t r = 1; r < segment_count; ++r) {
    if (merged.root[r] != static_cast<std::int32_t>(r) || block_counts_[r] < kSmallestCluster) continue;
    const PlaneFit fit = cluster_sums_[r].fit();
    if (!acceptablePlane(fit, params)) continue;
    fits_.push_back(fit);
    candidate_root_.push_back(static_cast<std::int32_t>(r));
    plane_of_root_[r] = static_cast<std::int32_t>(fits_.size());
  }
  const std::size_t candidates = fits_.size();
  // Flat as a whole: a block mean is a point of the planarity test.
  planarity_.reset(fits_);
  candidate_of_block_.assign(means.size(), 0);
  for (std::size_t i = 0; i < means.size(); ++i) {
    const std::int32_t r = root(i);
    if (r == 0 || blocks.count(i) == 0) continue;
    const std::int32_t k = plane_of_root_[static_cast<std::size_t>(r)];
    if (k == 0) continue;
    planarity_.add(static_cast<std::uint32_t>(k), Vec3::load(means.point(i)));
    candidate_of_block_[i] = static_cast<std::uint32_t>(k);
  }
  curved_.assign(candidates + 1, false);
  judgeable_.assign(candidates + 1, false);
  for (std::uint32_t k = 1; k <= candidates; ++k) {
    curved_[k] = planarity_.curved(k, block_tolerances);
    judgeable_[k] = planarity_.judgeable(k);
  }
  // Touching candidates judged as one surface (as at the end for the planes, FacetPairs): the
  // facets of one curved body are curved together, although each alone may pass.
  facets_.resize(candidates);
  for (std::size_t k = 0; k < candidates; ++k)
    facets_[k].criterion = planeCriterion(fits_[k], block_tolerances, block_grid.pitch);
  facet_pairs_.find(block_grid.points, PlainLabels{candidate_of_block_.data()}, facets_, fits_, judgeable_);
  for (const auto& [k, l] : facet_pairs_.pairs()) {
    if (curved_[k] && curved_[l]) continue;
    PlaneSums joint = cluster_sums_[static_cast<std::size_t>(candidate_root_[k - 1])];
    joint.merge(cluster_sums_[static_cast<std::size_t>(candidate_root_[l - 1])]);
    if (planarity_.curvedPair(k, l, joint.fit(), block_tolerances)) curved_[k] = curved_[l] = true;
  }
  // Chains of small facets meeting at shallow angles, far from one plane together: a body.
  chain_sums_.clear();
  for (std::size_t k = 0; k < candidates; ++k)
    chain_sums_.push_back(&cluster_sums_[static_cast<std::size_t>(candidate_root_[k])]);
  facet_chains_.judge(means, candidate_of_block_, fits_, chain_sums_, block_tolerances, curved_);
  std::vector<std::int32_t> plane_of_candidate(candidates + 1, 0);
  for (std::uint32_t k = 1; k <= candidates; ++k) {
    if (curved_[k]) continue;
    planes_.emplace_back();
    plane_of_candidate[k] = static_cast<std::int32_t>(planes_.size());
  }
  for (std::size_t r = 1; r < segment_count; ++r)
    if (plane_of_root_[r] != 0) plane_of_root_[r] = plane_of_candidate[static_cast<std::size_t>(plane_of_root_[r])];
  inner_plane_.assign(means.size(), 0);
  if (planes_.empty()) return;
  // The inner blocks: one surface with their eight neighbours (or without a measured pixel, or
  // beyond the frame's edge), their pixels within the noise band of that surface.
  const int width = means.width, height = means.height;
  const std::vector<Segment>& segments = coarse.segments();
  for (int by = 0; by < height; ++by) {
    for (int bx = 0; bx < width; ++bx) {
      const std::size_t i =
          static_cast<std::size_t>(by) * static_cast<std::size_t>(width) + static_cast<std::size_t>(bx);
      const std::int32_t r = root(i);
      if (r == 0 || blocks.count(i) == 0 || blocks.split(i)) continue;
      const std::int32_t k = plane_of_root_[static_cast<std::size_t>(r)];
      if (k == 0) continue;
      // Its segment's plane: its neighbours' means lie within that plane's band at the means'
      // noise (Eq. 2 of the coarse pass), so that the surface goes on around the block, and its
      // own pixels within the pixels' band on average.
      const FloodCriterion& own = segments[static_cast<std::size_t>(merged.labels[i])].criterion;
      bool inside = true;
      for (int dy = -1; dy <= 1 && inside; ++dy) {
        for (int dx = -1; dx <= 1 && inside; ++dx) {
          const int x = bx + dx, y = by + dy;
          if (x < 0 || y < 0 || x >= width || y >= height) continue;
          const std::size_t j =
              static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
          if (blocks.count(j) == 0) continue;
          if (blocks.split(j)) {
            inside = false;
          } else {
            const Vec3 mean = Vec3::load(means.point(j));
            float distance = 0.f;
            inside = own.fitsPlane(mean, mean.squaredNorm(), distance);
          }
        }
      }
      if (!inside || !insideBand(blocks, i, own.normal, own.offset, measured_tolerances)) continue;
      Plane& plane = planes_[static_cast<std::size_t>(k - 1)];
      plane.inner.push_back(i);
      inner_plane_[i] = k;
      blocks.addMeanTo(i, plane.sums);
    }
  }
}

std::size_t CoarsePlanes::claim(const BlockGrid& blocks, const PointGrid& pixels, const HoleFilling& holes,
                                const Tolerances& fine_tolerances, float pixel_pitch, FloodPass& fine,
                                SegmentationStats& stats) {
  std::size_t claimed = 0;
  const int s = blocks.factor();
  const int block_width = blocks.means().width, block_height = blocks.means().height;
  const std::size_t width = static_cast<std::size_t>(pixels.width);
  const auto pixel = [&](int u, int v) { return static_cast<std::size_t>(v) * width + static_cast<std::size_t>(u); };
  labels_.assign(planes_.size(), 0);
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    const Plane& plane = planes_[k];
    if (plane.inner.empty()) continue;
    const PlaneFit fit = plane.sums.fit();
    if (!fit.valid) continue;
    Segment segment;
    segment.sums = plane.sums;
    segment.criterion = planeCriterion(fit, fine_tolerances, pixel_pitch);
    const std::int32_t label = fine.addSegment(segment);
    labels_[k] = label;
    PlaneSums filled;
    for (const std::size_t i : plane.inner) {
      const int bx = static_cast<int>(i % static_cast<std::size_t>(block_width));
      const int by = static_cast<int>(i / static_cast<std::size_t>(block_width));
      const int u_end = std::min(blocks.firstColumn(bx) + s, pixels.width);
      const int v_end = std::min(blocks.firstRow(by) + s, pixels.height);
      const int u_begin = blocks.firstColumn(bx);
      if (blocks.complete(i)) {
        // Every pixel measured: none is a hole, none filled in.
        for (int v = blocks.firstRow(by); v < v_end; ++v)
          fine.claimRun(pixel(u_begin, v), static_cast<std::size_t>(u_end - u_begin), label);
        claimed += blocks.count(i);
        continue;
      }
      for (int v = blocks.firstRow(by); v < v_end; ++v) {
        for (int u = u_begin; u < u_end; ++u) {
          const std::size_t p = pixel(u, v);
          if (!pixels.isFinite(p)) continue;
          fine.claim(p, label);
          if (holes.isFilled(p)) filled.add(Vec3::load(pixels.point(p)));
          ++claimed;
        }
      }
    }
    fine.addToSums(label, filled);
  }
  // Inner blocks of two planes side by side: the two touch without a pixel of the fine pass
  // between them, which would have noted the pair for merging.
  for (int by = 0; by < block_height; ++by) {
    for (int bx = 0; bx < block_width; ++bx) {
      const std::size_t i =
          static_cast<std::size_t>(by) * static_cast<std::size_t>(block_width) + static_cast<std::size_t>(bx);
      const std::int32_t k = inner_plane_[i];
      if (k == 0 || labels_[static_cast<std::size_t>(k - 1)] == 0) continue;
      const std::int32_t right = bx + 1 < block_width ? inner_plane_[i + 1] : 0;
      const std::int32_t below = by + 1 < block_height ? inner_plane_[i + static_cast<std::size_t>(block_width)] : 0;
      for (const std::int32_t l : {right, below})
        if (l != 0 && l != k && labels_[static_cast<std::size_t>(l - 1)] != 0)
          fine.addEdge(labels_[static_cast<std::size_t>(k - 1)], labels_[static_cast<std::size_t>(l - 1)]);
    }
  }
  fillPockets(blocks, pixels, fine_tolerances, pixel_pitch, fine, stats);
  // Each plane's inner blocks along their edge (a side whose neighbour is not inside the same
  // plane): the pixels of that side start its flood into the pixels around.
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    if (labels_[k] == 0) continue;
    const std::int32_t own = static_cast<std::int32_t>(k + 1);
    starts_.clear();
    for (const std::size_t i : planes_[k].inner) {
      const int bx = static_cast<int>(i % static_cast<std::size_t>(block_width));
      const int by = static_cast<int>(i / static_cast<std::size_t>(block_width));
      const auto inside = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < block_width && y < block_height &&
               inner_plane_[static_cast<std::size_t>(y) * static_cast<std::size_t>(block_width) +
                            static_cast<std::size_t>(x)] == own;
      };
      const int u0 = blocks.firstColumn(bx), v0 = blocks.firstRow(by);
      const int u1 = std::min(u0 + s, pixels.width) - 1, v1 = std::min(v0 + s, pixels.height) - 1;
      // A pixel of the side starts a flood where the pixel beyond it is not the plane's yet:
      // the fill looks at the pixels around its start first.
      const std::vector<std::int32_t>& claimed_by = fine.labels();
      const auto add = [&](int u, int v, int du, int dv) {
        const std::size_t p = pixel(u, v);
        if (claimed_by[p] == labels_[k] && claimed_by[pixel(u + du, v + dv)] != labels_[k]) starts_.push_back(p);
      };
      if (bx > 0 && !inside(bx - 1, by))
        for (int v = v0; v <= v1; ++v) add(u0, v, -1, 0);
      if (u1 + 1 < pixels.width && !inside(bx + 1, by))
        for (int v = v0; v <= v1; ++v) add(u1, v, 1, 0);
      if (by > 0 && !inside(bx, by - 1))
        for (int u = u0; u <= u1; ++u) add(u, v0, 0, -1);
      if (v1 + 1 < pixels.height && !inside(bx, by + 1))
        for (int u = u0; u <= u1; ++u) add(u, v1, 0, 1);
    }
    fine.extend(labels_[k], starts_, fine.segments()[static_cast<std::size_t>(labels_[k])].criterion, stats);
  }
  return claimed;
}

void CoarsePlanes::fillPockets(const BlockGrid& blocks, const PointGrid& pixels, const Tolerances& fine_tolerances,
                               float pixel_pitch, FloodPass& fine, SegmentationStats& stats) {
  const int s = blocks.factor();
  const int block_width = blocks.means().width, block_height = blocks.means().height;
  const std::size_t width = static_cast<std::size_t>(pixels.width);
  const auto block = [&](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(block_width) + static_cast<std::size_t>(x);
  };
  const auto pixel = [&](int u, int v) { return static_cast<std::size_t>(v) * width + static_cast<std::size_t>(u); };
  pocket_mark_.assign(inner_plane_.size(), 0);
  const std::vector<std::int32_t>& claimed_by = fine.labels();
  for (int by = 0; by < block_height; ++by) {
    for (int bx = 0; bx < block_width; ++bx) {
      const std::size_t first = block(bx, by);
      if (inner_plane_[first] != 0 || pocket_mark_[first] != 0 || blocks.count(first) == 0) continue;
      // The blocks of one pocket (4-connected blocks with measured pixels, none inside a plane)
      // and the one plane around it, if there is one: -1 where the pocket touches the frame's
      // edge or another plane's inside. A block without a measured pixel is no way out.
      pocket_.assign(1, first);
      pocket_mark_[first] = 1;
      std::int32_t around = 0;
      for (std::size_t next = 0; next < pocket_.size(); ++next) {
        const int x = static_cast<int>(pocket_[next] % static_cast<std::size_t>(block_width));
        const int y = static_cast<int>(pocket_[next] / static_cast<std::size_t>(block_width));
        const int neighbours[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
        for (const auto& [nx, ny] : neighbours) {
          if (nx < 0 || ny < 0 || nx >= block_width || ny >= block_height) {
            around = -1;
            continue;
          }
          const std::size_t j = block(nx, ny);
          const std::int32_t k = inner_plane_[j];
          if (k != 0) {
            around = around == 0 || around == k ? k : -1;
          } else if (blocks.count(j) != 0 && pocket_mark_[j] == 0) {
            pocket_mark_[j] = 1;
            pocket_.push_back(j);
          }
        }
      }
      if (around <= 0 || pocket_.size() > kLargestPocket || labels_[static_cast<std::size_t>(around - 1)] == 0)
        continue;
      // The plane's inner blocks around the pocket (eight-neighbours of its blocks): their means
      // give the plane where the pocket is, and their sides on the pocket start its flood.
      PlaneSums local;
      starts_.clear();
      const std::int32_t label = labels_[static_cast<std::size_t>(around - 1)];
      for (const std::size_t i : pocket_) {
        const int x = static_cast<int>(i % static_cast<std::size_t>(block_width));
        const int y = static_cast<int>(i / static_cast<std::size_t>(block_width));
        for (int ny = y - 1; ny <= y + 1; ++ny)
          for (int nx = x - 1; nx <= x + 1; ++nx) {
            if (nx < 0 || ny < 0 || nx >= block_width || ny >= block_height) continue;
            const std::size_t j = block(nx, ny);
            if (inner_plane_[j] != around || pocket_mark_[j] == 2) continue;
            pocket_mark_[j] = 2;  // counted once
            blocks.addMeanTo(j, local);
          }
        // The pixels along the pocket block's edge, inside, whose neighbour outside is the
        // plane's: the fill starts from the plane's pixel next to each.
        const int u0 = blocks.firstColumn(x), v0 = blocks.firstRow(y);
        const int u1 = std::min(u0 + s, pixels.width) - 1, v1 = std::min(v0 + s, pixels.height) - 1;
        const auto add = [&](int u, int v) {
          if (claimed_by[pixel(u, v)] == label) starts_.push_back(pixel(u, v));
        };
        for (int v = v0; v <= v1; ++v) {
          if (u0 > 0) add(u0 - 1, v);
          if (u1 + 1 < pixels.width) add(u1 + 1, v);
        }
        for (int u = u0; u <= u1; ++u) {
          if (v0 > 0) add(u, v0 - 1);
          if (v1 + 1 < pixels.height) add(u, v1 + 1);
        }
      }
      for (const std::size_t i : pocket_)
        for (int ny = static_cast<int>(i / static_cast<std::size_t>(block_width)) - 1;
             ny <= static_cast<int>(i / static_cast<std::size_t>(block_width)) + 1; ++ny)
          for (int nx = static_cast<int>(i % static_cast<std::size_t>(block_width)) - 1;
               nx <= static_cast<int>(i % static_cast<std::size_t>(block_width)) + 1; ++nx)
            if (nx >= 0 && ny >= 0 && nx < block_width && ny < block_height && pocket_mark_[block(nx, ny)] == 2)
              pocket_mark_[block(nx, ny)] = 0;
      const PlaneFit fit = local.fit();
      if (!(normalUncertainty(fit, local.count) < std::numeric_limits<double>::infinity())) continue;
      fine.extend(label, starts_, planeCriterion(fit, fine_tolerances, pixel_pitch), stats);
    }
  }
}

}  // namespace floodplane
