#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "distance_function.h"
#include "floodplane/params.h"
#include "floodplane/plane_sums.h"
#include "floodplane/point_grid.h"
#include "floodplane/segmenter.h"

namespace floodplane {

/// The segments after merging, on the grid that was segmented.
struct MergedSegments {
  const std::int32_t* labels = nullptr;  ///< per pixel of the segmented grid: segment, 0 none
  const std::int32_t* root = nullptr;    ///< per segment: the segment it merged into
  const PlaneSums* sums = nullptr;       ///< per root segment: the sums of its whole cluster
  std::size_t segment_count = 0;         ///< labels are < segment_count
};

/// The last stage: from merged segments to the planes a user gets.
/// - Each cluster becomes a plane if it is flat enough (maximum curvature) and large enough
///   (min inliers, counted at full resolution); planes are numbered by size, largest first.
/// - With sub-sampling s > 1, every full-resolution pixel takes the best-fitting plane among
///   those of the four grid samples around it, if it is within the plane tolerance, so labels
///   are pixel-accurate although only every s-th pixel was segmented.
/// - Refinement grows each plane into adjacent unlabelled pixels that fit it (Eqs. 1-3 with
///   the plane's own thresholds): pixels a flood could not reach through noise, and pixels of
///   segments too small to report.
/// - Centroid, covariance and coefficients come from running sums of the inliers, updated as
///   pixels are added; there is no second pass over the cloud.
class RegionBuilder {
 public:
  /// `full` is the input grid, `segmented` the grid that was segmented (the same when s = 1),
  /// `angular_pitch` that of `full`.
  void build(const PointGrid& full, const PointGrid& segmented, int subsampling, const MergedSegments& merged,
             const Params& params, float angular_pitch, bool refine, Segmentation& out);

 private:
  struct Candidate {
    PlaneSums sums;          // full resolution inliers
    FloodCriterion criterion;  // its plane and thresholds for the refinement
    std::size_t first_pixel = 0;
  };
  void labelFullResolution(const PointGrid& full, const PointGrid& segmented, int subsampling,
                           const MergedSegments& merged, std::vector<std::uint32_t>& labels);
  // Labels pixels [u_begin, u_end) of a full-resolution row whose cells all have plane k
  // alone: k where the pixel fits k, else 0.
  void labelRun(const PointGrid& full, std::size_t row_start, int u_begin, int u_end, std::uint32_t k,
                std::uint32_t* out_row) const;
  // Adds the labelled pixels of one full-resolution row to their planes' sums and notes
  // each plane's first pixel.
  void addRowToSums(const PointGrid& full, std::size_t row_start, const std::uint32_t* row);
  // Drops candidates under min_inliers and, when `recheck` is given, those whose inliers no
  // longer make an acceptable plane under its parameters (invalid fit, curvature over the
  // maximum, facing away); orders the rest by size. remap_ maps old numbers to new. Returns
  // whether any number changed.
  bool sortBySize(std::uint32_t min_inliers, const Params* recheck);
  // Applies remap_ to a label image and finds each plane's first pixel again.
  void renumber(std::vector<std::uint32_t>& labels);
  // renumber() for pixels [begin, end), with the first pixels already reset and found
  // before `begin`.
  void renumberPixels(std::vector<std::uint32_t>& labels, std::size_t begin, std::size_t end);
  // Grows the planes into unlabelled pixels; with `renumber_first`, applies renumber() to
  // the labels first (in the same pass).
  void refine(const PointGrid& full, std::vector<std::uint32_t>& labels, bool renumber_first);

  // A cell of the segmented grid, between samples (gx, gy) and (gx + 1, gy + 1): the planes
  // of its four samples, and whether they are none (0), one (that plane) or several.
  static constexpr std::uint32_t kMixedCell = 0xffffffffu;
  struct Cell {
    std::array<std::uint32_t, 4> around;
    std::uint32_t plane;
    float sample_range_sq;  // of sample (gx, gy)
  };
  std::vector<Cell> cells_;  // one row of cells
  std::vector<float> column_range_sq_;  // per pixel column: its cell's sample_range_sq
  std::vector<Candidate> candidates_;
  std::vector<Candidate> kept_;
  std::vector<std::uint32_t> candidate_of_segment_;  // 0 = none, k = candidates_[k - 1]
  std::vector<std::uint32_t> remap_;
  std::vector<std::size_t> order_;
  std::vector<std::size_t> queue_;
};

}  // namespace floodplane
