#include "relabelling.h"

#include <algorithm>

#include "simd.h"

namespace floodplane {

void Relabelling::run(const PointGrid& grid, int subsampling, std::vector<std::int32_t>& labels,
                      std::vector<Segment>& segments) {
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
      segments[run.set].sums.merge(moved);
    }
  }
}

}  // namespace floodplane
