// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "regions/refinement.h"

#include <limits>

#include "util/row_search.h"
#include "util/simd.h"

namespace floodplane {

namespace {

class Refiner {
 public:
  Refiner(const PointGrid& full, const HoleFilling& holes, PlaneCandidates& planes, std::vector<std::size_t>& queue)
      : full_(full), holes_(holes), planes_(planes), queue_(queue), width_(full.width), height_(full.height) {}

  // Seeds of the growth: unlabelled pixels next to a plane they fit, the best plane first.
  // The image is written in the planes' current numbers on the way, if they changed since it
  // was written: one pass over it.
  void seedAlongPlaneBorders() {
    queue_.clear();
    planes_.forEachWritableRow([&](std::uint32_t* labels, int y) {
      labels_ = labels;
      // The unlabelled pixels are scattered along a row, too far apart for the hardware to
      // see a stream: the next row's points are requested while this one is worked on.
      if (y + 1 < height_) {
        const std::size_t next = static_cast<std::size_t>(y + 1) * static_cast<std::size_t>(width_);
        prefetchRange(full_.point(next), full_.point(next + static_cast<std::size_t>(width_) - 1) + 3);
      }
      const std::uint32_t* row = labels_ + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
      const std::uint32_t* above = y > 0 ? row - width_ : row;
      const std::uint32_t* below = y + 1 < height_ ? row + width_ : row;
      // Only an unlabelled pixel next to a labelled one can be a seed. The search starts
      // again after each: a seed labels its pixel, the left neighbour of the next.
      for (int x = findUnlabelledNextToLabelled(row, above, below, 0, width_); x < width_;
           x = findUnlabelledNextToLabelled(row, above, below, x + 1, width_)) {
        seedPixel(x, y);
      }
    });
  }

  // Breadth-first growth from the seeds.
  void grow() {
    labels_ = planes_.writableImage();
    const std::size_t width = static_cast<std::size_t>(width_);
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const std::size_t i = queue_[head];
      const std::uint32_t k = labels_[i];
      const int x = static_cast<int>(i % width);
      const int y = static_cast<int>(i / width);
      float distance = 0.f;
      if (x > 0 && labels_[i - 1] == 0 && fits(k, i, i - 1, distance)) take(k, i - 1);
      if (x + 1 < width_ && labels_[i + 1] == 0 && fits(k, i, i + 1, distance)) take(k, i + 1);
      if (y > 0 && labels_[i - width] == 0 && fits(k, i, i - width, distance)) take(k, i - width);
      if (y + 1 < height_ && labels_[i + width] == 0 && fits(k, i, i + width, distance)) take(k, i + width);
    }
  }

 private:
  // The unlabelled pixel (x, y), which has a labelled neighbour, joins the neighbouring plane
  // it fits best, if any.
  void seedPixel(int x, int y) {
    const std::size_t width = static_cast<std::size_t>(width_);
    const std::size_t i = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
    const std::size_t neighbours[4] = {x > 0 ? i - 1 : i, x + 1 < width_ ? i + 1 : i, y > 0 ? i - width : i,
                                       y + 1 < height_ ? i + width : i};
    std::uint32_t best = 0;
    float best_distance = std::numeric_limits<float>::infinity();
    for (const std::size_t j : neighbours) {
      const std::uint32_t k = labels_[j];
      float distance = 0.f;
      if (k != 0 && k != best && fits(k, j, i, distance) && distance < best_distance) {
        best = k;
        best_distance = distance;
      }
    }
    if (best != 0) take(best, i);
  }

  // Does pixel `to`, next to `from`, join plane k (Eqs. 1-3 with the plane's thresholds)?
  bool fits(std::uint32_t k, std::size_t from, std::size_t to, float& distance) const {
    return !holes_.isFilled(to) &&
           planes_[k].criterion.accepts(Vec3::load(full_.point(from)), Vec3::load(full_.point(to)), distance);
  }

  void take(std::uint32_t k, std::size_t pixel) {
    labels_[pixel] = k;
    PlaneCandidate& plane = planes_[k];
    plane.sums.add(Vec3::load(full_.point(pixel)));
    if (pixel < plane.first_pixel) plane.first_pixel = pixel;
    queue_.push_back(pixel);
  }

  const PointGrid& full_;
  const HoleFilling& holes_;
  std::uint32_t* labels_ = nullptr;  // the planes' image, writable
  PlaneCandidates& planes_;
  std::vector<std::size_t>& queue_;
  const int width_;
  const int height_;
};

}  // namespace

void refinePlanes(const PointGrid& full, const HoleFilling& holes, PlaneCandidates& planes,
                  std::vector<std::size_t>& queue) {
  if (planes.list().empty()) return;
  Refiner refiner(full, holes, planes, queue);
  refiner.seedAlongPlaneBorders();
  refiner.grow();
}

}  // namespace floodplane
