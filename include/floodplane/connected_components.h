#pragma once

#include <cstdint>
#include <vector>

#include "floodplane/union_find.h"

namespace floodplane {

/// An inclusive pixel rectangle.
struct PixelBox {
  int x_min = 0, y_min = 0, x_max = -1, y_max = -1;

  bool empty() const { return x_max < x_min || y_max < y_min; }
  void include(int x, int y) {
    if (empty()) {
      x_min = x_max = x;
      y_min = y_max = y;
      return;
    }
    if (x < x_min) x_min = x;
    if (x > x_max) x_max = x;
    if (y < y_min) y_min = y;
    if (y > y_max) y_max = y;
  }
};

/// The relabelling after Eq. 4 (Sec. III-B): when later floods take pixels from a segment,
/// what is left of it may fall apart. This splits the pixels labelled `label` inside `box`
/// into 4-connected components with the classic two-pass union-find labelling (as PCL's
/// OrganizedConnectedComponentSegmentation, [16]). The first component in raster order keeps
/// `label`; every other one gets the next label from `next_label`, which is advanced.
/// Returns the labels of the new components (empty when the segment is still connected).
/// `scratch` and `sets` are reused across calls.
class ComponentSplitter {
 public:
  std::vector<std::int32_t> split(std::int32_t* labels, int width, const PixelBox& box,
                                  std::int32_t label, std::int32_t& next_label);

 private:
  std::vector<std::int32_t> provisional_;  // per pixel of the box: provisional set id, -1 none
  std::vector<std::int32_t> final_label_;  // per set root: the label it receives
  UnionFind sets_;
};

}  // namespace floodplane
