// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "floodplane/point_grid.h"
#include "models/flood_criterion.h"
#include "stages/block_grid.h"
#include "stages/plane_candidates.h"

namespace floodplane {

/// Coarse to fine, the one full-resolution write (sub-sampling s > 1): the planes found on the
/// block grid become labels of the frame's pixels, with their exact sums and first pixels.
///
/// A block whose eight neighbours all carry its plane lies inside that plane: its pixels take
/// the plane with no test of their own, and its sums are the block's (BlockGrid::addTo). The
/// block's own test stands for them: its mean joined the plane's flood (Eqs. 1-3), and its
/// points lie within the plane's noise band on average (their mean squared distance, from the
/// block's scatter); a block that fails the second (an object of a pixel or two in front of a
/// wall) is decided pixel by pixel like a border block. Only the pixels of blocks next to
/// another plane or to no plane are decided one by one: each takes, among the planes of its
/// block and the eight around, the one that explains it with the smallest depth error within
/// that plane's noise band (Eq. 2 at the pixel's own noise), else none. Blocks with no plane
/// around are written as no plane without a test.
///
/// Rows are written in raster order. A plane's first pixel, where its boundary starts, is on its
/// body (a block inside it), at the left end of that pixel row, so that a pixel of clutter that
/// fits the plane apart from it does not become the plane's boundary.
class FullResolutionWrite {
 public:
  /// Writes `labels` (frame size) from the block labels `block_labels` (the planes' current
  /// numbers, 0 none) of `blocks`, read from `frame`; each plane's `criteria[k - 1]` is its
  /// test at full resolution. The planes' sums and first pixels are set anew.
  /// `centroids[k - 1]` is a point of plane k's inside (where two planes meet, which side each
  /// is on tells which the rays see: see prefers()).
  void write(const PointGrid& frame, const BlockGrid& blocks, const RenumberedLabels& block_labels,
             const std::vector<FloodCriterion>& criteria, const std::vector<Vec3>& centroids, PlaneCandidates& planes,
             std::vector<std::uint32_t>& labels);

 private:
  // How a block's pixels are decided.
  enum class Kind : std::uint8_t { kNone, kInside, kBorder };
  struct Block {
    Kind kind;
    std::uint8_t candidate_count;
    std::uint32_t plane;                      // kInside: its plane
    std::array<std::uint32_t, 9> candidates;  // kBorder: the planes around, distinct
  };
  // Classifies the blocks of block row `by` into blocks_.
  void classifyRow(const BlockGrid& blocks, const RenumberedLabels& block_labels,
                   const std::vector<FloodCriterion>& criteria, int by);
  // Decides the pixels [u_begin, u_end) of full-resolution row `row_start` against a border
  // block's candidates.
  void decidePixels(const PointGrid& frame, std::size_t row_start, int u_begin, int u_end, const Block& block,
                    const std::vector<FloodCriterion>& criteria, const std::vector<Vec3>& centroids,
                    PlaneCandidates& planes, std::uint32_t* out_row) const;
  // decidePixels for a block with plane k alone around it.
  void decideForOnePlane(const PointGrid& frame, std::size_t row_start, int u_begin, int u_end, std::uint32_t k,
                         const std::vector<FloodCriterion>& criteria, PlaneCandidates& planes,
                         std::uint32_t* out_row) const;
  // Whether a pixel that fits planes a and b (its ray meets them at depth_a and depth_b, in
  // units of its range; it lies distance_a and distance_b from them along the ray) is a's.
  static bool prefers(std::uint32_t a, float depth_a, float distance_a, std::uint32_t b, float depth_b,
                      float distance_b, const std::vector<FloodCriterion>& criteria,
                      const std::vector<Vec3>& centroids);

  static constexpr std::uint32_t kEmpty = 0xffffffffu;  // classifyRow: a block with no measured pixel
  std::vector<Block> blocks_;                           // one block row
  std::vector<std::uint32_t> above_, row_, below_;      // classifyRow's block labels, one row each
  std::vector<std::size_t> body_start_;                 // per plane: the first pixel of its first inner block
};

}  // namespace floodplane
