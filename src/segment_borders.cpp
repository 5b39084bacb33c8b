#include "segment_borders.h"

#include "distance_function.h"

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
  for (std::size_t y = 0; y < height; ++y) {
    const std::size_t row = y * width;
    for (std::size_t x = 0; x < width; ++x) {
      const std::size_t i = row + x;
      const std::int32_t a = labels[i];
      if (a == 0) continue;
      if (x + 1 < width) {
        const std::int32_t b = labels[i + 1];
        if (b != 0 && b != a) touch(a, i, b, i + 1);
      }
      if (y + 1 < height) {
        const std::int32_t b = labels[i + width];
        if (b != 0 && b != a) touch(a, i, b, i + width);
      }
    }
  }
}

}  // namespace floodplane
