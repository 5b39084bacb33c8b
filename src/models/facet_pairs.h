// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "floodplane/plane_fit.h"
#include "floodplane/point_grid.h"
#include "models/plane_candidates.h"

namespace floodplane {

/// Beyond the paper: the facets of one curved surface, judged together. A strip of a cylinder
/// or a ball narrow enough to stay within the noise band of its own plane passes the planarity
/// test (planarity_test.h) alone: its bend, the sagitta w^2 / 8R over its width w, is below the
/// noise. The flood then cuts the surface into a chain of such strips, each tilted against the
/// next by w / R. Two touching planes are judged as one surface: over the pair the bend is four
/// times as deep, and a smooth quadratic fits it better than the two planes do, where at a
/// crease (two real planes meeting: a box's faces, a ramp on the floor) the two planes fit
/// better than any quadratic (PlanarityTest::curvedPair).
///
/// This class finds the candidate pairs: planes that touch along at least kMinimumBorder pairs
/// of 4-neighbouring pixels whose points are 3-D neighbours (Eq. 3 under the first plane's
/// criterion: a facet in front of a wall only touches it in the image), and whose normals are
/// at most kMaximumAngle apart (a facet that turns further than that from its neighbour is not
/// within one noise band of its own plane: that is a crease).
/// A label image whose numbers are the planes' (as FacetPairs reads the coarse pass's
/// candidates); the planes' own image is read through CurrentLabels.
struct PlainLabels {
  const std::uint32_t* image = nullptr;
  std::uint32_t operator[](std::size_t i) const { return image[i]; }
};

class FacetPairs {
 public:
  static constexpr double kMaximumAngle = 1.0;  // rad (about 57 degrees)
  static constexpr std::uint32_t kMinimumBorder = 16;

  /// The pairs (k, l), k < l, of planes 1..fits.size() (fits[k - 1] and planes[k - 1] are
  /// plane k) in `labels` of the points `grid`, both planes `eligible` (indexed by plane
  /// number: those with a sample large enough to judge that are not dropped already).
  /// `Labels` is PlainLabels or CurrentLabels: labels[i] is pixel i's plane, and labels.image
  /// the image whose borders are scanned.
  template <class Labels>
  void find(const PointGrid& grid, const Labels& labels, const std::vector<PlaneCandidate>& planes,
            const std::vector<PlaneFit>& fits, const std::vector<bool>& eligible);
  const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs() const { return pairs_; }
  /// Calls visit(i, j) for each pair of 4-neighbouring pixels along pairs()[pair]'s border
  /// (i on its first plane, j on its second), 3-D neighbours or not (a step shows there), in
  /// the scan's order.
  template <class Visit>
  void forEachPixelPair(std::size_t pair, Visit&& visit) const {
    for (std::size_t r = pair_runs_[pair].first; r < pair_runs_[pair].second; ++r)
      for (std::uint32_t p = runs_[r].first; p < runs_[r].first + runs_[r].count; ++p)
        visit(static_cast<std::size_t>(pixel_pairs_[p].first), static_cast<std::size_t>(pixel_pairs_[p].second));
  }

 private:
  struct Touch {
    std::uint64_t key;    // low << 32 | high
    std::uint32_t count;  // neighbouring pixel pairs
  };
  struct Run {
    std::uint64_t key;    // as Touch
    std::uint32_t first;  // its first pixel pair in pixel_pairs_
    std::uint32_t count;  // its pixel pairs, 3-D neighbours or not
  };
  // The pairs whose borders have at least kMinimumBorder 3-D neighbours, with their runs.
  void keepLongBorders();

  std::vector<Touch> touching_;  // per stretch of one border in the scan, 3-D neighbours
  std::vector<Run> runs_;        // per stretch of one border in the scan
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pixel_pairs_;  // (low plane's pixel, high one's)
  std::vector<std::pair<std::size_t, std::size_t>> pair_runs_;        // per pair: its range of runs_
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
  std::vector<std::uint8_t> candidate_;  // per plane: in a pair of planes that may be facets
};

}  // namespace floodplane
