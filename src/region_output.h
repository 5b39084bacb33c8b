#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "tolerances.h"
#include "distance_function.h"
#include "floodplane/params.h"
#include "floodplane/point_grid.h"
#include "floodplane/segmenter.h"
#include "hole_filling.h"
#include "plane_sums.h"

namespace floodplane {

/// The segments after merging, on the grid that was segmented.
struct MergedSegments {
  const std::int32_t* labels = nullptr;  ///< per pixel of the segmented grid: segment, 0 none
  const std::int32_t* root = nullptr;    ///< per segment: the segment it merged into
  const PlaneSums* sums = nullptr;       ///< per root segment: the sums of its whole cluster
  std::size_t segment_count = 0;         ///< labels are < segment_count
};

/// "No pixel yet" for PlaneCandidate::first_pixel.
constexpr std::size_t kNoPixel = std::numeric_limits<std::size_t>::max();

/// A plane on its way to the output: its full-resolution inliers and its membership test.
struct PlaneCandidate {
  PlaneSums sums;            ///< of its full-resolution inliers
  FloodCriterion criterion;  ///< its plane and thresholds, for labelling and refinement
  std::size_t first_pixel = kNoPixel;
};

/// The candidate planes and their numbers in the label image (1..K, 0: no plane). Planes are
/// numbered by size, largest first; renumbering maps old numbers to new through remap().
class PlaneCandidates {
 public:
  std::vector<PlaneCandidate>& list() { return candidates_; }
  const std::vector<PlaneCandidate>& list() const { return candidates_; }
  PlaneCandidate& operator[](std::uint32_t label) { return candidates_[label - 1]; }

  /// Drops candidates under `min_inliers` and, when `recheck` is given, those whose inliers
  /// no longer make an acceptable plane under its parameters; orders the rest by size.
  /// Returns whether any number changed (the label image then needs renumberPixels).
  bool sortBySize(std::uint32_t min_inliers, const Params* recheck);
  /// The new number of old number k, after sortBySize (0: dropped).
  std::uint32_t remap(std::uint32_t k) const { return remap_[k]; }
  /// Forgets every plane's first pixel, before a full renumbering.
  void forgetFirstPixels();
  /// Applies remap() to labels [begin, end) and notes first pixels (those before `begin`
  /// already noted).
  void renumberPixels(std::uint32_t* labels, std::size_t begin, std::size_t end);

 private:
  std::vector<PlaneCandidate> candidates_;
  std::vector<PlaneCandidate> kept_;
  std::vector<std::uint32_t> remap_;
  std::vector<std::size_t> order_;
};

/// What a reported plane must be: a valid fit, no more curved than allowed, facing the sensor.
bool acceptablePlane(const PlaneFit& fit, const Params& params);

/// The last stage: from merged segments to the planes a user gets.
/// - Each cluster becomes a plane if it is flat enough (maximum curvature) and large enough
///   (min inliers, counted at full resolution); planes are numbered by size, largest first.
/// - With sub-sampling s > 1, every full-resolution pixel takes the best-fitting plane among
///   those of the four grid samples around it, if it is within the plane tolerance, so labels
///   are pixel-accurate although only every s-th pixel was segmented.
/// - Optionally the refinement (refinement.h) grows the planes into unlabelled pixels.
/// - Centroid, covariance and coefficients come from running sums of the inliers, updated as
///   pixels are added; there is no second pass over the cloud.
class RegionBuilder {
 public:
  /// `full` is the input grid, `segmented` the grid that was segmented (the same when s = 1),
  /// `angular_pitch` that of `full`.
  /// `segmented` is the grid that was segmented: `full`, or a copy with filled-in holes
  /// (`holes`), sub-sampled when s > 1.
  void build(const PointGrid& full, const PointGrid& segmented, const HoleFilling& holes, int subsampling,
             const MergedSegments& merged, const Params& params, const Tolerances& tolerances, float angular_pitch,
             bool refine, Segmentation& out);

 private:
  // One candidate per flat cluster; candidate_of_segment_ maps every segment to its cluster's.
  void selectCandidates(int subsampling, const MergedSegments& merged, const Params& params,
                        const Tolerances& tolerances, float angular_pitch);
  void labelFullResolution(const PointGrid& full, const PointGrid& segmented, int subsampling,
                           const MergedSegments& merged, std::vector<std::uint32_t>& labels);
  // The cells of sample row gy (see Cell) and each pixel column's sample range.
  void prepareCellRow(const PointGrid& segmented, int subsampling, int gy, const MergedSegments& merged);
  // Labels one full-resolution row from the cells of its sample row.
  void labelRowFromCells(const PointGrid& full, std::size_t row_start, int subsampling, std::uint32_t* out_row) const;
  // Labels pixels [u_begin, u_end) of a full-resolution row whose cells all have plane k
  // alone: k where the pixel fits k, else 0.
  void labelRun(const PointGrid& full, std::size_t row_start, int u_begin, int u_end, std::uint32_t k,
                std::uint32_t* out_row) const;
  // Labels pixels [u_begin, u_end) of a cell whose samples have several planes: the
  // best-fitting one within the tolerance, else 0.
  void labelMixedCell(const PointGrid& full, std::size_t row_start, int u_begin, int u_end, std::size_t gx,
                      std::uint32_t* out_row) const;
  // Adds the labelled pixels of one full-resolution row to their planes' sums and notes
  // each plane's first pixel.
  void addRowToSums(const PointGrid& full, std::size_t row_start, const std::uint32_t* row);

  // A cell of the segmented grid, between samples (gx, gy) and (gx + 1, gy + 1): the planes
  // of its four samples, and whether they are none (0), one (that plane) or several.
  static constexpr std::uint32_t kMixedCell = 0xffffffffu;
  struct Cell {
    std::array<std::uint32_t, 4> around;
    std::uint32_t plane;
    float sample_range_sq;  // of sample (gx, gy)
  };
  std::vector<Cell> cells_;             // one row of cells
  std::vector<float> column_range_sq_;  // per pixel column: its cell's sample_range_sq
  PlaneCandidates candidates_;
  std::vector<std::uint32_t> candidate_of_segment_;  // 0 = none, k = candidates_[k]
  std::vector<std::size_t> queue_;                   // the refinement's
  const HoleFilling* holes_ = nullptr;
};

}  // namespace floodplane
