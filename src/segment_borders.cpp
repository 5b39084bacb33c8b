#include "segment_borders.h"

#include "distance_function.h"
#include "simd.h"

namespace floodplane {

void SegmentBorders::collect(const PointGrid& grid, const std::vector<std::int32_t>& labels,
                             const std::vector<Segment>& segments) {
  borders_.clear();
  const std::size_t width = static_cast<std::size_t>(grid.width);
  const std::size_t height = static_cast<std::size_t>(grid.height);
  // Along a border the pair repeats pixel after pixel: one lookup per change of pair (the
  // map's entries stay where they are as it grows).
  std::uint64_t last_key = 0;  // 0: none (label 0 is never part of a pair)
  SegmentBorder* last = nullptr;
  const auto touch = [&](std::int32_t a, std::size_t i, std::int32_t b, std::size_t j) {
    const Vec3 p = Vec3::load(grid.point(i));
    const Vec3 q = Vec3::load(grid.point(j));
    if (!(squaredEuclideanDistance(p, q) < segments[a].criterion.euclideanToleranceSq(noiseRangeSq(p, q)))) return;
    const std::uint64_t key = borderKey(a, b);
    if (key != last_key) {
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
    std::size_t x = 0;
#if FLOODPLANE_SIMD
    // Four pixels at a time: the lanes where a border starts to the right or below, then only
    // those (the right neighbour of the fourth must lie in this row).
    if (has_below) {
      const std::int32_t* row_labels = labels.data() + row;
      // The points two rows ahead are requested as the scan passes above them: a noisy frame
      // has borders everywhere (some 40,000 pixel pairs on a real Kinect frame).
      const bool ahead = y + 2 < height;
      for (; x + 4 < width; x += 4) {
        if (ahead) prefetchRange(grid.point(row + 2 * width + x), grid.point(row + 2 * width + x + 3) + 3);
        const int right = segmentBorderLanes(row_labels + x, row_labels + x + 1);
        const int below = segmentBorderLanes(row_labels + x, row_labels + x + width);
        // Pixel by pixel, right before below, as the scalar loop: the sums come out the same.
        for (int lanes = right | below; lanes != 0; lanes &= lanes - 1) {
          const int k = __builtin_ctz(static_cast<unsigned>(lanes));
          const std::size_t i = row + x + static_cast<std::size_t>(k);
          if (right & (1 << k)) touch(labels[i], i, labels[i + 1], i + 1);
          if (below & (1 << k)) touch(labels[i], i, labels[i + width], i + width);
        }
      }
    }
#endif
    for (; x < width; ++x) pixel(row + x, x + 1 < width, has_below);
  }
}

}  // namespace floodplane
