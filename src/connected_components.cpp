#include "floodplane/connected_components.h"

#include <cstddef>

namespace floodplane {

std::vector<std::int32_t> ComponentSplitter::split(std::int32_t* labels, int width, const PixelBox& box,
                                                   std::int32_t label, std::int32_t& next_label) {
  std::vector<std::int32_t> created;
  if (box.empty()) return created;
  const int box_width = box.x_max - box.x_min + 1;
  const int box_height = box.y_max - box.y_min + 1;
  provisional_.assign(static_cast<std::size_t>(box_width) * static_cast<std::size_t>(box_height), -1);
  sets_.reset(0);

  // Pass 1: give each pixel the set of its left or upper neighbour, uniting the two when
  // both carry the label.
  for (int by = 0; by < box_height; ++by) {
    const std::int32_t* row = labels + static_cast<std::size_t>(box.y_min + by) * width + box.x_min;
    std::int32_t* sets_row = provisional_.data() + static_cast<std::size_t>(by) * box_width;
    const std::int32_t* sets_above = by > 0 ? sets_row - box_width : nullptr;
    for (int bx = 0; bx < box_width; ++bx) {
      if (row[bx] != label) continue;
      const std::int32_t left = bx > 0 ? sets_row[bx - 1] : -1;
      const std::int32_t up = sets_above ? sets_above[bx] : -1;
      if (left >= 0 && up >= 0) {
        sets_row[bx] = left;
        if (left != up) sets_.unite(left, up);
      } else if (left >= 0) {
        sets_row[bx] = left;
      } else if (up >= 0) {
        sets_row[bx] = up;
      } else {
        sets_row[bx] = sets_.add();
      }
    }
  }

  // Pass 2: one label per root, in raster order of first appearance.
  final_label_.assign(sets_.size(), -1);
  bool first = true;
  for (int by = 0; by < box_height; ++by) {
    std::int32_t* row = labels + static_cast<std::size_t>(box.y_min + by) * width + box.x_min;
    const std::int32_t* sets_row = provisional_.data() + static_cast<std::size_t>(by) * box_width;
    for (int bx = 0; bx < box_width; ++bx) {
      if (sets_row[bx] < 0) continue;
      const std::int32_t root = sets_.find(sets_row[bx]);
      if (final_label_[root] < 0) {
        if (first) {
          final_label_[root] = label;
          first = false;
        } else {
          final_label_[root] = next_label++;
          created.push_back(final_label_[root]);
        }
      }
      row[bx] = final_label_[root];
    }
  }
  return created;
}

}  // namespace floodplane
