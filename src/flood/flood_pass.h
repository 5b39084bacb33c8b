// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "flood/plane_flood.h"
#include "flood/plane_merger.h"
#include "flood/relabelling.h"
#include "flood/segment_borders.h"
#include "floodplane/params.h"
#include "floodplane/point_grid.h"
#include "floodplane/segmentation_stats.h"
#include "frame/flood_grid.h"
#include "models/tolerances.h"
#include "seeds/leftover_seeds.h"
#include "seeds/seed_selector.h"
#include "util/distance_buffer.h"

namespace floodplane {

/// The segments after merging, on the grid a flood pass segmented.
struct MergedSegments {
  const std::int32_t* labels = nullptr;  ///< per point of the grid: segment, 0 none
  const std::int32_t* root = nullptr;    ///< per segment: the segment it merged into
  const PlaneSums* sums = nullptr;       ///< per root segment: the sums of its whole cluster
  std::size_t segment_count = 0;         ///< labels are < segment_count
};

/// Segments one grid up to merged clusters: seed selection (Sec. III-C) interleaved with
/// flooding (Sec. III-A, III-B) in scan order, the relabelling of what Eq. 4 takeovers cut
/// apart, and agglomerative merging (Sec. III-D). The coarse pass runs it on the frame's block
/// means, the fine pass on its pixels, where the coarse planes' inner blocks are claimed before
/// the first seed (claim()).
class FloodPass {
 public:
  /// Starts a pass over `grid` (kept by reference until the pass ends): no segment, no
  /// pixel claimed.
  void begin(const FloodGrid& grid, const Params& params);
  /// A segment whose pixels are known before any flood (claimed with claim()): returns its label.
  std::int32_t addSegment(const Segment& segment);
  /// Gives `pixel` to segment `label` for good: no flood takes it over (Eq. 4 with D = 0).
  void claim(std::size_t pixel, std::int32_t label) { buffer_.claim(pixel, label, 0.0f); }
  /// claim() for the n pixels from `first` on.
  void claimRun(std::size_t first, std::size_t n, std::int32_t label) { buffer_.claimRun(first, n, label, 0.0f); }
  /// Floods on from the claimed pixels `starts` of segment `label` under `criterion`
  /// (PlaneFlood::extend).
  void extend(std::int32_t label, const std::vector<std::size_t>& starts, const FloodCriterion& criterion,
              SegmentationStats& stats);
  /// Notes that segments a and b touch (the merge tests them).
  void addEdge(std::int32_t a, std::int32_t b) { edges_.emplace_back(a, b); }
  /// Adds `sums` to those of segment `label`.
  void addToSums(std::int32_t label, const PlaneSums& sums) {
    segments_[static_cast<std::size_t>(label)].sums.merge(sums);
  }
  /// Seeds and floods every unclaimed point, in scan order; counts seeds, candidates and
  /// takeovers in `stats`, and the time of the floods and of the seeds into `phases` when
  /// `timed`.
  void seedAndFlood(bool timed, SegmentationStats& stats, PhaseTimes& phases);
  /// Sec. III-B, after the floods: segments that takeovers cut apart become one per piece.
  void relabel();
  /// Sec. III-D over the segment graph, and across the borders where a bent surface was cut:
  /// the clusters of segments, each with its whole sums (valid until the next begin()).
  MergedSegments merge(const MergeCriterion& criterion);

  const std::vector<std::int32_t>& labels() const { return buffer_.labels(); }
  const std::vector<Segment>& segments() const { return segments_; }
  std::size_t mergeCount() const { return merger_.mergeCount(); }

 private:
  const FloodGrid* grid_ = nullptr;
  Params params_;
  DistanceBuffer buffer_;
  SeedSelector selector_;
  SeedSelector fine_selector_;  // the second pass's smaller seed cube
  LeftoverSeeds leftover_;      // the third pass's: regions no seed reached
  PlaneFlood flood_;
  std::vector<Segment> segments_;
  std::vector<SegmentEdge> edges_;
  Relabelling relabelling_;
  SegmentBorders borders_;
  PlaneMerger merger_;
  std::vector<PlaneSums> cluster_sums_;
};

}  // namespace floodplane
