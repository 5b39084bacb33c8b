// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Segmentation quality against ground truth, exactly as the project's metrics definition
// (metrics.md) gives it: per-plane IoU, mean and weighted IoU (the paper's Table I), the Hoover
// et al. 1996 classification (SegComp), and the fraction of non-plane surface reported as
// plane. Plain arrays, no PCL, no I/O.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace floodplane::eval {

/// Settings of the comparison.
struct MetricsOptions {
  /// Ground-truth planes and predicted segments with fewer valid pixels than this are
  /// ignored. 500 at 640x480; use defaultMinPoints() at other resolutions.
  std::uint32_t min_points = 500;
  /// Hoover's tolerance T, in (0.5, 1]. Above 0.5 a region can be the larger part of at
  /// most one other region, which makes every classification below unambiguous.
  double tolerance = 0.8;
};

/// round(500 * width * height / (640 * 480)): the minimum size scaled with the pixel count.
std::uint32_t defaultMinPoints(std::size_t width, std::size_t height);

/// How a kept ground-truth plane was classified by Hoover's metric.
enum class HooverClass { correct, over_segmented, under_segmented, missed };

/// Why a kept ground-truth plane g is not a correct detection, from where its pixels went; the
/// first of these that applies:
/// 1. over_segmented or under_segmented: Hoover's class of g.
/// 2. no_segment: at least half of g's pixels carry no predicted label (0).
/// 3. over_segmented: no kept segment holds half of g: its labelled pixels are split among
///    several segments (kept ones, or ones below the size rule).
/// 4. under_segmented: the segment p holding most of g has more than (1 - T)|p| pixels on other
///    ground-truth planes: merged with other regions.
/// 5. iou_below_t: one segment holds at least half of g but covers less than T of it, or spills
///    beyond it (mostly onto no plane): found, at an IoU below T.
/// `none` for a correct detection.
enum class MissReason { none, no_segment, under_segmented, over_segmented, iou_below_t };

/// One kept ground-truth plane.
struct PlaneScore {
  std::uint32_t label = 0;         ///< its ground-truth label
  std::size_t pixels = 0;          ///< |g|, valid pixels only
  double iou = 0.0;                ///< max over kept predicted segments of |g n p| / |g u p|
  std::uint32_t best_segment = 0;  ///< the predicted label reaching `iou`; 0 if none overlaps
  HooverClass hoover = HooverClass::missed;
  MissReason miss = MissReason::none;  ///< why it is not a correct detection
  double unlabelled_share = 0.0;       ///< the share of its pixels with predicted label 0
  /// The kept segment that holds most of its pixels (ties: the lower label), 0 if none does,
  /// and the share of its pixels that segment holds.
  std::uint32_t main_segment = 0;
  double main_segment_share = 0.0;
};

/// A kept predicted segment in no Hoover instance (noise).
struct NoiseSegment {
  std::uint32_t label = 0;       ///< its predicted label
  std::size_t pixels = 0;        ///< |p|, valid pixels only
  double iou = 0.0;              ///< max over kept ground-truth planes of |g n p| / |g u p|
  double off_plane_share = 0.0;  ///< the share of its pixels whose ground-truth label is 0 (on no plane)
};

/// Hoover et al.'s counts. `over` counts over-segmented ground-truth planes and `under`
/// under-segmenting predicted segments (one per instance, as in SegComp), `missed` the
/// ground-truth planes and `noise` the predicted segments that are in no instance.
struct HooverCounts {
  std::size_t correct = 0;
  std::size_t over = 0;
  std::size_t under = 0;
  std::size_t missed = 0;
  std::size_t noise = 0;
};

struct SegmentationScores {
  std::vector<PlaneScore> planes;      ///< kept ground-truth planes, by ascending label
  std::vector<NoiseSegment> noise;     ///< the noise segments, by ascending label
  std::size_t predicted_segments = 0;  ///< kept predicted segments
  /// Averages of PlaneScore::iou, plain and weighted by |g|. NaN when no plane is kept:
  /// there is nothing to average, and 0 would read as "found nothing".
  double mean_iou = 0.0;
  double weighted_iou = 0.0;
  HooverCounts hoover;
  /// See falsePlaneFraction; NaN when the ground truth has no valid pixel of label 0.
  double false_plane_fraction = 0.0;
};

/// The share of the valid pixels with ground-truth label 0 (a surface that is not a plane:
/// a ball, a pipe, a person) that lie in a kept predicted segment (label != 0 and at least
/// `min_points` valid pixels: smaller segments are ignored, as everywhere in these metrics).
/// NaN when there is no valid pixel of ground-truth label 0: undefined, not 0, so that such
/// clouds are left out of averages. IoU and the Hoover counts do not see these errors.
/// Throws std::invalid_argument if the three vectors differ in size.
double falsePlaneFraction(const std::vector<std::uint32_t>& ground_truth, const std::vector<std::uint32_t>& predicted,
                          const std::vector<std::uint8_t>& valid, std::uint32_t min_points);

/// Compares `predicted` with `ground_truth`, both row-major label grids of one size, label 0
/// meaning "not on a plane". `valid[i] != 0` marks the pixels that count; pass a pixel as
/// invalid when its ground-truth point is NaN. All sizes (|g|, |p|, overlaps) count valid
/// pixels only.
///
/// Hoover classification order: correct detections first, then over-segmentations (ground-
/// truth planes by ascending label), then under-segmentations (predicted segments by
/// ascending label), each among regions not yet classified; what is left is missed / noise.
/// Every plane that is not a correct detection gets its MissReason.
///
/// Throws std::invalid_argument if the three vectors differ in size or the tolerance is not
/// in (0.5, 1].
SegmentationScores evaluateSegmentation(const std::vector<std::uint32_t>& ground_truth,
                                        const std::vector<std::uint32_t>& predicted,
                                        const std::vector<std::uint8_t>& valid,
                                        const MetricsOptions& options = MetricsOptions());

}  // namespace floodplane::eval
