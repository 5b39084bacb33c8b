// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "flood/relabelling.h"

#include <algorithm>

#include "models/lane_sums.h"
#include "util/simd.h"

namespace floodplane {

void Relabelling::run(const PointGrid& grid, int subsampling, std::vector<std::int32_t>& labels,
                      std::vector<Segment>& segments, std::vector<SegmentEdge>& edges) {
  // Crumbs below 16 full-resolution pixels' worth of samples are released (see
  // ComponentSplitter); at least one sample, so nothing is released at s >= 4.
  const std::size_t smallest_piece = static_cast<std::size_t>(std::max(1, 16 / (subsampling * subsampling)));
  const std::size_t width = static_cast<std::size_t>(grid.width);
  const std::int32_t before = static_cast<std::int32_t>(segments.size());
  std::int32_t next_label = before;
  // The segments to split, and their runs in one pass over the labels. A split only rewrites
  // its own segment's pixels, so the runs of the segments after it stay as found.
  const auto lost_pixels = [&](std::int32_t s) { return segments[s].lost_pixels && segments[s].sums.count > 0.0; };
  to_split_.assign(static_cast<std::size_t>(before), false);
  for (std::int32_t s = 1; s < before; ++s) to_split_[static_cast<std::size_t>(s)] = lost_pixels(s);
  runs_.collect(labels.data(), grid.width, grid.height, to_split_);
  for (std::int32_t s = 1; s < before; ++s) {
    if (!to_split_[static_cast<std::size_t>(s)]) continue;
    const std::int32_t first_new = next_label;
    const std::vector<std::int32_t> created =
        splitter_.split(labels.data(), grid.width, runs_.runs(s), runs_.count(s), s, next_label, smallest_piece);
    if (created.empty() && splitter_.releasedPixels() == 0) continue;
    const FloodCriterion criterion = segments[s].criterion;
    segments.resize(static_cast<std::size_t>(next_label));
    for (std::int32_t label = first_new; label < next_label; ++label) {
      segments[label] = Segment();
      segments[label].criterion = criterion;
    }
    for (const ComponentSplitter::Run& run : splitter_.runs()) {
      if (run.set == s) continue;
      PlaneSums moved;
      addRunToSums(moved, grid, static_cast<std::size_t>(run.y) * width + static_cast<std::size_t>(run.x_begin),
                   static_cast<std::size_t>(run.x_end - run.x_begin + 1));
      segments[s].sums.subtract(moved);
      if (run.set == 0) continue;  // released
      Segment& piece = segments[run.set];
      piece.sums.merge(moved);
      addPieceEdges(grid, labels, piece.criterion, run, edges);
    }
  }
}

void Relabelling::addPieceEdges(const PointGrid& grid, const std::vector<std::int32_t>& labels,
                                const FloodCriterion& criterion, const ComponentSplitter::Run& run,
                                std::vector<SegmentEdge>& edges) const {
  std::int32_t last_other = 0;
  const auto consider = [&](std::size_t i, std::size_t j) {
    const std::int32_t other = labels[j];
    // Along a run the neighbour is mostly the same segment pixel after pixel: one edge.
    if (other == 0 || other == run.set || other == last_other) return;
    const Vec3 p = Vec3::load(grid.point(i));
    if (squaredEuclideanDistance(p, Vec3::load(grid.point(j))) < criterion.euclideanToleranceSq(p.squaredNorm())) {
      edges.emplace_back(run.set, other);
      last_other = other;
    }
  };
  const std::size_t row = static_cast<std::size_t>(run.y) * static_cast<std::size_t>(grid.width);
  // Inside the run the left and right neighbours are the run itself: only its ends count.
  if (run.x_begin > 0) consider(row + run.x_begin, row + run.x_begin - 1);
  if (run.x_end + 1 < grid.width) consider(row + run.x_end, row + run.x_end + 1);
  for (const int dy : {-1, 1}) {
    if (run.y + dy < 0 || run.y + dy >= grid.height) continue;
    const std::ptrdiff_t offset = dy * static_cast<std::ptrdiff_t>(grid.width);
    for (int x = run.x_begin; x <= run.x_end; ++x) {
      const std::size_t i = row + static_cast<std::size_t>(x);
      consider(i, static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + offset));
    }
  }
}

}  // namespace floodplane
