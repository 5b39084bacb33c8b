// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "flood/flood_pass.h"

#include <algorithm>
#include <chrono>

namespace floodplane {

namespace {

// Seed candidates are every kSeedStride-th pixel of every kSeedStride-th row of the frame,
// not every pixel as in the paper: a plane worth reporting is many strides wide, and this
// cuts the cost of testing the pixels no flood claims (clutter, curved surfaces, borders)
// sixteen-fold (as DDPFF's sparse seed grid). A grid of blocks uses a proportionally smaller
// stride.
constexpr int kSeedStride = 4;

// Beyond the paper: a second, finer seeding pass over the pixels the first one left
// unclaimed, with a seed cube of sigma_seed / kFineSeedDivisor. sigma_seed = 6 cm keeps
// seeds off edges and out of noise, but it also means no plane narrower than about 6 cm can
// ever be seeded: table legs, shelf fronts, stair risers seen from above. After the first
// pass every large plane is already claimed, so the small seeds only see what is left;
// the noise-widened seed size (SeedSelector::seedSizeAt) still keeps them out of noise.
constexpr double kFineSeedDivisor = 2.0;
// On noise-free frames nothing fakes a small plane, and the second pass seeds with a third of
// the cube: a 3 cm edge 1.5 m from a Kinect-like camera is five pixels high.
constexpr double kNoiseFreeFineSeedDivisor = 3.0;

using Clock = std::chrono::steady_clock;
double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

void FloodPass::begin(const FloodGrid& grid, const Params& params) {
  grid_ = &grid;
  params_ = params;
  const PointGrid& points = grid.points;
  selector_.configure(params, grid.tolerances, 1.0, grid.pitch, points.width, points.height);
  fine_selector_.configure(params, grid.tolerances,
                           1.0 / (grid.noise_free ? kNoiseFreeFineSeedDivisor : kFineSeedDivisor), grid.pitch,
                           points.width, points.height);
  buffer_.reset(points.size());
  segments_.assign(1, Segment());  // label 0: no segment
  edges_.clear();
  flood_.beginFrame();
}

std::int32_t FloodPass::addSegment(const Segment& segment) {
  segments_.push_back(segment);
  return static_cast<std::int32_t>(segments_.size() - 1);
}

void FloodPass::extend(std::int32_t label, const std::vector<std::size_t>& starts, const FloodCriterion& criterion,
                       SegmentationStats& stats) {
  stats.pixels_taken_over +=
      flood_.extend(grid_->points, starts, label, criterion, params_, {buffer_, segments_, edges_});
}

void FloodPass::seedAndFlood(bool timed, SegmentationStats& stats, PhaseTimes& phases) {
  const Clock::time_point scan_start = timed ? Clock::now() : Clock::time_point();
  double flooding = 0.0;
  const PointGrid& grid = grid_->points;
  const Tolerances& tolerances = grid_->tolerances;
  const int stride = std::max(1, kSeedStride / grid_->factor);
  const int offset = stride / 2;
  // A new segment flooded from an accepted seed.
  const auto floodFrom = [&](const Seed& accepted) {
    ++stats.seeds;
    const std::int32_t label = static_cast<std::int32_t>(segments_.size());
    segments_.emplace_back();
    const Clock::time_point flood_start = timed ? Clock::now() : Clock::time_point();
    stats.pixels_taken_over += flood_.grow(grid, accepted, label, params_, tolerances, {buffer_, segments_, edges_});
    if (timed) flooding += millisecondsSince(flood_start);
  };
  Seed seed;
  for (const SeedSelector* seeds : {&selector_, &fine_selector_}) {
    for (int y = offset; y < grid.height; y += stride) {
      for (int x = offset; x < grid.width; x += stride) {
        const std::size_t pixel =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(grid.width) + static_cast<std::size_t>(x);
        if (buffer_.label(pixel) != 0) continue;
        ++stats.seed_candidates;
        if (seeds->test(grid, x, y, seed) == SeedVerdict::kAccepted) floodFrom(seed);
      }
    }
  }
  // Regions of unclaimed points large enough to be a plane: faces narrower than any seed
  // cross (LeftoverSeeds).
  const std::size_t min_pixels = tolerances.minInliers() / static_cast<std::size_t>(grid_->factor * grid_->factor);
  for (const Seed& leftover_seed : leftover_.find(grid, buffer_, tolerances, min_pixels)) {
    if (buffer_.label(leftover_seed.index) == 0) floodFrom(leftover_seed);  // else an earlier one's flood took it
  }
  if (timed) {
    phases.flood_fill += flooding;
    phases.seed_selection += millisecondsSince(scan_start) - flooding;
  }
}

void FloodPass::relabel() { relabelling_.run(grid_->points, grid_->factor, buffer_.labels(), segments_, edges_); }

MergedSegments FloodPass::merge(const MergeCriterion& criterion) {
  const std::vector<std::int32_t>& labels = buffer_.labels();
  borders_.collect(grid_->points, labels, segments_);
  merger_.reset(segments_.size());
  for (const SegmentEdge& edge : edges_) merger_.addEdge(edge.first, edge.second);
  cluster_sums_.resize(segments_.size());
  for (std::size_t i = 0; i < segments_.size(); ++i) cluster_sums_[i] = segments_[i].sums;
  merger_.merge(cluster_sums_, criterion, borders_.mutableBorders());
  MergedSegments clusters;
  clusters.labels = labels.data();
  clusters.root = merger_.rootData();
  clusters.sums = cluster_sums_.data();
  clusters.segment_count = segments_.size();
  return clusters;
}

}  // namespace floodplane
