// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "floodplane/noise_model.h"
#include "floodplane/point_grid.h"
#include "models/plane_sums.h"
#include "util/vec3.h"

namespace floodplane {

/// Coarse to fine, the one full-resolution read (sub-sampling s > 1): the frame as a grid of
/// s x s blocks, each with what every later stage needs of its pixels.
/// - Its mean point, the average of its measured (finite) points: the point the seeds and
///   floods see. Averaging s^2 points is the smoothing of the sub-sampled frame (Table III's
///   every s-th pixel would throw the other s^2 - 1 away), and it bridges the pixel-sized
///   holes of a scanner's dropped returns: a block is a hole only where all its pixels are.
/// - How many of its pixels were measured, and their exact plane sums (count, sum P, sum P P^T,
///   the last held as the scatter about the block's mean, which float keeps exact to its
///   precision): a plane's sums are those of its blocks, added up, and a block's test against
///   a plane costs O(1) (meanSquaredDistance).
/// - Where a block straddles two surfaces (an edge, a board in front of a wall, a face a few
///   pixels wide), its mean would be a point of neither. separateSurfaces() keeps, in such a
///   block, only the pixels on the surface of its first measured pixel (those connected to it
///   through steps that one surface can make between neighbouring pixels): the block then
///   samples that surface, as every s-th pixel would (Table III), less noisily. Such a block is `split`: the pixels it
///   left out belong to another surface, so the full-resolution write decides its pixels one by one.
/// The right and bottom blocks are smaller where s does not divide the frame.
///
/// The frame is read once, block by block: a block's pixels are summed, then read again for
/// their scatter about the mean while they are in the cache. Blocks without a hole are summed
/// four floats (a PCL point) at a time without a test per pixel; a block with a hole is summed
/// again pixel by pixel.
class BlockGrid {
 public:
  /// Reads `full` into blocks of `factor` x `factor` pixels (factor >= 1). The means grid and
  /// everything else stay valid until the next call.
  void read(const PointGrid& full, int factor);
  /// Keeps, in every block whose depths spread more than two neighbouring pixels of one surface
  /// can differ (a steep surface's slope over one pixel footprint, `angular_pitch` times the
  /// range, plus the noise `pixel_noise` of two pixels), the pixels connected to its first
  /// measured pixel through such steps (see above).
  void separateSurfaces(const PointGrid& full, const NoiseModel& pixel_noise, float angular_pitch);

  int factor() const { return factor_; }
  /// The blocks' mean points, four floats a block (x y z 0), NaN where a block has no
  /// measured point: the grid the seeds and floods segment.
  const PointGrid& means() const { return means_; }
  /// The number of measured pixels of block i.
  std::uint32_t count(std::size_t i) const { return counts_[i]; }
  /// Whether every pixel of block i was measured and is in its sums (the block is not split).
  bool complete(std::size_t i) const { return counts_[i] == area(i); }
  /// Whether block i keeps only the pixels of one of the surfaces it straddles.
  bool split(std::size_t i) const { return split_[i] != 0; }
  /// The number of pixels of block i (s^2 but at the frame's right and bottom edges).
  std::uint32_t area(std::size_t i) const;
  /// The plane sums of the measured points of block i.
  PlaneSums sums(std::size_t i) const;
  /// Adds the plane sums of block i to `sums`.
  void addTo(std::size_t i, PlaneSums& sums) const;
  /// Adds block i's mean to `sums` as if each of its measured pixels were there: the sums of the
  /// grid that is segmented, whose points scatter by the means' noise, counted in pixels.
  void addMeanTo(std::size_t i, PlaneSums& sums) const;
  /// The mean squared distance of the measured points of block i from the plane
  /// normal . P + offset = 0 (unit normal): the scatter about the block's mean along the
  /// normal plus the mean's own distance, squared.
  double meanSquaredDistance(std::size_t i, const Vec3& normal, float offset) const;
  /// The scatter of block i about its mean, sum (P - mean)(P - mean)^T, as xx yy zz xy yz zx.
  const float* scatter(std::size_t i) const { return &moments_[8 * i]; }

  /// The first full-resolution column and row of block (bx, by).
  int firstColumn(int bx) const { return bx * factor_; }
  int firstRow(int by) const { return by * factor_; }
  /// The frame that was read.
  int frameWidth() const { return frame_width_; }
  int frameHeight() const { return frame_height_; }

 private:
  // The sums, means and scatters of the blocks of block row `by`.
  void readRow(const PointGrid& full, int by);

  int factor_ = 1;
  int frame_width_ = 0;
  int frame_height_ = 0;
  PointGrid means_;
  std::vector<float> mean_points_;     // x y z 0 per block
  std::vector<float> moments_;         // per block: xx yy zz (unused) xy yz zx (unused)
  std::vector<std::uint16_t> counts_;  // measured pixels per block
  std::vector<float> depth_spread_;    // per block: its largest minus its smallest depth (z)
  std::vector<std::uint8_t> split_;    // per block: separateSurfaces() left pixels out
  std::vector<int> stack_;             // separateSurfaces' scratch
  std::vector<std::uint8_t> kept_;     // separateSurfaces' scratch: per pixel of a block
};

}  // namespace floodplane
