#pragma once

#include <cstdint>
#include <vector>

#include "connected_components.h"
#include "floodplane/point_grid.h"
#include "plane_flood.h"

namespace floodplane {

/// Sec. III-B, after the floods: the relabelling of segments that Eq. 4 takeovers cut apart.
/// Every segment that lost pixels is split into its 4-connected pieces (ComponentSplitter);
/// each new piece becomes a segment of its own, with the plane sums of its pixels and the
/// flood criterion of the segment it came from. Only the pixels that leave a segment are
/// visited after the split: the piece that keeps the label keeps its running sums minus what
/// left. Which segments touch is read from the relabelled image afterwards (SegmentBorders).
class Relabelling {
 public:
  void run(const PointGrid& grid, int subsampling, std::vector<std::int32_t>& labels, std::vector<Segment>& segments);

 private:
  ComponentSplitter splitter_;
  RunsByLabel runs_;
  std::vector<bool> to_split_;  // per segment: it lost pixels
};

}  // namespace floodplane
