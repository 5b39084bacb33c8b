// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What one segmentation measured about itself: the time of each phase and its counts. Plain
// types, for the result (floodplane/segmentation.h) and for the stages that count.

#include <cstddef>

/// \file
/// floodplane::PhaseTimes and floodplane::SegmentationStats: what a segmentation measured.

namespace floodplane {

/// Time spent in each phase of one segmentation (the paper's Fig. 5), in milliseconds.
/// Filled only when Segmenter::Options::measure_phases is set.
struct PhaseTimes {
  double preparation = 0.0;     ///< noise estimation, hole filling, smoothing, sub-sampling
  double seed_selection = 0.0;  ///< scanning for seeds and testing them (Sec. III-C)
  double flood_fill = 0.0;      ///< growing segments (Sec. III-A, III-B); at s > 1 also the coarse planes claimed
                                ///< into the fine pass
  double relabelling = 0.0;     ///< connected components after Eq. 4 reassignments
  double merging = 0.0;         ///< agglomerative plane merging (Sec. III-D)
  double region_output = 0.0;   ///< labels at full resolution, refinement, plane fits
  /// The PCL class's work around the core: input checks, the shift to the sensor origin and
  /// PCL's outputs (regions, coefficients, indices, the label cloud). 0 from Segmenter.
  double pcl_conversion = 0.0;
  /// \return the sum of the phases [ms]
  double total() const {
    return preparation + seed_selection + flood_fill + relabelling + merging + region_output + pcl_conversion;
  }
};

/// What happened inside one segmentation, for tests, benchmarks and curious users.
struct SegmentationStats {
  std::size_t seed_candidates = 0;    ///< unclaimed pixels tested as seeds
  std::size_t seeds = 0;              ///< candidates that passed Eqs. 5-7 (one flood each)
  std::size_t pixels_taken_over = 0;  ///< pixels reassigned by Eq. 4
  std::size_t segments = 0;           ///< segments after relabelling
  std::size_t merges = 0;             ///< merges by Eq. 9
  /// The noise model was the previous frame's (Segmenter::Options::head_start), not measured.
  bool head_start = false;
};

}  // namespace floodplane
