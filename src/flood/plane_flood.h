// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "floodplane/params.h"
#include "floodplane/point_grid.h"
#include "models/flood_criterion.h"
#include "models/plane_sums.h"
#include "models/tolerances.h"
#include "seeds/seed_selector.h"
#include "util/distance_buffer.h"
#include "util/span_flood_fill.h"

namespace floodplane {

/// A segment grown by one flood, as the later stages need it.
struct Segment {
  PlaneSums sums;            ///< of the pixels it owns now (Eq. 4 takeovers are subtracted)
  FloodCriterion criterion;  ///< its plane and thresholds when its flood ended
  bool lost_pixels = false;  ///< a later flood took pixels from it: it may be split
};

/// A pair of segments that touch: pixel neighbours whose points are 3-D neighbours.
using SegmentEdge = std::pair<std::int32_t, std::int32_t>;

/// What the floods of one pass write to: the owner and distance of every pixel (Eq. 4), the
/// segments with their sums, and the pairs of segments that touch.
struct FloodTarget {
  DistanceBuffer& buffer;
  std::vector<Segment>& segments;
  std::vector<SegmentEdge>& edges;
};

/// Grows one segment from a seed (Sec. III-A, III-B): the span flood fill with the distance
/// function of Eqs. 1-3 and the distance buffer of Eq. 4, collecting the neighbour graph on
/// the way (Sec. III-D: a flood that stops at a pixel of another segment whose point is a
/// Euclidean neighbour records the pair).
///
/// Beyond the paper, the flood's plane is refit to the pixels it has collected (least
/// squares from running sums) when their count doubles, starting at rho^2 pixels, i.e. once
/// the segment is as wide as the seed cube. The seed normal from cross products is the best
/// estimate a seed has, but on a Kinect at 2 m it is off by several degrees, which stops a
/// flood with a fixed seed plane long before the plane ends. When the fill runs dry, the
/// pixels it rejected for their plane distance are tested again against the refit plane
/// and the fill resumes from those that now join (at most kFrontierRounds times).
class PlaneFlood {
 public:
  static constexpr int kFrontierRounds = 4;

  /// Forgets the neighbour marks of the previous frame.
  void beginFrame() { neighbour_mark_.clear(); }

  /// Floods segment `label` (already present in the target's segments) from `seed`.
  /// Appends the segment's neighbour pairs to the target's edges; returns the pixels it took
  /// from other segments under Eq. 4.
  std::size_t grow(const PointGrid& grid, const Seed& seed, std::int32_t label, const Params& params,
                   const Tolerances& tolerances, FloodTarget target);

  /// Continues segment `label`, whose pixels `starts` are claimed already (a coarse plane's
  /// inner blocks along their edge), into the pixels around them, with the tests of grow()
  /// under `criterion` (the plane where the starts are: a big plane bends). The plane is not
  /// refit: it is that of many pixels. Returns the pixels it took from other segments under
  /// Eq. 4.
  std::size_t extend(const PointGrid& grid, const std::vector<std::size_t>& starts, std::int32_t label,
                     const FloodCriterion& criterion, const Params& params, FloodTarget target);

 private:
  std::vector<Shadow> shadows_;
  std::vector<std::pair<std::size_t, std::size_t>> frontier_;  // (from, to) rejected by Eq. 2
  std::vector<std::pair<std::size_t, std::size_t>> retest_;
  std::vector<std::int32_t> neighbour_mark_;  // per segment: the last flood that recorded it
};

}  // namespace floodplane
