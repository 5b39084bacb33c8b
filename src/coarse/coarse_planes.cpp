// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "coarse/coarse_planes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/depth_noise.h"
#include "models/plane_candidates.h"

namespace floodplane {

namespace {

// A coarse plane has at least this many blocks: fewer have no block inside them (a block
// with its eight neighbours is 3 x 3).
constexpr std::uint32_t kSmallestCluster = 9;
// A pocket of more blocks than this is left to the fine pass: a large patch that is not inside
// the plane around it is another surface (an object on a table, a picture on a wall).
constexpr std::size_t kLargestPocket = 16;

std::size_t blockIndex(int block_width, int bx, int by) {
  return static_cast<std::size_t>(by) * static_cast<std::size_t>(block_width) + static_cast<std::size_t>(bx);
}

std::size_t pixelIndex(const PointGrid& pixels, int u, int v) {
  return static_cast<std::size_t>(v) * static_cast<std::size_t>(pixels.width) + static_cast<std::size_t>(u);
}

// The cluster block i belongs to: the root of its coarse segment, 0 none.
std::int32_t clusterRoot(const MergedSegments& merged, std::size_t i) {
  const std::int32_t segment = merged.labels[i];
  return segment == 0 ? 0 : merged.root[segment];
}

}  // namespace

void CoarsePlanes::find(const BlockGrid& blocks, const FloodGrid& block_grid, const FloodPass& coarse,
                        const MergedSegments& merged, const Params& params, const Tolerances& measured_tolerances) {
  planes_.clear();
  sumClusters(blocks, merged);
  pickCandidates(merged, params);
  testFlatness(blocks, merged, block_grid.tolerances);
  testFacetPairs(block_grid);
  testFacetChains(blocks.means(), block_grid.tolerances);
  numberPlanes();
  inner_plane_.assign(blocks.means().size(), 0);
  if (planes_.empty()) return;
  findInnerBlocks(blocks, coarse, merged, measured_tolerances);
}

void CoarsePlanes::sumClusters(const BlockGrid& blocks, const MergedSegments& merged) {
  // Each cluster's block means, one each: the sums whose scatter the block tolerances describe.
  clusters_.sums.assign(merged.segment_count, PlaneSums());
  clusters_.blocks.assign(merged.segment_count, 0);
  const PointGrid& means = blocks.means();
  for (std::size_t i = 0; i < means.size(); ++i) {
    const std::int32_t r = clusterRoot(merged, i);
    if (r == 0 || blocks.count(i) == 0) continue;
    clusters_.sums[static_cast<std::size_t>(r)].add(Vec3::load(means.point(i)));
    ++clusters_.blocks[static_cast<std::size_t>(r)];
  }
}

void CoarsePlanes::pickCandidates(const MergedSegments& merged, const Params& params) {
  // The candidates: clusters large enough to have a block inside, planes as the output has them.
  clusters_.candidate.assign(merged.segment_count, 0);
  fits_.clear();
  candidate_root_.clear();
  for (std::size_t r = 1; r < merged.segment_count; ++r) {
    if (merged.root[r] != static_cast<std::int32_t>(r) || clusters_.blocks[r] < kSmallestCluster) continue;
    const PlaneFit fit = clusters_.sums[r].fit();
    if (!acceptablePlane(fit, params)) continue;
    fits_.push_back(fit);
    candidate_root_.push_back(static_cast<std::int32_t>(r));
    clusters_.candidate[r] = static_cast<std::int32_t>(fits_.size());
  }
}

void CoarsePlanes::testFlatness(const BlockGrid& blocks, const MergedSegments& merged,
                                const Tolerances& block_tolerances) {
  // Flat as a whole: a block mean is a point of the planarity test.
  const std::size_t candidates = fits_.size();
  const PointGrid& means = blocks.means();
  planarity_.reset(fits_);
  candidate_of_block_.assign(means.size(), 0);
  for (std::size_t i = 0; i < means.size(); ++i) {
    const std::int32_t r = clusterRoot(merged, i);
    if (r == 0 || blocks.count(i) == 0) continue;
    const std::int32_t k = clusters_.candidate[static_cast<std::size_t>(r)];
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
}

void CoarsePlanes::testFacetPairs(const FloodGrid& block_grid) {
  const std::size_t candidates = fits_.size();
  const Tolerances& block_tolerances = block_grid.tolerances;
  // Touching candidates judged as one surface (as at the end for the planes, FacetPairs): the
  // facets of one curved body are curved together, although each alone may pass.
  facets_.resize(candidates);
  for (std::size_t k = 0; k < candidates; ++k)
    facets_[k].criterion = planeCriterion(fits_[k], block_tolerances, block_grid.pitch);
  facet_pairs_.find(block_grid.points, PlainLabels{candidate_of_block_.data()}, facets_, fits_, judgeable_);
  for (const auto& [k, l] : facet_pairs_.pairs()) {
    if (curved_[k] && curved_[l]) continue;
    PlaneSums joint = clusters_.sums[static_cast<std::size_t>(candidate_root_[k - 1])];
    joint.merge(clusters_.sums[static_cast<std::size_t>(candidate_root_[l - 1])]);
    if (planarity_.curvedPair(k, l, joint.fit(), block_tolerances)) curved_[k] = curved_[l] = true;
  }
}

void CoarsePlanes::testFacetChains(const PointGrid& means, const Tolerances& block_tolerances) {
  // Chains of small facets meeting at shallow angles, far from one plane together: a body.
  chain_sums_.clear();
  for (const std::int32_t root : candidate_root_)
    chain_sums_.push_back(&clusters_.sums[static_cast<std::size_t>(root)]);
  facet_chains_.judge(means, candidate_of_block_, fits_, chain_sums_, block_tolerances, curved_);
}

void CoarsePlanes::numberPlanes() {
  // The candidates that are not curved, in their order: the planes.
  clusters_.plane.assign(clusters_.candidate.size(), 0);
  for (std::uint32_t k = 1; k <= fits_.size(); ++k) {
    if (curved_[k]) continue;
    planes_.emplace_back();
    clusters_.plane[static_cast<std::size_t>(candidate_root_[k - 1])] = static_cast<std::int32_t>(planes_.size());
  }
}

void CoarsePlanes::findInnerBlocks(const BlockGrid& blocks, const FloodPass& coarse, const MergedSegments& merged,
                                   const Tolerances& measured_tolerances) {
  // The inner blocks: one surface with their eight neighbours (or without a measured pixel, or
  // beyond the frame's edge), their pixels within the noise band of that surface.
  const int width = blocks.means().width, height = blocks.means().height;
  const std::vector<Segment>& segments = coarse.segments();
  for (int by = 0; by < height; ++by) {
    for (int bx = 0; bx < width; ++bx) {
      const std::size_t i = blockIndex(width, bx, by);
      const std::int32_t r = clusterRoot(merged, i);
      if (r == 0 || blocks.count(i) == 0 || blocks.split(i)) continue;
      const std::int32_t k = clusters_.plane[static_cast<std::size_t>(r)];
      if (k == 0) continue;
      // Its segment's plane: its neighbours' means lie within that plane's band at the means'
      // noise (Eq. 2 of the coarse pass), so that the surface goes on around the block, and its
      // own pixels within the pixels' band on average.
      const FloodCriterion& own = segments[static_cast<std::size_t>(merged.labels[i])].criterion;
      if (!surroundedBySurface(blocks, bx, by, own) ||
          !insideBand(blocks, i, own.normal, own.offset, measured_tolerances))
        continue;
      Plane& plane = planes_[static_cast<std::size_t>(k - 1)];
      plane.inner.push_back(i);
      inner_plane_[i] = k;
      blocks.addMeanTo(i, plane.sums);
    }
  }
}

bool CoarsePlanes::surroundedBySurface(const BlockGrid& blocks, int bx, int by, const FloodCriterion& own) {
  const PointGrid& means = blocks.means();
  for (int y = std::max(by - 1, 0); y <= std::min(by + 1, means.height - 1); ++y) {
    for (int x = std::max(bx - 1, 0); x <= std::min(bx + 1, means.width - 1); ++x) {
      const std::size_t j = blockIndex(means.width, x, y);
      if (blocks.count(j) == 0) continue;  // no measured pixel: no way out, no surface either
      if (blocks.split(j)) return false;
      const Vec3 mean = Vec3::load(means.point(j));
      float distance = 0.f;
      if (!own.fitsPlane(mean, mean.squaredNorm(), distance)) return false;
    }
  }
  return true;
}

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

std::size_t CoarsePlanes::claim(const BlockGrid& blocks, const PointGrid& pixels, const HoleFilling& holes,
                                const Tolerances& fine_tolerances, float pixel_pitch, FloodPass& fine,
                                SegmentationStats& stats) {
  const std::size_t claimed = claimInnerBlocks(blocks, pixels, holes, fine_tolerances, pixel_pitch, fine);
  noteTouchingPlanes(blocks, fine);
  fillPockets(blocks, pixels, fine_tolerances, pixel_pitch, fine, stats);
  floodFromInnerEdges(blocks, pixels, fine, stats);
  return claimed;
}

std::size_t CoarsePlanes::claimInnerBlocks(const BlockGrid& blocks, const PointGrid& pixels, const HoleFilling& holes,
                                           const Tolerances& fine_tolerances, float pixel_pitch, FloodPass& fine) {
  // A segment of the fine pass per plane with inner blocks, holding their pixels.
  std::size_t claimed = 0;
  for (Plane& plane : planes_) {
    plane.label = 0;
    if (plane.inner.empty()) continue;
    const PlaneFit fit = plane.sums.fit();
    if (!fit.valid) continue;
    Segment segment;
    segment.sums = plane.sums;
    segment.criterion = planeCriterion(fit, fine_tolerances, pixel_pitch);
    plane.label = fine.addSegment(segment);
    PlaneSums filled;
    for (const std::size_t i : plane.inner) claimed += claimBlock(blocks, i, pixels, holes, plane.label, fine, filled);
    fine.addToSums(plane.label, filled);
  }
  return claimed;
}

std::size_t CoarsePlanes::claimBlock(const BlockGrid& blocks, std::size_t i, const PointGrid& pixels,
                                     const HoleFilling& holes, std::int32_t label, FloodPass& fine, PlaneSums& filled) {
  // Block i's pixels to segment `label`; the points `holes` filled in added to `filled`.
  const int s = blocks.factor();
  const int block_width = blocks.means().width;
  const int bx = static_cast<int>(i % static_cast<std::size_t>(block_width));
  const int by = static_cast<int>(i / static_cast<std::size_t>(block_width));
  const int u_begin = blocks.firstColumn(bx), u_end = std::min(u_begin + s, pixels.width);
  const int v_begin = blocks.firstRow(by), v_end = std::min(v_begin + s, pixels.height);
  if (blocks.complete(i)) {
    // Every pixel measured: none is a hole, none filled in.
    for (int v = v_begin; v < v_end; ++v)
      fine.claimRun(pixelIndex(pixels, u_begin, v), static_cast<std::size_t>(u_end - u_begin), label);
    return blocks.count(i);
  }
  std::size_t claimed = 0;
  for (int v = v_begin; v < v_end; ++v) {
    for (int u = u_begin; u < u_end; ++u) {
      const std::size_t p = pixelIndex(pixels, u, v);
      if (!pixels.isFinite(p)) continue;
      fine.claim(p, label);
      if (holes.isFilled(p)) filled.add(Vec3::load(pixels.point(p)));
      ++claimed;
    }
  }
  return claimed;
}

void CoarsePlanes::noteTouchingPlanes(const BlockGrid& blocks, FloodPass& fine) const {
  // Inner blocks of two planes side by side: the two touch without a pixel of the fine pass
  // between them, which would have noted the pair for merging.
  const int block_width = blocks.means().width, block_height = blocks.means().height;
  const auto label = [&](std::int32_t k) { return planes_[static_cast<std::size_t>(k - 1)].label; };
  for (int by = 0; by < block_height; ++by) {
    for (int bx = 0; bx < block_width; ++bx) {
      const std::size_t i = blockIndex(block_width, bx, by);
      const std::int32_t k = inner_plane_[i];
      if (k == 0 || label(k) == 0) continue;
      const std::int32_t right = bx + 1 < block_width ? inner_plane_[i + 1] : 0;
      const std::int32_t below = by + 1 < block_height ? inner_plane_[i + static_cast<std::size_t>(block_width)] : 0;
      for (const std::int32_t l : {right, below})
        if (l != 0 && l != k && label(l) != 0) fine.addEdge(label(k), label(l));
    }
  }
}

void CoarsePlanes::fillPockets(const BlockGrid& blocks, const PointGrid& pixels, const Tolerances& fine_tolerances,
                               float pixel_pitch, FloodPass& fine, SegmentationStats& stats) {
  const int block_width = blocks.means().width, block_height = blocks.means().height;
  pockets_.mark.assign(inner_plane_.size(), 0);
  const std::vector<std::int32_t>& claimed_by = fine.labels();
  for (int by = 0; by < block_height; ++by) {
    for (int bx = 0; bx < block_width; ++bx) {
      const std::size_t first = blockIndex(block_width, bx, by);
      if (inner_plane_[first] != 0 || pockets_.mark[first] != 0 || blocks.count(first) == 0) continue;
      const std::int32_t around = collectPocket(blocks, first);
      if (around <= 0 || pockets_.blocks.size() > kLargestPocket ||
          planes_[static_cast<std::size_t>(around - 1)].label == 0)
        continue;
      // The plane's inner blocks around the pocket give the plane where the pocket is, and
      // their sides on the pocket start its flood.
      const PlaneSums local = sumAroundPocket(blocks, around);
      const std::int32_t label = planes_[static_cast<std::size_t>(around - 1)].label;
      addPocketStarts(blocks, pixels, label, claimed_by);
      const PlaneFit fit = local.fit();
      if (!(normalUncertainty(fit, local.count) < std::numeric_limits<double>::infinity())) continue;
      fine.extend(label, starts_, planeCriterion(fit, fine_tolerances, pixel_pitch), stats);
    }
  }
}

std::int32_t CoarsePlanes::collectPocket(const BlockGrid& blocks, std::size_t first) {
  // The blocks of one pocket (4-connected blocks with measured pixels, none inside a plane)
  // and the one plane around it, if there is one: -1 where the pocket touches the frame's
  // edge or another plane's inside. A block without a measured pixel is no way out.
  const int block_width = blocks.means().width, block_height = blocks.means().height;
  pockets_.blocks.assign(1, first);
  pockets_.mark[first] = 1;
  std::int32_t around = 0;
  for (std::size_t next = 0; next < pockets_.blocks.size(); ++next) {
    const int x = static_cast<int>(pockets_.blocks[next] % static_cast<std::size_t>(block_width));
    const int y = static_cast<int>(pockets_.blocks[next] / static_cast<std::size_t>(block_width));
    const int neighbours[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
    for (const auto& [nx, ny] : neighbours) {
      if (nx < 0 || ny < 0 || nx >= block_width || ny >= block_height) {
        around = -1;
        continue;
      }
      const std::size_t j = blockIndex(block_width, nx, ny);
      const std::int32_t k = inner_plane_[j];
      if (k != 0) {
        around = around == 0 || around == k ? k : -1;
      } else if (blocks.count(j) != 0 && pockets_.mark[j] == 0) {
        pockets_.mark[j] = 1;
        pockets_.blocks.push_back(j);
      }
    }
  }
  return around;
}

PlaneSums CoarsePlanes::sumAroundPocket(const BlockGrid& blocks, std::int32_t around) {
  // The means of plane `around`'s inner blocks among the pocket's blocks' eight neighbours,
  // each once (marked 2 while they are summed, unmarked after).
  const int block_width = blocks.means().width, block_height = blocks.means().height;
  const auto each_neighbour = [&](std::size_t i, auto&& visit) {
    const int x = static_cast<int>(i % static_cast<std::size_t>(block_width));
    const int y = static_cast<int>(i / static_cast<std::size_t>(block_width));
    for (int ny = y - 1; ny <= y + 1; ++ny)
      for (int nx = x - 1; nx <= x + 1; ++nx)
        if (nx >= 0 && ny >= 0 && nx < block_width && ny < block_height) visit(blockIndex(block_width, nx, ny));
  };
  PlaneSums local;
  for (const std::size_t i : pockets_.blocks)
    each_neighbour(i, [&](std::size_t j) {
      if (inner_plane_[j] != around || pockets_.mark[j] == 2) return;
      pockets_.mark[j] = 2;  // counted once
      blocks.addMeanTo(j, local);
    });
  for (const std::size_t i : pockets_.blocks)
    each_neighbour(i, [&](std::size_t j) {
      if (pockets_.mark[j] == 2) pockets_.mark[j] = 0;
    });
  return local;
}

void CoarsePlanes::addPocketStarts(const BlockGrid& blocks, const PointGrid& pixels, std::int32_t label,
                                   const std::vector<std::int32_t>& claimed_by) {
  // The pixels along each pocket block's edge, inside, whose neighbour outside is the plane's:
  // the fill starts from the plane's pixel next to each.
  const int s = blocks.factor();
  const int block_width = blocks.means().width;
  starts_.clear();
  const auto add = [&](int u, int v) {
    if (claimed_by[pixelIndex(pixels, u, v)] == label) starts_.push_back(pixelIndex(pixels, u, v));
  };
  for (const std::size_t i : pockets_.blocks) {
    const int x = static_cast<int>(i % static_cast<std::size_t>(block_width));
    const int y = static_cast<int>(i / static_cast<std::size_t>(block_width));
    const int u0 = blocks.firstColumn(x), v0 = blocks.firstRow(y);
    const int u1 = std::min(u0 + s, pixels.width) - 1, v1 = std::min(v0 + s, pixels.height) - 1;
    for (int v = v0; v <= v1; ++v) {
      if (u0 > 0) add(u0 - 1, v);
      if (u1 + 1 < pixels.width) add(u1 + 1, v);
    }
    for (int u = u0; u <= u1; ++u) {
      if (v0 > 0) add(u, v0 - 1);
      if (v1 + 1 < pixels.height) add(u, v1 + 1);
    }
  }
}

void CoarsePlanes::floodFromInnerEdges(const BlockGrid& blocks, const PointGrid& pixels, FloodPass& fine,
                                       SegmentationStats& stats) {
  // Each plane's inner blocks along their edge (a side whose neighbour is not inside the same
  // plane): the pixels of that side start its flood into the pixels around.
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    const std::int32_t label = planes_[k].label;
    if (label == 0) continue;
    addEdgeStarts(blocks, pixels, k, fine.labels());
    fine.extend(label, starts_, fine.segments()[static_cast<std::size_t>(label)].criterion, stats);
  }
}

void CoarsePlanes::addEdgeStarts(const BlockGrid& blocks, const PointGrid& pixels, std::size_t k,
                                 const std::vector<std::int32_t>& claimed_by) {
  const int s = blocks.factor();
  const int block_width = blocks.means().width, block_height = blocks.means().height;
  const std::int32_t own = static_cast<std::int32_t>(k + 1), label = planes_[k].label;
  const auto inside = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < block_width && y < block_height &&
           inner_plane_[blockIndex(block_width, x, y)] == own;
  };
  // A pixel of the side starts a flood where the pixel beyond it is not the plane's yet: the
  // fill looks at the pixels around its start first.
  const auto add = [&](int u, int v, int du, int dv) {
    const std::size_t p = pixelIndex(pixels, u, v);
    if (claimed_by[p] == label && claimed_by[pixelIndex(pixels, u + du, v + dv)] != label) starts_.push_back(p);
  };
  starts_.clear();
  for (const std::size_t i : planes_[k].inner) {
    const int bx = static_cast<int>(i % static_cast<std::size_t>(block_width));
    const int by = static_cast<int>(i / static_cast<std::size_t>(block_width));
    const int u0 = blocks.firstColumn(bx), v0 = blocks.firstRow(by);
    const int u1 = std::min(u0 + s, pixels.width) - 1, v1 = std::min(v0 + s, pixels.height) - 1;
    if (bx > 0 && !inside(bx - 1, by))
      for (int v = v0; v <= v1; ++v) add(u0, v, -1, 0);
    if (u1 + 1 < pixels.width && !inside(bx + 1, by))
      for (int v = v0; v <= v1; ++v) add(u1, v, 1, 0);
    if (by > 0 && !inside(bx, by - 1))
      for (int u = u0; u <= u1; ++u) add(u, v0, 0, -1);
    if (v1 + 1 < pixels.height && !inside(bx, by + 1))
      for (int u = u0; u <= u1; ++u) add(u, v1, 0, 1);
  }
}

}  // namespace floodplane
