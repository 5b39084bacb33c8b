// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Object segmentation quality against object labels, as ../shared/tools/osd_scores.py
// --objects defines it on the mOSD frames: each ground-truth object's IoU with the output
// object that overlaps it most, the share found (IoU >= 0.8), cut (over) and merged (under),
// and the share of the support (the table) inside output objects. Plain arrays, no PCL, no I/O.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace floodplane::eval {

/// How the ground truth is labelled and what the scores count. The defaults are mOSD's coding
/// (0 nothing, 1-9 the table's disjoint parts, 20-29 the first object's parts, 30-39 the
/// second, ...) and osd_scores.py's thresholds.
struct ObjectMetricsOptions {
  /// Ground-truth labels from this one on are objects: each label an object of its own (mOSD
  /// labels each disjoint part of an object apart, and the script scores them apart).
  std::uint32_t first_object_label = 20;
  /// Ground-truth labels in [first_support_label, last_support_label] are the support.
  std::uint32_t first_support_label = 1;
  std::uint32_t last_support_label = 9;
  /// Ground-truth objects with fewer pixels are left out.
  std::size_t min_object_pixels = 200;
  /// An object is found when its IoU is at least this.
  double found_iou = 0.8;
  /// An output object "holds" a part of an object when it has at least this share of the
  /// object's pixels: two such output objects cut it (over), one that also holds this share of
  /// another object merges them (under).
  double hold_share = 0.2;
};

/// One kept ground-truth object.
struct ObjectScore {
  std::uint32_t label = 0;  ///< its ground-truth label
  std::size_t pixels = 0;   ///< its pixels
  std::uint32_t best = 0;   ///< the output object holding most of it (ties: the lower label); 0: none
  double iou = 0.0;         ///< IoU with `best`, 0 without one
  bool found = false;       ///< iou >= found_iou
  bool over = false;        ///< at least two output objects each hold hold_share of it
  bool under = false;       ///< `best` also holds hold_share of another kept object
};

struct ObjectScores {
  std::vector<ObjectScore> objects;  ///< the kept ground-truth objects, by ascending label
  std::size_t output_objects = 0;    ///< distinct output labels other than 0
  /// Mean of ObjectScore::iou; 0 when no object is kept (as the script gives it).
  double object_iou = 0.0;
  /// Shares of the kept objects found, over- and under-segmented (each over max(1, objects)).
  double objects_found = 0.0;
  double over = 0.0;
  double under = 0.0;
  /// The share of the support's pixels inside output objects (over max(1, support pixels)).
  double support_in_objects = 0.0;
};

/// Scores the object labels `predicted` (0 = no object, any other value an object) against
/// `ground_truth`, both row-major grids of one size. Every pixel counts (the script's rule:
/// mOSD labels a pixel without a point 0). Throws std::invalid_argument if the sizes differ,
/// the support's range is empty or reaches the objects' labels, or a share is not in (0, 1].
ObjectScores evaluateObjects(const std::vector<std::uint32_t>& ground_truth,
                             const std::vector<std::uint32_t>& predicted,
                             const ObjectMetricsOptions& options = ObjectMetricsOptions());

}  // namespace floodplane::eval
