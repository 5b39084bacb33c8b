// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <vector>

#include "flood/plane_merger.h"
#include "floodplane/point_grid.h"
#include "models/plane_candidates.h"
#include "util/union_find.h"

namespace floodplane {

/// Beyond the paper: pieces of one plane cut apart by something in front of it (a wall behind
/// a column or a chair) are one plane, as users and ground truth see it; two coplanar tables
/// with the floor visible between them are two. The flood cannot tell: neither pair touches.
///
/// Two planes that would merge by Eq. 9 (MergeCriterion: normals, centroid distances, a
/// common fit) merge across the pixels between them, along the image rows and columns they
/// share, only when every such pixel lies in front of their plane (an occluder) or on it, or
/// has no return; a pixel behind the plane (the floor seen between two tables, the room seen
/// through a window) means there is no surface there, and keeps them apart. Pairs without a
/// shared row or column have no pixels between them to judge and stay apart.
class OcclusionMerging {
 public:
  /// Merges such candidates of `planes` (on the grid `full`); returns whether any merged. Only
  /// when it did does `planes.remap()` map every old number to its new one (with fewer than
  /// two planes it is left as the previous stage set it).
  bool run(const PointGrid& full, PlaneCandidates& planes, const MergeCriterion& criterion,
           const Tolerances& tolerances, float angular_pitch);

 private:
  struct Box {
    int x_min, y_min, x_max, y_max;
  };
  // The pixel boxes of the planes (box k - 1 of plane k).
  void findBoxes(int width, int height, const CurrentLabels& labels, std::size_t planes);
  // Whether the pixels between a and b along their shared rows and columns allow a merge.
  bool occludedBetween(const PointGrid& full, const CurrentLabels& labels, std::uint32_t a, std::uint32_t b,
                       const FloodCriterion& plane) const;

  std::vector<Box> boxes_;
  std::vector<PlaneFit> fits_;
  UnionFind sets_;
};

}  // namespace floodplane
