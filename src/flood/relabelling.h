// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <vector>

#include "flood/component_splitter.h"
#include "flood/plane_flood.h"
#include "floodplane/point_grid.h"

namespace floodplane {

/// Sec. III-B, after the floods: the relabelling of segments that Eq. 4 takeovers cut apart.
/// Every segment that lost pixels is split into its 4-connected pieces (ComponentSplitter);
/// each new piece becomes a segment of its own, with the plane sums of its pixels and the
/// flood criterion of the segment it came from. Only the pixels that leave a segment are
/// visited after the split: the piece that keeps the label keeps its running sums minus what
/// left, and its neighbour edges (an edge it inherits from a piece that split off joins it to a
/// segment it touched through that piece, across the band the takeover cut, which the merge
/// test still judges on the planes). New pieces get the neighbour edges they have in the
/// label image: pixel neighbours with another label whose points are 3-D neighbours (Eq. 3).
class Relabelling {
 public:
  void run(const PointGrid& grid, int subsampling, std::vector<std::int32_t>& labels, std::vector<Segment>& segments,
           std::vector<SegmentEdge>& edges);

 private:
  // The neighbour edges of a run of a new piece.
  void addPieceEdges(const PointGrid& grid, const std::vector<std::int32_t>& labels, const FloodCriterion& criterion,
                     const ComponentSplitter::Run& run, std::vector<SegmentEdge>& edges) const;

  ComponentSplitter splitter_;
  RunsByLabel runs_;
  std::vector<bool> to_split_;  // per segment: it lost pixels
};

}  // namespace floodplane
