#include "segment_borders.h"

#include "distance_function.h"
#include "simd.h"

namespace floodplane {

void SegmentBorders::collect(const PointGrid& grid, const std::vector<std::int32_t>& labels,
                             const std::vector<Segment>& segments) {
  borders_.clear();
  const std::size_t width = static_cast<std::size_t>(grid.width);
  const std::size_t height = static_cast<std::size_t>(grid.height);
  // Along a border the pair repeats pixel after pixel: one lookup per change of pair.
  std::uint64_t last_key = 0;
  SegmentBorder* last = nullptr;
  const auto touch = [&](std::int32_t a, std::size_t i, std::int32_t b, std::size_t j) {
    const Vec3 p = Vec3::load(grid.point(i));
    const Vec3 q = Vec3::load(grid.point(j));
    if (!(squaredEuclideanDistance(p, q) < segments[a].criterion.euclideanToleranceSq(noiseRangeSq(p, q)))) return;
    const std::uint64_t key = borderKey(a, b);
    if (last == nullptr || key != last_key) {
      last = &borders_[key];
      last_key = key;
    }
    if (a < b)
      last->add(p, q);
    else
      last->add(q, p);
  };
  const auto pixel = [&](std::size_t i, bool has_right, bool has_below) {
    const std::int32_t a = labels[i];
    // Interior pixels and unlabelled areas first: one test for most of the frame.
    const std::int32_t right = has_right ? labels[i + 1] : a;
    const std::int32_t below = has_below ? labels[i + width] : a;
    if (((a ^ right) | (a ^ below)) == 0 || a == 0) return;
    if (right != 0 && right != a) touch(a, i, right, i + 1);
    if (below != 0 && below != a) touch(a, i, below, i + width);
  };
  for (std::size_t y = 0; y < height; ++y) {
    const std::size_t row = y * width;
    const bool has_below = y + 1 < height;
    // The points of the row after next, requested now: borders are everywhere in a noisy
    // frame (some 40,000 pixel pairs on a real Kinect frame), and loading their points on
    // demand waits on memory at every one; the whole frame in order costs a tenth of that.
    if (y + 2 < height) prefetchRange(grid.point(row + 2 * width), grid.point(row + 3 * width - 1) + 3);
    std::size_t x = 0;
#if FLOODPLANE_SIMD
    // Four pixels at a time where none starts a border (the right neighbour of the fourth
    // must lie in this row).
    if (has_below) {
      for (; x + 4 < width; x += 4) {
        if (sameAsRightAndBelow(labels.data() + row + x, labels.data() + row + x + width)) continue;
        for (std::size_t k = 0; k < 4; ++k) pixel(row + x + k, true, true);
      }
    }
#endif
    for (; x < width; ++x) pixel(row + x, x + 1 < width, has_below);
  }
}

}  // namespace floodplane
